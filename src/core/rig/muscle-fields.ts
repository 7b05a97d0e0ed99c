/**
 * The displacement field of a packed muscle of any type at a point (thesis 3.2 and 4.4), as a brush changes it, and
 * whether a rest point may lie in its zone: the per-vertex code MuscleRig runs, and MuscleField for one muscle.
 *
 * The thesis's printed formulas carry typos (a garbled radial falloff, an ellipsoid test without squares); each field
 * (here, waters-muscles.ts, rotation-muscles.ts) says which of its ideas it implements and uses the smooth form that
 * was meant.
 */
import { rotationOffset } from '../math3';
import {
  ANCHOR,
  BOUND_SQUARED,
  CURVE,
  FRAME,
  HALF_PI,
  HALF_SIZE,
  LIP_DROP,
  INVERSE_RADII,
  JAW,
  JOINT,
  LID,
  LINEAR,
  LINEAR_ANGLE,
  LINEAR_AXIS,
  LINEAR_FALLOFF_END,
  MAX_ANGLE,
  packMuscle,
  SCALE,
  SPHINCTER,
  STRENGTH,
  STRIDE,
  TYPE,
} from './muscle-packing';
import { validateMuscle } from './muscle-validation';
import type { BrushSphere, Muscle, Vec3 } from './rig-types';
import { turnAt, turnPoint } from './rotation-muscles';
import { displaceLinear, displaceSphincter } from './waters-muscles';

/** Where displace puts a rotation muscle's turn (sine and versine) unless told otherwise. */
const TURN = new Float64Array(2);

/**
 * Displacement of the point (x, y, z) by packed muscle `o` at contraction `c`, into `out[0..3]`; returns the
 * muscle's falloff (0..1; 0 outside its zone, where the displacement is zero too). Linear and sphincter fields are
 * asked where the skin is now (so skin sliding out of a zone is pulled less); a rotation muscle's zone is asked at the
 * skin's rest point (rx, ry, rz), because the lid or jaw carries its skin with it: skin it has turned is still its
 * skin, and a lid closing would otherwise leave its own zone halfway. Allocates nothing.
 */
function displace(
  P: Float64Array,
  o: number,
  c: number,
  x: number,
  y: number,
  z: number,
  out: Float64Array | number[],
  rx = x,
  ry = y,
  rz = z,
  turn: Float64Array = TURN,
  at = 0,
): number {
  out[0] = 0;
  out[1] = 0;
  out[2] = 0;
  const type = P[o + TYPE];
  const rotates = type === LID || type === JAW;
  const px = rotates ? rx : x;
  const py = rotates ? ry : y;
  const pz = rotates ? rz : z;
  const dx = px - P[o + ANCHOR];
  const dy = py - P[o + ANCHOR + 1];
  const dz = pz - P[o + ANCHOR + 2];
  if (dx * dx + dy * dy + dz * dz >= P[o + BOUND_SQUARED]) return 0;
  if (type === LINEAR) return displaceLinear(P, o, c, dx, dy, dz, out);
  // Local coordinates: the transposed frame times the offset from the centre.
  const F = o + FRAME;
  const qx = P[F] * dx + P[F + 3] * dy + P[F + 6] * dz;
  const qy = P[F + 1] * dx + P[F + 4] * dy + P[F + 7] * dz;
  const qz = P[F + 2] * dx + P[F + 5] * dy + P[F + 8] * dz;
  if (type === SPHINCTER) return displaceSphincter(P, o, c, qx, qy, qz, out);
  const falloff = turnAt(P, o, c, qx, qy, qz, turn, at);
  // Thesis 3.2.2 and 4.4.3: rotation muscles turn their skin about a joint, about the local x axis (the frame's first
  // column); the turn moves skin farther from the joint farther, as the thesis wants.
  if (falloff !== 0) turnPoint(P, o, x, y, z, turn, at, out);
  return falloff;
}

/**
 * Rotation muscles turn the skin by an amount that depends on its rest point only (see displace), the same at every
 * substep of a compute: so each vertex's turn by each rotation muscle is found once (`vertex[m]` is the vertex it was
 * found for; -1 for none), and its falloff and turn kept.
 */
export interface TurnCache {
  vertex: Int32Array;
  falloff: Float64Array;
  /** Sine and versine per muscle. */
  turn: Float64Array;
}

/** displace, with the turn of a rotation muscle `m` (at `o`) for vertex `v` taken from `cache` once displace found it. */
export function displaceVertex(
  P: Float64Array,
  o: number,
  m: number,
  v: number,
  c: number,
  x: number,
  y: number,
  z: number,
  out: Float64Array,
  rx: number,
  ry: number,
  rz: number,
  cache: TurnCache,
): number {
  const type = P[o + TYPE];
  if (type !== LID && type !== JAW) return displace(P, o, c, x, y, z, out, rx, ry, rz);
  if (cache.vertex[m] !== v) {
    // First asked for this vertex: displace finds the turn, and keeps it in the cache.
    cache.vertex[m] = v;
    cache.falloff[m] = displace(P, o, c, x, y, z, out, rx, ry, rz, cache.turn, 2 * m);
    return cache.falloff[m];
  }
  const falloff = cache.falloff[m];
  if (falloff === 0) {
    out[0] = 0;
    out[1] = 0;
    out[2] = 0;
    return 0;
  }
  turnPoint(P, o, x, y, z, cache.turn, 2 * m, out);
  return falloff;
}

/**
 * The displacement packed muscle `o` gives (x, y, z) as if its falloff there were 1, at contraction `c`: every field
 * is its falloff times this (the turn's angle, for the rotation muscles), so `c` times a falloff gives the field at
 * that falloff. Used where a brush sets the falloff, also outside the muscle's zone. Allocates nothing.
 */
export function displaceAtFalloff(
  P: Float64Array,
  o: number,
  c: number,
  x: number,
  y: number,
  z: number,
  out: Float64Array | number[],
  rx: number,
  ry: number,
  rz: number,
): void {
  const type = P[o + TYPE];
  const F = o + FRAME;
  if (type === LINEAR) {
    const k = -c * P[o + STRENGTH];
    out[0] = k * (x - P[o + ANCHOR]);
    out[1] = k * (y - P[o + ANCHOR + 1]);
    out[2] = k * (z - P[o + ANCHOR + 2]);
    return;
  }
  const rotates = type === LID || type === JAW;
  const dx = (rotates ? rx : x) - P[o + ANCHOR];
  const dy = (rotates ? ry : y) - P[o + ANCHOR + 1];
  const dz = (rotates ? rz : z) - P[o + ANCHOR + 2];
  const qx = P[F] * dx + P[F + 3] * dy + P[F + 6] * dz;
  const qy = P[F + 1] * dx + P[F + 4] * dy + P[F + 7] * dz;
  const qz = P[F + 2] * dx + P[F + 5] * dy + P[F + 8] * dz;
  if (type === SPHINCTER) {
    const k = -c * P[o + STRENGTH];
    const wx = k * P[o + SCALE] * qx;
    const wy = k * P[o + SCALE + 1] * qy;
    const wz = k * P[o + SCALE + 2] * qz;
    out[0] = P[F] * wx + P[F + 1] * wy + P[F + 2] * wz;
    out[1] = P[F + 3] * wx + P[F + 4] * wy + P[F + 5] * wz;
    out[2] = P[F + 6] * wx + P[F + 7] * wy + P[F + 8] * wz;
    return;
  }
  let angle = c * P[o + MAX_ANGLE];
  if (type === JAW) {
    const across = Math.max(-1, Math.min(1, qx / P[o + HALF_SIZE]));
    angle *= 1 + P[o + CURVE] * (1 - across * across);
  }
  rotationOffset(x, y, z, P[o + JOINT], P[o + JOINT + 1], P[o + JOINT + 2], P[F], P[F + 3], P[F + 6], angle, out);
}

/**
 * A brush sphere's weight at a rest point: 1 in its inner half, fading (cosine) to 0 at its surface, so painted
 * influence has no step at a dab's edge.
 */
export function sphereWeight(s: BrushSphere, x: number, y: number, z: number): number {
  const d = Math.hypot(x - s[0], y - s[1], z - s[2]);
  const r = s[3];
  if (d >= r) return 0;
  if (d <= r / 2) return 1;
  return Math.cos(((d - r / 2) / (r / 2)) * HALF_PI);
}

/** The falloff a brushed vertex gets: at least what the add spheres give, less what the remove spheres take. */
export function brushed(falloff: number, add: number, keep: number): number {
  return (falloff > add ? falloff : add) * keep;
}

/**
 * Whether a rest point is a candidate of packed muscle `o`: within `margin` of its zone, by a test that may say yes
 * too often but never too rarely (the thesis's membership tests of 4.4, grown by the margin).
 */
export function reaches(P: Float64Array, o: number, margin: number, x: number, y: number, z: number): boolean {
  const dx = x - P[o + ANCHOR];
  const dy = y - P[o + ANCHOR + 1];
  const dz = z - P[o + ANCHOR + 2];
  const type = P[o + TYPE];
  if (type === LINEAR) {
    const D = Math.sqrt(dx * dx + dy * dy + dz * dz);
    if (D > P[o + LINEAR_FALLOFF_END] + margin) return false;
    if (D <= margin) return true;
    const cosMu = (dx * P[o + LINEAR_AXIS] + dy * P[o + LINEAR_AXIS + 1] + dz * P[o + LINEAR_AXIS + 2]) / D;
    const outside = Math.acos(cosMu > 1 ? 1 : cosMu < -1 ? -1 : cosMu) - P[o + LINEAR_ANGLE];
    // Distance to the cone's side is D sin(outside) while the nearest point is on the side, D beyond a right angle.
    return outside <= 0 || (outside < HALF_PI ? D * Math.sin(outside) : D) <= margin;
  }
  const F = o + FRAME;
  const qx = P[F] * dx + P[F + 3] * dy + P[F + 6] * dz;
  const qy = P[F + 1] * dx + P[F + 4] * dy + P[F + 7] * dz;
  const qz = P[F + 2] * dx + P[F + 5] * dy + P[F + 8] * dz;
  if (type === JAW) {
    return (
      Math.abs(qx) <= P[o + HALF_SIZE] + margin &&
      // A top face bent up toward the sides (a negative LIP_DROP) reaches above the box's half height.
      qy <= P[o + HALF_SIZE + 1] + Math.max(0, -P[o + LIP_DROP]) + margin &&
      -qy <= P[o + HALF_SIZE + 1] + margin &&
      Math.abs(qz) <= P[o + HALF_SIZE + 2] + margin
    );
  }
  // Ellipsoids: dividing by the radii stretches distances by at most 1 / (smallest radius), so a point within
  // `margin` of the ellipsoid has a normalised distance of at most 1 + margin / (smallest radius).
  const ix = P[o + INVERSE_RADII];
  const iy = P[o + INVERSE_RADII + 1];
  const iz = P[o + INVERSE_RADII + 2];
  const stretch = Math.max(ix, iy, iz);
  const rho = Math.sqrt((qx * ix) ** 2 + (qy * iy) ** 2 + (qz * iz) ** 2);
  return rho <= 1 + margin * stretch;
}

/** One muscle's displacement field, for tools and tests; MuscleRig runs the same code per vertex. */
export class MuscleField {
  readonly muscle: Muscle;
  private readonly packed = new Float64Array(STRIDE);

  /** Throws, naming the muscle, if it is not valid (see validateMuscle). */
  constructor(muscle: Muscle) {
    validateMuscle(muscle);
    this.muscle = muscle;
    packMuscle(muscle, this.packed, 0);
  }

  /** Displacement at (x, y, z) for contraction `c` (not clamped) into `out[0..3]`; returns the falloff, 0 outside. */
  displace(c: number, x: number, y: number, z: number, out: Float64Array | number[]): number {
    return displace(this.packed, 0, c, x, y, z, out);
  }

  /** Whether a rest point at (x, y, z) is within `margin` of the zone (conservatively: may say yes too often). */
  reaches(x: number, y: number, z: number, margin: number): boolean {
    return reaches(this.packed, 0, margin, x, y, z);
  }

  /** The hinge a lid or jaw muscle turns its skin about, in the head's frame; null for linear and sphincter. */
  joint(): Vec3 | null {
    const P = this.packed;
    return P[TYPE] === LID || P[TYPE] === JAW ? [P[JOINT], P[JOINT + 1], P[JOINT + 2]] : null;
  }

  /** The axis a lid or jaw muscle turns about (the local x axis, unit); null for linear and sphincter. */
  axis(): Vec3 | null {
    const P = this.packed;
    return P[TYPE] === LID || P[TYPE] === JAW ? [P[FRAME], P[FRAME + 3], P[FRAME + 6]] : null;
  }
}
