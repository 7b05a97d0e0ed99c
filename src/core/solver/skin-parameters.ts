/** The skin's parameters (SkinParameters), their defaults and their ranges. */
import { checkNumber, type Range } from '../check';

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
   * The solver sleeps once no vertex moves more than this in a frame, relative to the mesh size (skin with a triangle
   * turned over: once as still as STILL_MOVE). The default stops within a twentieth of a millimetre of where a
   * fifth of it would, in about three quarters of the frames (docs/solver-notes.md, "Sleep tolerance").
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
  /**
   * Share of its rest length an edge may lose before it resists: the tension skin carries in the body, which a
   * compression first releases before the skin goes slack and folds. Young skin carries more (it retracts more when
   * cut free) and folds less; 0 folds at the first compression. Stretching is resisted from the rest length as ever.
   */
  pretension: number;
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
  sleepTolerance: 1e-5,
  momentum: 0.5,
  startMomentum: 0.7,
  foldMomentum: 0.85,
  pretension: 0,
};

/**
 * The accepted values of each parameter, ends included: validateParameters, the staging of a change on the main
 * thread (input-staging.ts) and the Rendering panel's sliders read this one table.
 */
export const SKIN_RANGES: Readonly<Record<keyof SkinParameters, Range>> = Object.freeze({
  positionIterations: [1, 64],
  lengthIterations: [0, 64],
  positionStiffness: [0, 1],
  lengthStiffness: [0, 1],
  muscleStiffness: [0, 1],
  wrinkleSpacing: [0, 1],
  inwardResistance: [1, 100],
  bulge: [0, 10],
  sleepTolerance: [0, 1],
  momentum: [0, 0.9],
  startMomentum: [0, 0.9],
  foldMomentum: [0, 0.9],
  pretension: [0, 0.5],
});

/** The parameters that count passes, and so must be whole. */
export const SKIN_INTEGERS: readonly (keyof SkinParameters)[] = Object.freeze(['positionIterations', 'lengthIterations']);

/** What messages about skin parameters start with: `skin parameters: lengthIterations: expected ...`. */
export const SKIN_PARAMETERS = 'skin parameters';

/** Throws the refusal of the first parameter that is not a finite number in its range (and whole, if it counts). */
export function validateParameters(p: SkinParameters): void {
  for (const key of Object.keys(SKIN_RANGES) as (keyof SkinParameters)[])
    checkNumber(SKIN_PARAMETERS, key, p[key], SKIN_RANGES[key], SKIN_INTEGERS.includes(key));
}
