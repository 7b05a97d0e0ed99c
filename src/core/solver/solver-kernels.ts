/**
 * The solver's heaviest loops as functions of one part of the constraint lists (see constraint-lists.ts): the leader
 * thread's SkinSolver and the partner thread's SolverPartner run the same code on the same shared arrays. Here the
 * constraints that move a vertex (or a vertex and its ring) alone: position and muscle, collisions, bending, and the
 * normals; the lengths, the orientation and the frame's bookkeeping are in length-kernels.ts, orientation-kernel.ts and
 * frame-kernels.ts.
 */
import { COLLIDER_SHAPE, shapeDistance } from './colliders';
import { PART_EVEN, PART_EVEN_SEAM, PARTS } from './constraint-lists';
import type { PartArrays } from './part-arrays';
import { meet } from './partner-board';
import { addFaceNormals, normalize } from './topology';
import { type WasmKernels, wasmKernels } from './wasm-kernels';

/**
 * Position and muscle constraints of the region's vertices `k0..k1`, each vertex's in turn (both move only their own
 * vertex, so this is the order of all positions, then all muscles).
 *
 * Position (thesis 4.3.2): pull each vertex back toward rest by `stiffness`. The thesis adds the unit vector from rest
 * to the vertex times the distance, which pushes it away; the stable form moves a fraction of the way back. Sinking
 * below rest along the normal is resisted harder (by `extra` more), so folds bulge out rather than in.
 *
 * Muscle (thesis 4.3.4): move a held vertex toward its target by `muscleStiffness` times its weights, along the surface
 * and along the rest normal. The thesis scales the step by the squared distance, a force cubic in distance that
 * overshoots and explodes for far targets; a fixed fraction of the remaining distance converges for any target.
 */
export function projectPositions(a: PartArrays, stiffness: number, extra: number, muscleStiffness: number, k0: number, k1: number): void {
  const x = a.positions;
  const kernels = wasmKernels(a);
  if (kernels) {
    const { rest, restNormals, targets, weights, normalWeights, regionVertices } = a;
    const xp = x.byteOffset;
    const np = restNormals.byteOffset;
    const tp = targets.byteOffset;
    const vp = regionVertices.byteOffset;
    kernels.positions(
      xp,
      rest.byteOffset,
      np,
      tp,
      weights.byteOffset,
      normalWeights.byteOffset,
      vp,
      stiffness,
      extra,
      muscleStiffness,
      k0,
      k1,
    );
    return;
  }
  const X = a.rest;
  const N = a.restNormals;
  const T = a.targets;
  const W = a.weights;
  const WN = a.normalWeights;
  const V = a.regionVertices;
  for (let j = k0; j < k1; j++) {
    const v = V[j];
    const i = 3 * v;
    const nx = N[i],
      ny = N[i + 1],
      nz = N[i + 2];
    const ux = X[i] - x[i];
    const uy = X[i + 1] - x[i + 1];
    const uz = X[i + 2] - x[i + 2];
    // Depth below rest along the normal (positive when sunk in).
    const depth = ux * nx + uy * ny + uz * nz;
    const k = depth > 0 ? extra * depth : 0;
    x[i] += stiffness * ux + k * nx;
    x[i + 1] += stiffness * uy + k * ny;
    x[i + 2] += stiffness * uz + k * nz;
    const w = W[v];
    const wn = WN[v];
    if (w === 0 && wn === 0) continue;
    const m = muscleStiffness * w;
    const dx = T[i] - x[i];
    const dy = T[i + 1] - x[i + 1];
    const dz = T[i + 2] - x[i + 2];
    // The pull's part along the rest normal gets its own weight.
    const along = (muscleStiffness * wn - m) * (dx * nx + dy * ny + dz * nz);
    x[i] += m * dx + along * nx;
    x[i + 1] += m * dy + along * ny;
    x[i + 2] += m * dz + along * nz;
  }
}

/**
 * Area-weighted normals of the first `count` shaded vertices, whose normals and those of the other corners of their
 * triangles the caller has zeroed: the triangles' normals are added part by part (the even blocks with the odd ones,
 * then the even seams with the odd ones, as the orientation passes go), then the vertices' sums scaled to unit length.
 * With a `board`, this thread takes half `half` (0 or 1) of it and meets the other at each step; without, it takes
 * all. Each vertex gets the same sums in the same order either way.
 */
export function projectNormals(a: PartArrays, count: number, board: Int32Array | null, half: number): void {
  const out = a.normals;
  const parts = a.shadedTriangles.parts;
  const kernels = wasmKernels(a);
  if (board) {
    addFaces(a, kernels, parts[PART_EVEN + half], parts[PART_EVEN + half + 1]);
    meet(board);
    addFaces(a, kernels, parts[PART_EVEN_SEAM + half], parts[PART_EVEN_SEAM + half + 1]);
    meet(board);
  } else addFaces(a, kernels, 0, parts[PARTS]);
  const V = a.shadedVertices;
  const k0 = board && half === 1 ? count >> 1 : 0;
  const k1 = board && half === 0 ? count >> 1 : count;
  if (kernels) kernels.units(out.byteOffset, V.byteOffset, k0, k1);
  else for (let k = k0; k < k1; k++) normalize(out, 3 * V[k]);
}

/** The face normals of shaded triangles `t0..t1` added to their corners', by the kernel if any. */
function addFaces(a: PartArrays, kernels: WasmKernels | null, t0: number, t1: number): void {
  const corners = a.shadedTriangles.corners;
  if (kernels) kernels.faces(a.positions.byteOffset, corners.byteOffset, a.normals.byteOffset, t0, t1);
  else addFaceNormals(a.positions, corners, t0, t1, 1, a.normals);
}

/**
 * Collisions: a candidate vertex that was outside a collider at rest keeps its rest clearance. Half `half` (0 or 1)
 * of each collider's candidates, or all of them when `halves` is 1; each candidate moves only its own vertex.
 * `direction` is scratch (3 floats).
 */
export function projectCollisions(a: PartArrays, half: number, halves: number, direction: Float32Array): void {
  const x = a.positions;
  const list = a.activeCandidates;
  const start = a.activeCandidateStart;
  const shapes = a.colliderShapes;
  const kernels = a.collisionKernel && wasmKernels(a);
  for (let c = 0; c < a.colliders.length; c++) {
    const o = COLLIDER_SHAPE * c;
    let k0 = start[c];
    let k1 = start[c + 1];
    if (halves === 2) {
      const middle = (k0 + k1) >> 1;
      if (half === 0) k1 = middle;
      else k0 = middle;
    }
    if (kernels) {
      const vertices = a.colliderVertices.byteOffset;
      const shape = shapes.byteOffset + o * Float64Array.BYTES_PER_ELEMENT;
      kernels.collide(x.byteOffset, shape, list.byteOffset, vertices, a.colliderClearance.byteOffset, a.colliderSide.byteOffset, k0, k1);
      continue;
    }
    for (let k = k0; k < k1; k++) {
      const j = list[k];
      const i = 3 * a.colliderVertices[j];
      const d = shapeDistance(shapes, o, x[i], x[i + 1], x[i + 2], direction, a.colliderSide[j]);
      const push = a.colliderClearance[j] - d;
      if (push > 0) {
        x[i] += push * direction[0];
        x[i + 1] += push * direction[1];
        x[i + 2] += push * direction[2];
      }
    }
  }
}

/**
 * Bending (see SkinSolver.projectBending) of one part of the region's vertices in pass `pass` of a frame: keeps the
 * Laplacian of the normal displacement near its rest value. Each constraint moves a vertex and its ring, so the parts
 * that go at once (see constraint-lists.ts) share no vertex.
 */
export function projectBendingPart(a: PartArrays, pass: number, part: number): void {
  const x = a.positions;
  const kernels = wasmKernels(a);
  if (kernels) {
    const run = (pass === 0 ? 0 : PARTS + 1) + part;
    const runs = a.bending.runs;
    kernels.bend(
      x.byteOffset,
      a.restNormals.byteOffset,
      a.neighbourStart.byteOffset,
      a.neighbourOffsets.byteOffset,
      a.bendRest.byteOffset,
      a.bendGain.byteOffset,
      a.inverseDegree.byteOffset,
      a.bendPasses.byteOffset,
      a.bending.vertices.byteOffset,
      runs[run],
      runs[run + 1],
      pass,
    );
    return;
  }
  const N = a.restNormals;
  const start = a.neighbourStart;
  const nb = a.neighbourOffsets;
  const atRest = a.bendRest;
  const gain = a.bendGain;
  const inverse = a.inverseDegree;
  const passes = a.bendPasses;
  const list = a.bending.vertices;
  const run = (pass === 0 ? 0 : PARTS + 1) + part;
  const r1 = a.bending.runs[run + 1];
  for (let r = a.bending.runs[run]; r < r1; r++) {
    const v = list[r];
    const g = gain[v];
    if (passes[v] <= pass || g === 0) continue;
    const j0 = start[v];
    const j1 = start[v + 1];
    const i = 3 * v;
    const nx = N[i];
    const ny = N[i + 1];
    const nz = N[i + 2];
    // Mean normal displacement of the neighbours minus the vertex's own, along this vertex's rest normal: the
    // neighbours' mean height above the vertex now, less the same at rest.
    let mean = 0;
    for (let j = j0; j < j1; j++) {
      const k = nb[j];
      mean += x[k] * nx + x[k + 1] * ny + x[k + 2] * nz;
    }
    const w = inverse[v];
    const C = mean * w - (x[i] * nx + x[i + 1] * ny + x[i + 2] * nz) - atRest[v];
    // Gradient: -n at the vertex, n / degree at each neighbour; the gain holds the division by its squared norm.
    const lambda = g * C;
    x[i] += lambda * nx;
    x[i + 1] += lambda * ny;
    x[i + 2] += lambda * nz;
    const q = lambda * w;
    for (let j = j0; j < j1; j++) {
      const k = nb[j];
      x[k] -= q * nx;
      x[k + 1] -= q * ny;
      x[k + 2] -= q * nz;
    }
  }
}
