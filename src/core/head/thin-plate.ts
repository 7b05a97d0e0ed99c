/**
 * A thin-plate spline in 3D: the smooth map that takes a set of source points exactly onto target points, with the
 * least bending (kernel |r|, the biharmonic one in three dimensions) on top of an affine part. It carries a rig made
 * on one head over to another head whose landmarks were found. Pure numbers: no three.js, no DOM.
 */
import type { Vec3 } from '../rig/rig-types';

/** A fitted thin-plate spline: `apply` maps points, `jacobian` gives the local linear part. */
export interface ThinPlateWarp {
  /** The source points the spline was fitted on (xyz, flat). */
  readonly sources: Float64Array;
  /** Kernel weights, xyz per source point. */
  readonly weights: Float64Array;
  /** Affine part: row-major 3 x 3 matrix, then the translation. */
  readonly linear: Float64Array;
  readonly translation: Float64Array;
  /** The affine part's uniform scale: the cube root of its determinant (lengths in the rig scale by this). */
  readonly scale: number;
  /**
   * Where many more point pairs are known than the spline was fitted on (two heads with the same vertices): those
   * points (xyz, flat) and what the spline misses at each (target minus spline, xyz), spread to every point from its
   * nearest few by inverse distance squared, so that the warp takes each known point exactly onto its target.
   */
  readonly correction?: { readonly points: Float64Array; readonly residuals: Float64Array };
}

/** How many known points spread their residual to a warped point (see ThinPlateWarp.correction). */
const CORRECTION_NEIGHBOURS = 6;

/**
 * Fits the spline that maps `sources[i]` onto `targets[i]` exactly. Needs at least four points not all in one plane;
 * throws naming the problem otherwise.
 */
export function fitThinPlate(sources: readonly Vec3[], targets: readonly Vec3[]): ThinPlateWarp {
  const n = sources.length;
  if (n !== targets.length) throw new Error(`thin-plate warp: ${n} source points but ${targets.length} targets`);
  if (n < 4) throw new Error(`thin-plate warp: needs at least 4 point pairs, got ${n}`);
  for (const [list, what] of [
    [sources, 'source'],
    [targets, 'target'],
  ] as const) {
    list.forEach((p, i) => {
      if (!p.every(Number.isFinite)) throw new Error(`thin-plate warp: ${what} point ${i} is not finite (${p.join(', ')})`);
    });
  }
  // The system [K P; P^T 0] [w; a] = [t; 0], K_ij = |s_i - s_j|, P_i = [1 s_i].
  const m = n + 4;
  const A = new Float64Array(m * m);
  const B = new Float64Array(m * 3);
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < n; j++) A[i * m + j] = distance(sources[i], sources[j]);
    A[i * m + n] = 1;
    A[n * m + i] = 1;
    for (let k = 0; k < 3; k++) {
      A[i * m + n + 1 + k] = sources[i][k];
      A[(n + 1 + k) * m + i] = sources[i][k];
      B[i * 3 + k] = targets[i][k];
    }
  }
  const X = solve(A, B, m, 3);
  if (!X) throw new Error('thin-plate warp: the source points are degenerate (all in one plane, or repeated)');
  const weights = X.slice(0, 3 * n);
  const translation = X.slice(3 * n, 3 * n + 3);
  // Rows n+1..n+3 hold d(target_k)/d(source_j) as X[(n+1+j)*3 + k]: transpose into row-major target-by-source.
  const linear = new Float64Array(9);
  for (let j = 0; j < 3; j++) for (let k = 0; k < 3; k++) linear[k * 3 + j] = X[(n + 1 + j) * 3 + k];
  const det =
    linear[0] * (linear[4] * linear[8] - linear[5] * linear[7]) -
    linear[1] * (linear[3] * linear[8] - linear[5] * linear[6]) +
    linear[2] * (linear[3] * linear[7] - linear[4] * linear[6]);
  const sources64 = Float64Array.from(sources.flat());
  return { sources: sources64, weights, linear, translation, scale: Math.cbrt(Math.abs(det)) };
}

/** Where the warp takes the point `p`. */
export function warpPoint(warp: ThinPlateWarp, p: readonly number[]): Vec3 {
  const { sources, weights, linear: L, translation: t } = warp;
  const out: Vec3 = [
    t[0] + L[0] * p[0] + L[1] * p[1] + L[2] * p[2],
    t[1] + L[3] * p[0] + L[4] * p[1] + L[5] * p[2],
    t[2] + L[6] * p[0] + L[7] * p[1] + L[8] * p[2],
  ];
  for (let i = 0; i < sources.length / 3; i++) {
    const r = Math.hypot(p[0] - sources[3 * i], p[1] - sources[3 * i + 1], p[2] - sources[3 * i + 2]);
    for (let k = 0; k < 3; k++) out[k] += weights[3 * i + k] * r;
  }
  if (warp.correction) addCorrection(warp.correction, p, out);
  return out;
}

/** Adds the inverse-distance-squared mean of the nearest known points' residuals to `out` (see ThinPlateWarp.correction). */
function addCorrection(c: NonNullable<ThinPlateWarp['correction']>, p: readonly number[], out: Vec3): void {
  const nearest: { d: number; i: number }[] = [];
  for (let i = 0; i < c.points.length / 3; i++) {
    const d = (p[0] - c.points[3 * i]) ** 2 + (p[1] - c.points[3 * i + 1]) ** 2 + (p[2] - c.points[3 * i + 2]) ** 2;
    if (nearest.length === CORRECTION_NEIGHBOURS && d >= nearest[CORRECTION_NEIGHBOURS - 1].d) continue;
    if (nearest.length === CORRECTION_NEIGHBOURS) nearest.pop();
    let at = nearest.length;
    while (at > 0 && nearest[at - 1].d > d) at--;
    nearest.splice(at, 0, { d, i });
  }
  // On a known point itself: its residual whole.
  if (nearest.length > 0 && nearest[0].d < 1e-18) {
    for (let k = 0; k < 3; k++) out[k] += c.residuals[3 * nearest[0].i + k];
    return;
  }
  let total = 0;
  const sum = [0, 0, 0];
  for (const { d, i } of nearest) {
    total += 1 / d;
    for (let k = 0; k < 3; k++) sum[k] += c.residuals[3 * i + k] / d;
  }
  if (total > 0) for (let k = 0; k < 3; k++) out[k] += sum[k] / total;
}

/** The warp's derivative at `p`: row-major 3 x 3, d(out_row) / d(in_column) (the spline's: a correction's is left out). */
export function warpJacobian(warp: ThinPlateWarp, p: readonly number[]): Float64Array {
  const J = Float64Array.from(warp.linear);
  const { sources, weights } = warp;
  for (let i = 0; i < sources.length / 3; i++) {
    const d = [p[0] - sources[3 * i], p[1] - sources[3 * i + 1], p[2] - sources[3 * i + 2]];
    const r = Math.hypot(d[0], d[1], d[2]);
    // The kernel's gradient d/r is undefined at a source point itself; its limit is taken as zero there.
    if (r < 1e-12) continue;
    for (let row = 0; row < 3; row++) for (let col = 0; col < 3; col++) J[row * 3 + col] += (weights[3 * i + row] * d[col]) / r;
  }
  return J;
}

function distance(a: readonly number[], b: readonly number[]): number {
  return Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

/** Solves A X = B (A m x m, B m x k, row-major) by Gaussian elimination with partial pivoting; null if singular. */
function solve(A: Float64Array, B: Float64Array, m: number, k: number): Float64Array | null {
  const a = Float64Array.from(A);
  const b = Float64Array.from(B);
  let scale = 0;
  for (const v of a) scale = Math.max(scale, Math.abs(v));
  for (let col = 0; col < m; col++) {
    let pivot = col;
    for (let r = col + 1; r < m; r++) if (Math.abs(a[r * m + col]) > Math.abs(a[pivot * m + col])) pivot = r;
    if (Math.abs(a[pivot * m + col]) <= 1e-12 * scale) return null;
    if (pivot !== col) {
      for (let c = 0; c < m; c++) [a[col * m + c], a[pivot * m + c]] = [a[pivot * m + c], a[col * m + c]];
      for (let c = 0; c < k; c++) [b[col * k + c], b[pivot * k + c]] = [b[pivot * k + c], b[col * k + c]];
    }
    for (let r = 0; r < m; r++) {
      if (r === col) continue;
      const f = a[r * m + col] / a[col * m + col];
      if (f === 0) continue;
      for (let c = col; c < m; c++) a[r * m + c] -= f * a[col * m + c];
      for (let c = 0; c < k; c++) b[r * k + c] -= f * b[col * k + c];
    }
  }
  for (let r = 0; r < m; r++) for (let c = 0; c < k; c++) b[r * k + c] /= a[r * m + r];
  return b;
}
