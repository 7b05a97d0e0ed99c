/**
 * Orientation constraints as a part loop (see solver-kernels.ts): a triangle may tilt into a fold but not turn over.
 * Here also each triangle's rest frame and least area, and the pass modes that let most passes check only the
 * triangles that may need it.
 */
import type { PartArrays } from './part-arrays';
import { wasmKernels } from './wasm-kernels';

/**
 * The least share of its rest area a triangle keeps along its rest normal: a triangle tilted 75 degrees into a fold
 * still passes, one flattened to a sliver or turned over does not.
 */
export const MIN_PROJECTED_AREA = 0.25;

/** Each triangle's rest unit normal and twice its least projected area (MIN_PROJECTED_AREA of the rest), xyzA. */
export function triangleFrames(rest: Float32Array, triangles: Uint32Array): Float32Array {
  const count = triangles.length / 3;
  const out = new Float32Array(4 * count);
  for (let t = 0; t < count; t++) {
    const a = 3 * triangles[3 * t];
    const b = 3 * triangles[3 * t + 1];
    const c = 3 * triangles[3 * t + 2];
    const ux = rest[b] - rest[a],
      uy = rest[b + 1] - rest[a + 1],
      uz = rest[b + 2] - rest[a + 2];
    const vx = rest[c] - rest[a],
      vy = rest[c + 1] - rest[a + 1],
      vz = rest[c + 2] - rest[a + 2];
    const cx = uy * vz - uz * vy,
      cy = uz * vx - ux * vz,
      cz = ux * vy - uy * vx;
    const twiceArea = Math.hypot(cx, cy, cz);
    if (twiceArea === 0) continue;
    out[4 * t] = cx / twiceArea;
    out[4 * t + 1] = cy / twiceArea;
    out[4 * t + 2] = cz / twiceArea;
    out[4 * t + 3] = MIN_PROJECTED_AREA * twiceArea;
  }
  return out;
}

/**
 * Orientation of one part's triangles: each triangle's area projected on its frame's normal (its rest normal, turned
 * where the lids and the jaw carry the skin: see CarriedFrames) stays above a fraction of its rest area, so compressed
 * skin folds (the triangle tilts) instead of crumpling flat (the triangle turns over within the surface), which no
 * length constraint can tell from the right shape. The projected area is linear in each corner, so one projection
 * restores the bound exactly; the corrections lie in the plane the frame's normal stands on.
 *
 * `mode` is ORIENT_FULL, ORIENT_AGAIN or ORIENT_WATCHED. ORIENT_AGAIN says that nothing but the previous orientation
 * pass moved the skin since: a triangle found within its bound then, none of whose corners moved since, still is and
 * is skipped, with the same result as checking it. `floor` scales the bound (see ORIENTATION_SHOWN_FLOOR in
 * solver.ts). Returns whether a triangle was more than a hair under its bound.
 */
export function projectOrientationPart(a: PartArrays, part: number, mode: number, floor = 1): boolean {
  const x = a.positions;
  const kernels = wasmKernels(a);
  if (kernels) {
    const t = a.triangles;
    const corrected = kernels.orient(
      x.byteOffset,
      t.corners.byteOffset,
      t.frames.byteOffset,
      a.unchecked.byteOffset,
      a.watched.byteOffset,
      a.vertexTriangleStart.byteOffset,
      a.vertexTriangles.byteOffset,
      a.listedTriangle.byteOffset,
      t.parts[part],
      t.parts[part + 1],
      mode,
      floor,
    );
    return corrected !== 0;
  }
  const T = a.triangles.corners;
  const F = a.triangles.frames;
  const full = mode === ORIENT_FULL;
  const flags = mode === ORIENT_AGAIN ? a.unchecked : a.watched;
  const words = mode === ORIENT_AGAIN ? a.uncheckedWords : a.watchedWords;
  const unchecked = a.unchecked;
  const watched = a.watched;
  let corrected = false;
  const t1 = a.triangles.parts[part + 1];
  for (let t = a.triangles.parts[part]; t < t1; t++) {
    if (!full) {
      // Most triangles are skipped: skip them four at a time where aligned.
      if ((t & 3) === 0 && words[t >> 2] === 0) {
        t += 3;
        continue;
      }
      if (flags[t] === 0) continue;
    }
    if (mode !== ORIENT_WATCHED) unchecked[t] = 0;
    const ia = T[3 * t];
    const ib = T[3 * t + 1];
    const ic = T[3 * t + 2];
    const ax = x[ia],
      ay = x[ia + 1],
      az = x[ia + 2];
    const ux = x[ib] - ax;
    const uy = x[ib + 1] - ay;
    const uz = x[ib + 2] - az;
    const vx = x[ic] - ax;
    const vy = x[ic + 1] - ay;
    const vz = x[ic + 2] - az;
    const nx = F[4 * t];
    const ny = F[4 * t + 1];
    const nz = F[4 * t + 2];
    const bound = F[4 * t + 3];
    // Twice the area along n: n . (u x v).
    const area = nx * (uy * vz - uz * vy) + ny * (uz * vx - ux * vz) + nz * (ux * vy - uy * vx);
    if (full && area < ORIENT_WATCH * bound) watched[t] = 1;
    const least = floor * bound;
    const C = area - least;
    if (C >= 0) continue;
    // A triangle a hair under its bound (the relaxation's blend) is corrected but does not ask for another pass.
    if (C < -0.01 * least) corrected = true;
    // Gradients: b gets v x n, c gets n x u, a gets minus their sum, (u - v) x n.
    const gbx = vy * nz - vz * ny;
    const gby = vz * nx - vx * nz;
    const gbz = vx * ny - vy * nx;
    const gcx = ny * uz - nz * uy;
    const gcy = nz * ux - nx * uz;
    const gcz = nx * uy - ny * ux;
    const gax = -gbx - gcx;
    const gay = -gby - gcy;
    const gaz = -gbz - gcz;
    const norm = gax * gax + gay * gay + gaz * gaz + gbx * gbx + gby * gby + gbz * gbz + gcx * gcx + gcy * gcy + gcz * gcz;
    if (norm === 0) {
      if (mode !== ORIENT_WATCHED) unchecked[t] = 1; // not within its bound: check it again next time
      continue;
    }
    if (mode !== ORIENT_WATCHED) {
      markMoved(a, ia);
      markMoved(a, ib);
      markMoved(a, ic);
    }
    const lambda = -C / norm;
    x[ia] += lambda * gax;
    x[ia + 1] += lambda * gay;
    x[ia + 2] += lambda * gaz;
    x[ib] += lambda * gbx;
    x[ib + 1] += lambda * gby;
    x[ib + 2] += lambda * gbz;
    x[ic] += lambda * gcx;
    x[ic + 1] += lambda * gcy;
    x[ic + 2] += lambda * gcz;
  }
  return corrected;
}

/**
 * Whether a listed triangle is turned over (its area along its frame below zero). The passes keep every triangle
 * above its bound, but in a frame where they run out a sliver can still be over; the solver does not sleep on one.
 */
export function anyTurnedOver(a: PartArrays): boolean {
  const T = a.triangles.corners;
  const parts = a.triangles.parts;
  for (let t = parts[0], end = parts[parts.length - 1]; t < end; t++)
    if (areaAlong(a.positions, T[3 * t], T[3 * t + 1], T[3 * t + 2], a.triangles.frames, 4 * t) < 0) return true;
  return false;
}

/** How many of the triangles (vertex indices) are turned over against their frames (triangleFrames' layout). */
export function countTurnedOver(x: Float32Array, triangles: Uint32Array, frames: Float32Array): number {
  let count = 0;
  for (let t = 0; t < triangles.length / 3; t++)
    if (areaAlong(x, 3 * triangles[3 * t], 3 * triangles[3 * t + 1], 3 * triangles[3 * t + 2], frames, 4 * t) < 0) count++;
  return count;
}

/**
 * Twice the area, along the frame normal `F[o..o+2]`, of the triangle whose corners lie at xyz offsets `ia`, `ib`,
 * `ic` of `x`: below zero for a triangle turned over against its frame.
 */
function areaAlong(x: Float32Array, ia: number, ib: number, ic: number, F: Float32Array, o: number): number {
  const ux = x[ib] - x[ia];
  const uy = x[ib + 1] - x[ia + 1];
  const uz = x[ib + 2] - x[ia + 2];
  const vx = x[ic] - x[ia];
  const vy = x[ic + 1] - x[ia + 1];
  const vz = x[ic + 2] - x[ia + 2];
  return F[o] * (uy * vz - uz * vy) + F[o + 1] * (uz * vx - ux * vz) + F[o + 2] * (ux * vy - uy * vx);
}

/** An orientation pass that checks every listed triangle and adds those near their bound to the watched ones. */
export const ORIENT_FULL = 0;
/** A pass that follows another with nothing else in between: it checks only triangles with a corner moved since. */
export const ORIENT_AGAIN = 1;
/** A pass within a frame's iterations: it checks only the watched triangles (see ORIENT_WATCH). */
export const ORIENT_WATCHED = 2;
/**
 * A triangle is watched once a full pass finds it under this many times its bound; it stays watched until the inputs
 * change. The frame's last passes check every triangle, so what is shown keeps the bound either way; the passes within
 * the iterations, which on the high head took a quarter of the frame, then check a few thousand triangles instead of
 * the whole region (high happiness: 8 thousand of 93). The set only grows within a motion, so the frame's map stops
 * changing within some dozens of frames instead of switching a triangle's check on and off.
 */
export const ORIENT_WATCH = 1.5;

/**
 * Marks the listed triangles of the vertex at xyz offset `i` for the next orientation check. The other thread's part
 * shares no vertex with this one, but the triangles around a vertex may lie in either seam part: both threads may
 * mark one, each writing the same 1, and neither checks it before the next pair of parts.
 */
function markMoved(a: PartArrays, i: number): void {
  const v = i / 3;
  const start = a.vertexTriangleStart;
  const listed = a.listedTriangle;
  const triangles = a.vertexTriangles;
  for (let j = start[v]; j < start[v + 1]; j++) {
    const t = listed[triangles[j]];
    if (t >= 0) a.unchecked[t] = 1;
  }
}
