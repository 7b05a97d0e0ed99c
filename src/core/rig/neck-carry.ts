/**
 * The neck under a turned head (FACS AU51 to AU58, see head-pose.ts), as the skin solver takes it. The skin is solved
 * in the head's frame, where the skull stands still; a head turned by a pose is there a neck whose base is turned by
 * the inverse pose, while the head's skin stays put. So the neck's skin, from the cut at its base up to where the
 * head begins, is pulled by muscle-style targets: the inverse of a share of the pose that is whole at the base and
 * fades to none over the carried length. The solver then stretches the far side and folds the near side, as skin
 * over turning vertebrae does; the view turns the whole head by the pose, which puts the base back where the body
 * holds it. The thesis has no head positions; the pull is its muscle constraint (4.3.4) with targets from a turn, as
 * its rotation muscles (3.2.2) have. Pure: no three.js, no DOM.
 */
import {
  inverseTransformPoint,
  isRestingPose,
  POSE_TRANSFORM_SIZE,
  poseTransform,
  restingHeadPose,
  type HeadPose,
} from '../expression/head-pose';
import { chainLoops } from '../head/polymesh';
import type { MuscleInputs } from '../solver/muscle-inputs';
import { VertexKeyCounts } from '../solver/vertex-key-counts';
import type { Vec3 } from './rig-types';

/** Where the neck is: its cut, the axis up the neck from it, and the pivot the head turns about. */
export interface NeckFrame {
  /** The centre of the cut at the neck's base (the mean of its boundary loop). */
  base: Vec3;
  /** Unit axis from the cut toward the head (the cut's normal). */
  up: Vec3;
  /** Mean distance of the cut's loop from its centre, metres. */
  radius: number;
  /** Height above the cut over which the carry fades from whole to none, metres. */
  length: number;
  /** Where the head turns: on the axis, `length` above the cut. */
  pivot: Vec3;
}

/**
 * The carried length as a share of the cut's radius: on the default head 4 cm, from the cut up to the chin's
 * underside at the front and the skull's base at the back, so that the turn is spread over the neck's skin and none
 * of it over the face.
 */
const CARRY_LENGTH_SHARE = 0.8;
/**
 * Degrees of sideways bend in the neck's middle per degree of turn. The neck's vertebrae below the second couple a
 * turn with a bend to the same side, and those above bend back so the eyes stay level (the cervical spine's coupled
 * motion): the head's pose stays a pure turn, while the neck bows toward the side it turns to and its skin bunches
 * there. The bend is sin(pi share) times this, none at the cut and none at the head.
 */
const TURN_COUPLING = 0.25;
/** A boundary loop with fewer vertices than this is a hole, not the neck's cut. */
const MIN_LOOP = 8;
/** The hold reaches its whole weight where the carry's share is this or more (from none at the top of the neck). */
const FULL_HOLD_SHARE = 0.25;
/** A pose smaller than this (degrees, or metres times POSE_METRES_TO_DEGREES) holds the neck only partly. */
const HOLD_FADE_DEGREES = 3;
const POSE_METRES_TO_DEGREES = 1000;

/**
 * The skin's cut at the neck: its lowest boundary loop (the eyes and lips of a head mesh are closed or hidden, and
 * any other hole is higher), as a NeckFrame; null for a closed skin or one whose holes are all smaller than 8 edges.
 */
export function findNeck(rest: ArrayLike<number>, triangles: ArrayLike<number>): NeckFrame | null {
  const loops = boundaryLoops(triangles);
  let best: number[] | null = null;
  let bestY = Infinity;
  for (const loop of loops) {
    if (loop.length < MIN_LOOP) continue;
    let y = 0;
    for (const v of loop) y += rest[3 * v + 1];
    y /= loop.length;
    if (y < bestY) {
      bestY = y;
      best = loop;
    }
  }
  if (!best) return null;
  const base: Vec3 = [0, 0, 0];
  for (const v of best) for (let k = 0; k < 3; k++) base[k] += rest[3 * v + k] / best.length;
  // Newell's normal of the loop, turned toward the rest of the skin (the head is above its cut).
  const up: Vec3 = [0, 0, 0];
  for (let i = 0; i < best.length; i++) {
    const a = 3 * best[i];
    const b = 3 * best[(i + 1) % best.length];
    up[0] += (rest[a + 1] - rest[b + 1]) * (rest[a + 2] + rest[b + 2]);
    up[1] += (rest[a + 2] - rest[b + 2]) * (rest[a] + rest[b]);
    up[2] += (rest[a] - rest[b]) * (rest[a + 1] + rest[b + 1]);
  }
  const n = Math.hypot(up[0], up[1], up[2]);
  if (!(n > 0)) return null;
  for (let k = 0; k < 3; k++) up[k] /= n;
  let centreSide = 0;
  const count = rest.length / 3;
  for (let v = 0; v < count; v++) {
    centreSide += (rest[3 * v] - base[0]) * up[0] + (rest[3 * v + 1] - base[1]) * up[1] + (rest[3 * v + 2] - base[2]) * up[2];
  }
  if (centreSide < 0) for (let k = 0; k < 3; k++) up[k] = -up[k];
  let radius = 0;
  for (const v of best) radius += Math.hypot(rest[3 * v] - base[0], rest[3 * v + 1] - base[1], rest[3 * v + 2] - base[2]) / best.length;
  const length = CARRY_LENGTH_SHARE * radius;
  const pivot: Vec3 = [base[0] + length * up[0], base[1] + length * up[1], base[2] + length * up[2]];
  return { base, up, radius, length, pivot };
}

/** The share of the pose's inverse a vertex `height` metres above the cut takes: 1 at the cut, 0 from `length` up, smooth. */
export function carryShare(height: number, length: number): number {
  if (height <= 0) return 1;
  if (height >= length) return 0;
  const t = height / length;
  return 1 - t * t * (3 - 2 * t);
}

/**
 * The neck's pull for a head pose, added to the rig's muscle inputs after the rig computed them: each carried
 * vertex's target (where its muscles put it, or its rest) is moved by the inverse of its share of the pose, and it is
 * held at least by a weight that grows with that share. A resting pose changes nothing, so an expression without
 * head positions is solved exactly as before. Allocates nothing per call.
 */
export class NeckCarry {
  /** The carried vertices (simulation order) and each one's share of the pose. */
  private readonly vertices: Uint32Array;
  private readonly shares: Float32Array;
  private readonly transform = new Float64Array(POSE_TRANSFORM_SIZE);
  /** The share of the pose one vertex takes (reused). */
  private readonly part = restingHeadPose();

  private constructor(
    readonly frame: NeckFrame,
    rest: ArrayLike<number>,
  ) {
    const picked: number[] = [];
    const shares: number[] = [];
    const { base, up, length } = frame;
    for (let v = 0; v < rest.length / 3; v++) {
      const h = (rest[3 * v] - base[0]) * up[0] + (rest[3 * v + 1] - base[1]) * up[1] + (rest[3 * v + 2] - base[2]) * up[2];
      const s = carryShare(h, length);
      if (s > 0) {
        picked.push(v);
        shares.push(s);
      }
    }
    this.vertices = Uint32Array.from(picked);
    this.shares = Float32Array.from(shares);
  }

  /** The carry of a skin with a neck cut (see findNeck); null for one without. */
  static create(rest: ArrayLike<number>, triangles: ArrayLike<number>): NeckCarry | null {
    const frame = findNeck(rest, triangles);
    return frame ? new NeckCarry(frame, rest) : null;
  }

  /** How many vertices the carry may move. */
  get vertexCount(): number {
    return this.vertices.length;
  }

  /** Adds the neck's pull for `pose` to muscle inputs the rig has just written (targets and both weights). */
  apply(pose: HeadPose, into: MuscleInputs): void {
    if (isRestingPose(pose)) return;
    const { targets: T, weights: W, normalWeights: WN } = into;
    const size = Math.max(Math.abs(pose.yaw), Math.abs(pose.pitch), Math.abs(pose.roll), Math.abs(pose.forward) * POSE_METRES_TO_DEGREES);
    const fade = Math.min(1, size / HOLD_FADE_DEGREES);
    const m = this.transform;
    const pivot = this.frame.pivot;
    const part = this.part;
    for (let k = 0; k < this.vertices.length; k++) {
      const v = this.vertices[k];
      const share = this.shares[k];
      const i = 3 * v;
      part.yaw = share * pose.yaw;
      part.pitch = share * pose.pitch;
      part.roll = share * pose.roll + TURN_COUPLING * pose.yaw * Math.sin(Math.PI * share);
      part.forward = share * pose.forward;
      poseTransform(part, 1, pivot, m);
      inverseTransformPoint(m, T[i], T[i + 1], T[i + 2], T, i);
      const hold = fade * Math.min(1, share / FULL_HOLD_SHARE);
      if (W[v] < hold) W[v] = hold;
      if (WN[v] < hold) WN[v] = hold;
    }
  }
}

/** The boundary loops of a triangle mesh: edges with no twin, chained head to tail (each loop in order). */
function boundaryLoops(triangles: ArrayLike<number>): number[][] {
  // Each edge a -> b, counted in typed arrays (a Set of a * count + b took the high head 0.28 s).
  const directed = new VertexKeyCounts(triangles.length);
  for (let t = 0; t < triangles.length; t += 3) {
    for (let k = 0; k < 3; k++) directed.add(triangles[t + k], triangles[t + ((k + 1) % 3)]);
  }
  const next = new Map<number, number>();
  for (let t = 0; t < triangles.length; t += 3) {
    for (let k = 0; k < 3; k++) {
      const a = triangles[t + k];
      const b = triangles[t + ((k + 1) % 3)];
      if (directed.get(b, a) === 0) next.set(a, b);
    }
  }
  return chainLoops(next);
}
