/**
 * The frame's bookkeeping as part loops (see solver-kernels.ts): the momentum a frame starts with, the relaxation that
 * turns cycles into convergence, and each vertex's recorded move.
 */
import type { PartArrays } from './part-arrays';
import { wasmKernels } from './wasm-kernels';

/**
 * The frame's start for the region's vertices `k0..k1`: stores where each starts (skin outside the region stays at
 * rest, and so does `previous` there; see SkinSolver.refreshLists), then carries its momentum. Heavy-ball
 * acceleration (Polyak): each vertex first takes `beta` times its last move along the surface and `foldBeta` times its
 * last move along its rest normal, then the frame's projections. The soft position constraint lets a displaced sheet
 * fade by only a few per cent an iteration; the carried move makes the slow modes fade about as the square root of
 * that factor per frame. A carried move that overshoots turns back, and the relaxation treats that as any cycle.
 */
export function startFramePart(a: PartArrays, beta: number, foldBeta: number, k0: number, k1: number): void {
  const x = a.positions;
  const prev = a.previous;
  const N = a.restNormals;
  const extra = foldBeta - beta;
  const carry = beta !== 0 || foldBeta !== 0;
  const last = a.lastStep;
  const restart = a.restart;
  const share = a.relaxation;
  const V = a.regionVertices;
  const kernels = wasmKernels(a);
  if (kernels) {
    kernels.start(
      x.byteOffset,
      prev.byteOffset,
      N.byteOffset,
      last.byteOffset,
      restart.byteOffset,
      share.byteOffset,
      V.byteOffset,
      beta,
      extra,
      carry ? 1 : 0,
      k0,
      k1,
    );
    return;
  }
  for (let k = k0; k < k1; k++) {
    const v = V[k];
    const i = 3 * v;
    prev[i] = x[i];
    prev[i + 1] = x[i + 1];
    prev[i + 2] = x[i + 2];
    if (!carry) continue;
    if (restart[v] === 1 || share[v] < 1) {
      restart[v] = 0;
      continue;
    }
    const along = extra * (last[i] * N[i] + last[i + 1] * N[i + 1] + last[i + 2] * N[i + 2]);
    x[i] += beta * last[i] + along * N[i];
    x[i + 1] += beta * last[i + 1] + along * N[i + 1];
    x[i + 2] += beta * last[i + 2] + along * N[i + 2];
  }
}

/** The least share of its solved move a vertex that keeps turning back takes in a frame (see relaxPart). */
const MIN_RELAXATION = 1 / 16;

/**
 * A vertex's share is halved when it turns back again within this many frames of its last turn (see relaxPart): a
 * cycle repeats, while one turn is often a single bounce (a lip on a tooth as the skin starts moving).
 */
const CYCLE_TURNS_WITHIN = 2;

/**
 * The relaxation (see SkinSolver.relax) of the region's vertices `k0..k1`: each takes its share, at most `cap`, of its
 * solved move; a vertex whose move turns back on its last one again soon halves its share.
 */
export function relaxPart(a: PartArrays, cap: number, k0: number, k1: number): void {
  const x = a.positions;
  const prev = a.previous;
  const last = a.lastStep;
  const share = a.relaxation;
  const calm = a.calm;
  const restart = a.restart;
  const V = a.regionVertices;
  const kernels = wasmKernels(a);
  if (kernels) {
    kernels.relax(
      x.byteOffset,
      prev.byteOffset,
      last.byteOffset,
      share.byteOffset,
      calm.byteOffset,
      restart.byteOffset,
      V.byteOffset,
      cap,
      MIN_RELAXATION,
      CYCLE_TURNS_WITHIN,
      k0,
      k1,
    );
    return;
  }
  for (let k = k0; k < k1; k++) {
    const v = V[k];
    const i = 3 * v;
    const dx = x[i] - prev[i];
    const dy = x[i + 1] - prev[i + 1];
    const dz = x[i + 2] - prev[i + 2];
    const lx = last[i],
      ly = last[i + 1],
      lz = last[i + 2];
    const turn = dx * lx + dy * ly + dz * lz;
    if (turn < 0) restart[v] = 1;
    let w = share[v];
    // Turned back by more than 120 degrees: a cycle, not a curve.
    if (turn < 0 && 4 * turn * turn > (dx * dx + dy * dy + dz * dz) * (lx * lx + ly * ly + lz * lz)) {
      if (w > MIN_RELAXATION && calm[v] < CYCLE_TURNS_WITHIN) w = share[v] = w * 0.5;
      calm[v] = 0;
    } else if (calm[v] < 255) calm[v]++;
    if (w > cap) w = cap;
    if (w === 1) continue;
    x[i] = prev[i] + w * dx;
    x[i + 1] = prev[i + 1] + w * dy;
    x[i + 2] = prev[i + 2] + w * dz;
  }
}

/**
 * Stores the frame's move of each of the region's vertices `k0..k1`, adds its length to the vertex's way, and returns
 * the largest squared move. Skin outside the region does not move; its steps are zeroed when it leaves (see
 * SkinSolver.refreshLists).
 */
export function recordStepsPart(a: PartArrays, k0: number, k1: number): number {
  const x = a.positions;
  const prev = a.previous;
  const last = a.lastStep;
  const path = a.path;
  const V = a.regionVertices;
  const kernels = wasmKernels(a);
  if (kernels) return kernels.steps(x.byteOffset, prev.byteOffset, last.byteOffset, path.byteOffset, V.byteOffset, k0, k1);
  let largest2 = 0;
  for (let k = k0; k < k1; k++) {
    const v = V[k];
    const i = 3 * v;
    // The step as computed (double), not as stored in the Float32Array: the same numbers as before.
    const dx = x[i] - prev[i];
    const dy = x[i + 1] - prev[i + 1];
    const dz = x[i + 2] - prev[i + 2];
    last[i] = dx;
    last[i + 1] = dy;
    last[i + 2] = dz;
    const d2 = dx * dx + dy * dy + dz * dz;
    if (d2 > largest2) largest2 = d2;
    path[v] += Math.sqrt(d2);
  }
  return largest2;
}

/**
 * Skin outside the region (`inside[v]` 0) is at rest and does not move: its last step is zero, its previous place rest
 * and it has no turn to remember, so that a vertex joining within a frame (see SkinSolver.settleRegion) starts from
 * there, as it would had it never been in the region.
 */
export function restOutside(a: PartArrays, inside: Uint8Array): void {
  const last = a.lastStep;
  const prev = a.previous;
  const X = a.rest;
  for (let v = 0; v < inside.length; v++) {
    if (inside[v]) continue;
    const i = 3 * v;
    a.restart[v] = 0;
    a.path[v] = 0;
    last[i] = last[i + 1] = last[i + 2] = 0;
    prev[i] = X[i];
    prev[i + 1] = X[i + 1];
    prev[i + 2] = X[i + 2];
  }
}
