/**
 * The warp that carries what was made on the default head (its rig, its landmarks) over to an identity's head. Both
 * heads have the same vertices in the same order, so instead of a dozen landmarks found on the new mesh the warp is
 * fitted on a few hundred matching skin vertices, spread over the head: it follows the identity's shape closely.
 */
import type { Vec3 } from '../rig/rig-types';
import { fitThinPlate, warpPoint, type ThinPlateWarp } from './thin-plate';

/** How many matching vertices the warp is fitted on: enough to follow a nose or a brow ridge, few enough to solve fast. */
const IDENTITY_WARP_POINTS = 240;

/**
 * `count` vertices spread evenly over a point set (farthest-point sampling from vertex 0, deterministic): each next
 * pick is the vertex farthest from all picked so far.
 */
export function spreadVertices(positions: ArrayLike<number>, count: number): number[] {
  const n = Math.floor(positions.length / 3);
  const picks: number[] = [];
  if (n === 0) return picks;
  const nearest = new Float64Array(n).fill(Infinity);
  let next = 0;
  for (let k = 0; k < Math.min(count, n); k++) {
    picks.push(next);
    const px = positions[3 * next];
    const py = positions[3 * next + 1];
    const pz = positions[3 * next + 2];
    let far = -1;
    let farthest = -1;
    for (let v = 0; v < n; v++) {
      const d = (positions[3 * v] - px) ** 2 + (positions[3 * v + 1] - py) ** 2 + (positions[3 * v + 2] - pz) ** 2;
      if (d < nearest[v]) nearest[v] = d;
      if (nearest[v] > far) {
        far = nearest[v];
        farthest = v;
      }
    }
    if (far <= 0) break;
    next = farthest;
  }
  return picks;
}

/**
 * Fits the warp from the default head's skin (`base`, xyz per vertex) to an identity's (`moved`, the same vertices
 * moved): a thin-plate spline on `count` vertices spread over the head, corrected by what it misses at every vertex
 * (so it takes each vertex exactly onto its place). Throws if the two differ in length or hold a non-finite value.
 */
export function fitIdentityWarp(base: ArrayLike<number>, moved: ArrayLike<number>, count = IDENTITY_WARP_POINTS): ThinPlateWarp {
  if (base.length !== moved.length)
    throw new Error(`identity warp: the default head has ${base.length / 3} vertices but the identity's ${moved.length / 3}`);
  const picks = spreadVertices(base, count);
  const at = (p: ArrayLike<number>, v: number): Vec3 => [p[3 * v], p[3 * v + 1], p[3 * v + 2]];
  const spline = fitThinPlate(
    picks.map((v) => at(base, v)),
    picks.map((v) => at(moved, v)),
  );
  // What the spline misses between its points (lips and lids, where close surfaces move apart) at every vertex.
  const points = Float64Array.from(base);
  const residuals = new Float64Array(points.length);
  for (let v = 0; v < points.length / 3; v++) {
    const p = warpPoint(spline, at(base, v));
    for (let k = 0; k < 3; k++) residuals[3 * v + k] = moved[3 * v + k] - p[k];
  }
  return { ...spline, correction: { points, residuals } };
}
