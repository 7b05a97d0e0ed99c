/** Length constraints (thesis 4.3.3) as part loops (see solver-kernels.ts): free edges, edges a muscle holds and unfolding edges. */
import { EDGE_KINDS, EDGE_RECORD } from './constraint-lists';
import type { KernelMemory } from './kernel-memory';
import { allocate, type Memory } from './memory';
import type { PartArrays } from './part-arrays';
import { meet } from './partner-board';
import { wasmKernels } from './wasm-kernels';
import type { SkinTopology } from './topology';

/**
 * Length constraints (thesis 4.3.3): restore each edge to its rest length, half the correction to each end. (As
 * printed, the correction's sign moves the ends the wrong way.) Edges go colour by colour: the free edges, then those
 * under a muscle, where a compressed edge also nudges its ends out along their rest normals. With a `board`, two
 * threads share the pass: this one projects half `half` (0 or 1) of each colour, and the two meet after each colour;
 * without, this thread projects every edge. Within a colour no two edges share a vertex, so the result is the same.
 * An edge between `1 - pretension` times its rest length and its rest length is left as it is (see
 * SkinParameters.pretension): shorter, it is pushed back to the lower end of that band.
 */
export function projectLengths(
  a: PartArrays,
  stiffness: number,
  bulge: number,
  pretension: number,
  board: Int32Array | null,
  half: number,
): void {
  const { ends, rest, runs } = a.edges;
  const x = a.positions;
  const K = EDGE_KINDS;
  const directions = a.bulgeDirections;
  const kernel = wasmKernels(a);
  for (let c = 0; K * c + K < runs.length; c++) {
    let f0 = runs[K * c];
    let f1 = runs[K * c + 1];
    let h0 = f1;
    let h1 = runs[K * c + 2];
    let u0 = h1;
    let u1 = runs[K * c + 3];
    if (board) {
      const f = (f0 + f1) >> 1;
      const h = (h0 + h1) >> 1;
      const u = (u0 + u1) >> 1;
      if (half === 0) {
        f1 = f;
        h1 = h;
        u1 = u;
      } else {
        f0 = f;
        h0 = h;
        u0 = u;
      }
    }
    if (pretension > 0) projectBandEdges(x, ends, rest, stiffness, 1 - pretension, f0, f1);
    else if (kernel) kernel.free(x.byteOffset, ends.byteOffset, 2 * stiffness, EDGE_RECORD * f0, EDGE_RECORD * f1);
    else projectFreeEdges(x, ends, rest, stiffness, f0, f1);
    if (kernel) {
      const r = EDGE_RECORD;
      kernel.held(x.byteOffset, ends.byteOffset, directions.byteOffset, 0.5 * stiffness, bulge, 1 - pretension, r * h0, r * h1);
    } else projectHeldEdges(x, ends, rest, directions, stiffness, bulge, 1 - pretension, h0, h1);
    if (u1 > u0) projectBandEdges(x, ends, rest, stiffness, 1 - pretension, u0, u1);
    if (board) meet(board);
  }
}

/**
 * Length projections of the edges `e0..e1` of an edge list that no muscle holds: each end moves half the length error
 * times `stiffness` along the edge. The share of the edge to remove, 1 - r / |d|, is taken without a square root:
 * with u = |d|² / r² it is 4 (u² - 1) / (5u² + 10u + 1), the [2/2] Padé approximant of 1 - 1 / sqrt(u) at rest
 * (within 0.5 % of it from 0.6 to 1.5 times the rest length, zero at the same length, no pole: rest lengths are
 * positive, as zero-area triangles are dropped). The loop is bound by the divider, which roots and divisions share;
 * cruder forms cost less but push compressed edges apart too little (docs/solver-notes.md, "Length projection").
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
 * projectFreeEdges with a band (a skin with pretension, or unfolding edges): the length aimed at is the edge's own
 * within the band from `slack` times its rest length to the length in its record's fourth word (its rest length for a
 * free edge, its unfolded length for an unfolding one, see EdgeLists), the band's nearer end outside it, a clamp of
 * |d|². Folded skin that opens (the upper lid's, as the lid closes) so lengthens without pulling on the skin beyond
 * it. A loop of its own: the clamp lengthens the path to the divider, and made every free edge 60 % slower (11 to 18
 * ns an edge in Node) where there is no band.
 */
function projectBandEdges(
  x: Float32Array,
  ends: Uint32Array,
  rest: Float32Array,
  stiffness: number,
  slack: number,
  e0: number,
  e1: number,
): void {
  const s2 = 2 * stiffness;
  const slack2 = slack * slack;
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
    const d2 = dx * dx + dy * dy + dz * dz;
    const r0 = rest[j + 2];
    const open = rest[j + 3];
    const r2 = Math.min(Math.max(d2, slack2 * r0 * r0), open * open);
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
 * Length projections of held edges `e0..e1`: as projectFreeEdges, with the exact length error, and an edge compressed
 * past its slack band pushes each end along its bulge direction (`directions`) by `bulge` times that compression times
 * the edge's muscle weight. (The compression would need a second division without the root, which saves nothing.)
 */
function projectHeldEdges(
  x: Float32Array,
  ends: Uint32Array,
  rest: Float32Array,
  directions: Float32Array,
  stiffness: number,
  bulge: number,
  slack: number,
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
    const r0 = rest[j + 2];
    // Stretched past the rest length, or compressed past the band's lower end (the other is 0); without branches that
    // half the edges take (compressed or stretched at random): (|e| + e) / 2 is max(0, e), (e - |e|) / 2 min(0, e).
    const over = len - r0;
    const under = len - slack * r0;
    const short = (under - Math.abs(under)) * 0.5;
    const error = (over + Math.abs(over)) * 0.5 + short;
    const k = (s * error) / len;
    // bulge * weight * the compression past the band.
    const push = -bulge * rest[j + 3] * short;
    x[ia] = ax + k * dx + push * directions[ia];
    x[ia + 1] = ay + k * dy + push * directions[ia + 1];
    x[ia + 2] = az + k * dz + push * directions[ia + 2];
    x[ib] = bx - k * dx + push * directions[ib];
    x[ib + 1] = by - k * dy + push * directions[ib + 1];
    x[ib + 2] = bz - k * dz + push * directions[ib + 2];
  }
}

/**
 * Each vertex's push per unit of compression of a held edge (see PartArrays.bulgeDirections): a fixed, deterministic
 * per-vertex seed in [-0.25, 0.75) along the rest normal. It breaks the symmetry of a flat compressed patch so it
 * buckles at the wavelength the skin prefers; its positive mean makes folds rise rather than sink. A larger mean lifts
 * the whole patch in one bulge instead of folding it.
 */
export function createBulgeDirections(topology: SkinTopology, memory: Memory, kernel: KernelMemory | null = null): Float32Array {
  const n = topology.vertexCount;
  const directions = allocate(Float32Array, 3 * n, memory, kernel);
  for (let v = 0; v < n; v++) {
    const seed = hash01(v) - 0.25;
    for (let k = 3 * v; k < 3 * v + 3; k++) directions[k] = seed * topology.restNormals[k];
  }
  return directions;
}

/** A fixed hash of an integer to [0, 1). */
function hash01(i: number): number {
  let h = Math.imul(i ^ 0x9e3779b9, 0x85ebca6b);
  h ^= h >>> 13;
  h = Math.imul(h, 0xc2b2ae35);
  h ^= h >>> 16;
  return (h >>> 0) / 4294967296;
}
