/** The skin's parameters (SkinParameters), their defaults and their ranges. */

/** The skin's parameters; every one can change while the solver runs. */
export interface SkinParameters {
  /** Outer iterations per frame; each projects position, muscle, length (x lengthIterations), bending, collisions. */
  positionIterations: number;
  /** Passes over all length constraints per outer iteration (the thesis found 3 the least that looks soft). */
  lengthIterations: number;
  /** Fraction of the way back to rest per projection: the skin's elasticity (the tissue under it). */
  positionStiffness: number;
  /** Fraction of an edge's length error removed per projection: how little the skin compresses. */
  lengthStiffness: number;
  /** Fraction of the way to a muscle target per projection, times the vertex's muscle weight. */
  muscleStiffness: number;
  /**
   * Wrinkle spacing in metres: the wavelength at which compressed skin folds. It sets the bending stiffness against
   * the position stiffness (a plate on an elastic foundation buckles at 2 pi (B / k)^(1/4)). 0 turns bending off.
   */
  wrinkleSpacing: number;
  /** How much harder the tissue resists skin sinking in along the rest normal than lifting out (1 = symmetric). */
  inwardResistance: number;
  /**
   * Outward push per unit of edge compression, along the rest normal, scaled by the muscle weight at the edge: it
   * starts compressed skin buckling (a flat patch has no other reason to leave its plane) and, being fixed per
   * vertex, pins the fold pattern so the solver settles instead of letting folds drift. Where no muscle holds the skin
   * it is zero, so released skin returns exactly to rest.
   */
  bulge: number;
  /**
   * The solver sleeps once no vertex moves more than this in a frame, relative to the mesh size. The default stops
   * close to where half of it would, and sooner (docs/solver-notes.md, "Sleep tolerance").
   */
  sleepTolerance: number;
  /**
   * Share of its last frame's move each vertex starts the next frame with (heavy-ball acceleration). The frame's
   * fixed points are unchanged (a settled vertex has no move to carry), and the slow fading modes of a soft skin on
   * stiff edges settle in about two thirds of the frames (see the benchmark).
   */
  momentum: number;
  /**
   * The share along the surface in a motion's first START_MOMENTUM_FRAMES frames, when the skin travels farthest: the
   * expressions come to their shapes and sleep sooner, with the same folds (docs/solver-notes.md, "Start momentum").
   */
  startMomentum: number;
  /**
   * The same share for the part of the move along the vertex's rest normal: how folds rise and settle. A fold near
   * its buckling point moves slowly, and a larger share there settles it sooner; but too large a share while the
   * pattern forms picks longer folds than `wrinkleSpacing` asks for, so a motion's first frames take at most
   * FOLD_CHOICE_MOMENTUM (docs/solver-notes.md, "Fold momentum").
   */
  foldMomentum: number;
}

export const SKIN_DEFAULTS: Readonly<SkinParameters> = {
  positionIterations: 4,
  lengthIterations: 3,
  positionStiffness: 0.05,
  lengthStiffness: 0.9,
  muscleStiffness: 0.5,
  wrinkleSpacing: 0.012,
  inwardResistance: 3,
  bulge: 0.2,
  sleepTolerance: 2e-6,
  momentum: 0.5,
  startMomentum: 0.7,
  foldMomentum: 0.85,
};

const RANGES: Record<keyof SkinParameters, [number, number, boolean]> = {
  positionIterations: [1, 64, true],
  lengthIterations: [0, 64, true],
  positionStiffness: [0, 1, false],
  lengthStiffness: [0, 1, false],
  muscleStiffness: [0, 1, false],
  wrinkleSpacing: [0, 1, false],
  inwardResistance: [1, 100, false],
  bulge: [0, 10, false],
  sleepTolerance: [0, 1, false],
  momentum: [0, 0.9, false],
  startMomentum: [0, 0.9, false],
  foldMomentum: [0, 0.9, false],
};

/** Throws an error naming the first parameter that is not a finite number within its range. */
export function validateParameters(p: SkinParameters): void {
  for (const [name, [lo, hi, integer]] of Object.entries(RANGES) as [keyof SkinParameters, [number, number, boolean]][]) {
    const v = p[name];
    if (typeof v !== 'number' || !Number.isFinite(v)) throw new Error(`skin parameter ${name} must be a finite number, got ${v}`);
    if (v < lo || v > hi) throw new Error(`skin parameter ${name} must be between ${lo} and ${hi}, got ${v}`);
    if (integer && !Number.isInteger(v)) throw new Error(`skin parameter ${name} must be a whole number, got ${v}`);
  }
}
