/**
 * The solver's heaviest loops as functions of one part of the constraint lists (see constraint-lists.ts): the leader
 * thread's SkinSolver and the partner thread's SolverPartner run the same code on the same shared arrays.
 */
import { COLLIDER_SHAPE, shapeDistance, type Collider } from './colliders';
import { EDGE_RECORD, PART_EVEN, PART_EVEN_SEAM, PARTS, type BendingLists, type EdgeLists, type TriangleLists } from './constraint-lists';
import { meet } from './partner-board';
import { addFaceNormals, normalize } from './topology';

/** What the part loops read and write: the solver's lists and positions, and the topology's fixed arrays. */
export interface PartArrays {
  /** Current positions, xyz per vertex. */
  positions: Float32Array;
  rest: Float32Array;
  restNormals: Float32Array;
  /** The muscle inputs (see SolverBuffers). */
  targets: Float32Array;
  weights: Float32Array;
  normalWeights: Float32Array;
  /** Current unit normals. */
  normals: Float32Array;
  /** The triangles with a corner in `shadedVertices`, part by part as the orientation's. */
  shadedTriangles: TriangleLists;
  /** The topology's neighbours (CSR), as xyz offsets (3 * vertex). */
  neighbourStart: Uint32Array;
  neighbourOffsets: Uint32Array;
  /** The topology's triangles of each vertex (CSR). */
  vertexTriangleStart: Uint32Array;
  vertexTriangles: Uint32Array;
  edges: EdgeLists;
  /**
   * Per vertex, at its xyz offset: the way a compressed held edge pushes it per unit of compression and of muscle
   * weight, its rest normal times its bulge seed (see SkinSolver).
   */
  bulgeDirections: Float32Array;
  triangles: TriangleLists;
  bending: BendingLists;
  /**
   * Per vertex: the bending constraint's value at rest, its step per unit of the constraint (its share per pass over
   * the gradient's squared norm, 1 + 1 / degree; 0 for none) and its passes (see SkinSolver), and 1 / its degree.
   */
  bendRest: Float64Array;
  bendGain: Float32Array;
  bendPasses: Uint8Array;
  inverseDegree: Float32Array;
  /**
   * For orientation passes that follow one another (see projectOrientationPart): 1 for each listed triangle with a
   * corner moved since it was last checked; and each triangle's place in the list (-1 if not listed).
   */
  unchecked: Uint8Array;
  /** The same flags four at a time (`unchecked`'s buffer, whose length is a multiple of 4): a zero word skips four. */
  uncheckedWords: Uint32Array;
  /** 1 for each watched listed triangle (see ORIENT_WATCH), and the same flags four at a time. */
  watched: Uint8Array;
  watchedWords: Uint32Array;
  listedTriangle: Int32Array;
  /** The active region's vertices, ascending (see ActiveRegion). */
  regionVertices: Uint32Array;
  /** The vertices whose normals a frame computes: the region and its ring (see ActiveRegion.shadedVertices). */
  shadedVertices: Uint32Array;
  /** Each vertex's place at the frame's start and its last frame's move (xyz), for the frame's bookkeeping. */
  previous: Float32Array;
  lastStep: Float32Array;
  /** Share of its solved move each vertex takes this frame (see relaxPart). */
  relaxation: Float32Array;
  /** 1 for a vertex whose last move turned back on the one before: it carries no momentum into the next frame. */
  restart: Uint8Array;
  /** Frames since each vertex last turned back, up to 255 (see relaxPart). */
  calm: Uint8Array;
  /** Each vertex's way (the sum of its moves) since the loop window began (see SkinSolver.breakLoops). */
  path: Float32Array;
  /**
   * The colliders, and their current shapes (`COLLIDER_SHAPE` values each), which the leader updates when an input
   * moves one; the collision loop reads only the shapes, so the partner's copies of the colliders need not follow.
   */
  colliders: Collider[];
  colliderShapes: Float64Array;
  /** Collision candidates: vertex, rest clearance and side of each (see SkinSolver.collisionCandidates). */
  colliderVertices: Uint32Array;
  colliderClearance: Float32Array;
  colliderSide: Int8Array;
  /** The candidates a frame checks, collider by collider: `activeCandidates[activeCandidateStart[c]..[c + 1]]`. */
  activeCandidates: Uint32Array;
  activeCandidateStart: Uint32Array;
}

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
  const x = a.positions;
  const out = a.normals;
  const { corners, parts } = a.shadedTriangles;
  if (board) {
    addFaceNormals(x, corners, parts[PART_EVEN + half], parts[PART_EVEN + half + 1], 1, out);
    meet(board);
    addFaceNormals(x, corners, parts[PART_EVEN_SEAM + half], parts[PART_EVEN_SEAM + half + 1], 1, out);
    meet(board);
  } else addFaceNormals(x, corners, 0, parts[PARTS], 1, out);
  const V = a.shadedVertices;
  const k0 = board && half === 1 ? count >> 1 : 0;
  const k1 = board && half === 0 ? count >> 1 : count;
  for (let k = k0; k < k1; k++) normalize(out, 3 * V[k]);
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
  for (let c = 0; c < a.colliders.length; c++) {
    const o = COLLIDER_SHAPE * c;
    let k0 = start[c];
    let k1 = start[c + 1];
    if (halves === 2) {
      const middle = (k0 + k1) >> 1;
      if (half === 0) k1 = middle;
      else k0 = middle;
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
 * Length constraints (thesis 4.3.3): restore each edge to its rest length, half the correction to each end. (As
 * printed, the correction's sign moves the ends the wrong way.) Edges go colour by colour: the free edges, then those
 * under a muscle, where a compressed edge also nudges its ends out along their rest normals. With a `board`, two
 * threads share the pass: this one projects half `half` (0 or 1) of each colour, and the two meet after each colour;
 * without, this thread projects every edge. Within a colour no two edges share a vertex, so the result is the same.
 */
export function projectLengths(a: PartArrays, stiffness: number, bulge: number, board: Int32Array | null, half: number): void {
  const { ends, rest, runs } = a.edges;
  const x = a.positions;
  for (let c = 0; 2 * c + 2 < runs.length; c++) {
    let f0 = runs[2 * c];
    let f1 = runs[2 * c + 1];
    let h0 = f1;
    let h1 = runs[2 * c + 2];
    if (board) {
      const f = (f0 + f1) >> 1;
      const h = (h0 + h1) >> 1;
      if (half === 0) {
        f1 = f;
        h1 = h;
      } else {
        f0 = f;
        h0 = h;
      }
    }
    projectFreeEdges(x, ends, rest, stiffness, f0, f1);
    projectHeldEdges(x, ends, rest, a.bulgeDirections, stiffness, bulge, h0, h1);
    if (board) meet(board);
  }
}

/**
 * Length projections of the edges `e0..e1` of an edge list that no muscle holds: each end moves half the length error
 * times `stiffness` along the edge. The share of the edge to remove, 1 - r / |d|, is taken without a square root:
 * with u = |d|² / r² it is 4 (u² - 1) / (5u² + 10u + 1), the [2/2] Padé approximant of 1 - 1 / sqrt(u) at rest
 * (within 0.5 % of it from 0.6 to 1.5 times the rest length, zero at the same length, no pole: rest lengths are
 * positive, as zero-area triangles are dropped). The loop is bound by the divider, which roots and divisions share:
 * 11.5 ns an edge instead of 12.1 in a loop test. Cruder forms cost less but changed the physics: Jakobsen's
 * (u - 1) / (u + 1) (10.5 ns) pushes compressed edges apart too little and left the low head's lips creeping for
 * 600 frames after AU26.
 */
function projectFreeEdges(x: Float32Array, ends: Uint32Array, rest: Float32Array, stiffness: number, e0: number, e1: number): void {
  const s2 = 2 * stiffness; // half of it, times the approximant's 4
  // The record size read once into a local: an imported binding in the loop's test slowed the partner thread's
  // copy of this loop threefold under Node's module loader.
  const r = EDGE_RECORD;
  const j1 = r * e1;
  for (let j = r * e0; j < j1; j += r) {
    const ia = ends[j];
    const ib = ends[j + 1];
    const ax = x[ia],
      ay = x[ia + 1],
      az = x[ia + 2];
    const bx = x[ib],
      by = x[ib + 1],
      bz = x[ib + 2];
    const dx = bx - ax;
    const dy = by - ay;
    const dz = bz - az;
    const d2 = dx * dx + dy * dy + dz * dz;
    const r0 = rest[j + 2];
    const r2 = r0 * r0;
    const k = (s2 * (d2 * d2 - r2 * r2)) / (5 * d2 * d2 + 10 * d2 * r2 + r2 * r2);
    x[ia] = ax + k * dx;
    x[ia + 1] = ay + k * dy;
    x[ia + 2] = az + k * dz;
    x[ib] = bx - k * dx;
    x[ib + 1] = by - k * dy;
    x[ib + 2] = bz - k * dz;
  }
}

/**
 * Length projections of held edges `e0..e1`: as projectFreeEdges, with the exact length error, and a compressed edge
 * pushes each end along its bulge direction (`directions`) by `bulge` times its compression times the edge's muscle
 * weight. (The compression would need a second division without the root, which saves nothing.)
 */
function projectHeldEdges(
  x: Float32Array,
  ends: Uint32Array,
  rest: Float32Array,
  directions: Float32Array,
  stiffness: number,
  bulge: number,
  e0: number,
  e1: number,
): void {
  const s = 0.5 * stiffness;
  const r = EDGE_RECORD; // read once, as in projectFreeEdges
  const j1 = r * e1;
  for (let j = r * e0; j < j1; j += r) {
    const ia = ends[j];
    const ib = ends[j + 1];
    const ax = x[ia],
      ay = x[ia + 1],
      az = x[ia + 2];
    const bx = x[ib],
      by = x[ib + 1],
      bz = x[ib + 2];
    const dx = bx - ax;
    const dy = by - ay;
    const dz = bz - az;
    const len = Math.sqrt(dx * dx + dy * dy + dz * dz);
    if (len === 0) continue;
    const error = len - rest[j + 2];
    const k = (s * error) / len;
    // bulge * weight * max(0, -error), without a branch that half the edges take (compressed or stretched at random):
    // (|error| - error) / 2 is exactly -error or 0.
    const push = bulge * rest[j + 3] * ((Math.abs(error) - error) * 0.5);
    x[ia] = ax + k * dx + push * directions[ia];
    x[ia + 1] = ay + k * dy + push * directions[ia + 1];
    x[ia + 2] = az + k * dz + push * directions[ia + 2];
    x[ib] = bx - k * dx + push * directions[ib];
    x[ib + 1] = by - k * dy + push * directions[ib + 1];
    x[ib + 2] = bz - k * dz + push * directions[ib + 2];
  }
}

/**
 * Orientation of one part's triangles: each triangle's area projected on its rest normal stays above a fraction of
 * its rest area, so compressed skin folds (the triangle tilts) instead of crumpling flat (the triangle turns over
 * within the surface), which no length constraint can tell from the right shape. The projected area is linear in each
 * corner, so one projection restores the bound exactly; the corrections lie in the rest tangent plane.
 *
 * `mode` is ORIENT_FULL, ORIENT_AGAIN or ORIENT_WATCHED. ORIENT_AGAIN says that nothing but the previous orientation
 * pass moved the skin since: a triangle found within its bound then, none of whose corners moved since, still is and
 * is skipped, with the same result as checking it. `floor` scales the bound (see ORIENTATION_SHOWN_FLOOR in solver.ts). Returns whether a
 * triangle was more than a hair
 * under its bound.
 */
export function projectOrientationPart(a: PartArrays, part: number, mode: number, floor = 1): boolean {
  const x = a.positions;
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

/**
 * Bending (see SkinSolver.projectBending) of one part of the region's vertices in pass `pass` of a frame: keeps the
 * Laplacian of the normal displacement near its rest value. Each constraint moves a vertex and its ring, so the parts
 * that go at once (see constraint-lists.ts) share no vertex.
 */
export function projectBendingPart(a: PartArrays, pass: number, part: number): void {
  const x = a.positions;
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
