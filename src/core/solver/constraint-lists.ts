/**
 * Flat lists that the solver's per-frame loops walk, built once or when the muscle inputs change, never per frame:
 * vertex indices are stored already multiplied by 3 (the offset of x in an xyz array), so the loops neither multiply
 * nor look an index up twice, and each list holds only what its loop reads, in the order it reads it.
 *
 * Two threads can share a pass (see solver-partner.ts) when what each projects shares no vertex with the other's:
 * the edges of one colour can be split anywhere; the triangles are split in four parts by blocks of consecutive
 * vertices (see `vertexBlocks`): those within an even block, within an odd block, across the boundary of an even block
 * and the block before it, and across an odd block's. Triangles of an even and an odd part share no vertex, so the
 * even and the odd parts go at once, one pair after the other. A frame walks the parts in the same order on one
 * thread, so one thread and two give the same shape; the blocks do not depend on the active region, so neither does
 * the order. The vertices are in reverse Cuthill-McKee order (see topology.ts): the blocks are bands a few rings wide
 * across the mesh, so any moving patch spans many of them, about as many even as odd.
 */
import type { KernelMemory } from './kernel-memory';
import { allocate, type Memory } from './memory';
import type { SkinTopology } from './topology';

/** The constraints within even blocks, within odd ones, across the boundaries of even blocks and of odd ones. */
export const PART_EVEN = 0;
export const PART_ODD = 1;
export const PART_EVEN_SEAM = 2;
export const PART_ODD_SEAM = 3;
export const PARTS = 4;

/**
 * The length constraints, colour by colour as the topology orders them. Within a colour no two edges share a vertex,
 * so their order within the colour does not change the result: each colour lists first the edges no muscle holds (a
 * plain length projection), then the held ones (which also bulge when compressed), then the unfolding ones (free
 * edges that stretch without resistance up to their unfolded length, see SolverBuffers.unfoldedLengths), so that no
 * loop branches on the edge's kind.
 *
 * Each listed edge is one record of four 32-bit words, so that the loop reads one aligned stream: listed edge e has its
 * ends' xyz offsets (3 * vertex) at `ends[4e]` and `ends[4e + 1]`, its rest length at `rest[4e + 2]` and at
 * `rest[4e + 3]` the longest length it takes without resisting (its rest length if free, its unfolded length if
 * unfolding) or, if held, the larger muscle weight of its ends (two views of one buffer). The weight, with each
 * vertex's bulge direction (see PartArrays.bulgeDirections), replaces six floats an edge of precomputed pushes, whose
 * reading bound the held edges' loop (15.6 against 21.3 ns an edge in a loop test on the high head's smile).
 */
export interface EdgeLists {
  ends: Uint32Array;
  rest: Float32Array;
  /**
   * Colour c's free edges are `runs[3c]..runs[3c+1]`, its held edges `runs[3c+1]..runs[3c+2]`, its unfolding edges
   * `runs[3c+2]..runs[3c+3]`.
   */
  runs: Uint32Array;
  /**
   * Scratch while filling: the held edges of a colour from its start, the unfolding ones from its end (in the lists'
   * memory, so that posting the lists to a partner thread copies nothing).
   */
  readonly sorting: Uint32Array;
}

/** Edge kinds per colour in EdgeLists.runs: free, held, unfolding. */
export const EDGE_KINDS = 3;

/** Words per listed edge (see EdgeLists). */
export const EDGE_RECORD = 4;

/**
 * Edge lists with room for every edge of the topology; their records in `kernel` when it has room (the length kernels
 * read them there, see wasm-kernels.ts).
 */
export function createEdgeLists(topology: SkinTopology, memory: Memory = 'local', kernel: KernelMemory | null = null): EdgeLists {
  const m = topology.restLength.length;
  const colours = topology.colourStart.length - 1;
  const records = allocate(Uint32Array, EDGE_RECORD * m, memory, kernel);
  return {
    ends: records,
    rest: new Float32Array(records.buffer, records.byteOffset, records.length),
    runs: allocate(Uint32Array, EDGE_KINDS * colours + 1, memory),
    sorting: allocate(Uint32Array, m, memory),
  };
}

/**
 * Splits the vertices into blocks of consecutive vertices (returns each vertex's block) such that every constraint
 * lies within one block or across the boundary of two neighbouring ones, and no vertex is reached from two boundaries.
 * A vertex and its neighbours contain every edge and triangle at the vertex, so it suffices for these rings. Blocks
 * are made as short as that allows: about twice the vertex order's local bandwidth.
 */
export function vertexBlocks(topology: SkinTopology): Uint32Array {
  const n = topology.vertexCount;
  const start = topology.neighbourStart;
  const nb = topology.neighbours;
  // reach[b]: the highest vertex of a ring that starts below b; back[b]: the lowest vertex of a ring that ends at b or
  // above. A ring across boundary b lies within back[b]..reach[b].
  const reach = new Int32Array(n + 1).fill(-1);
  const back = new Int32Array(n + 1).fill(n);
  for (let v = 0; v < n; v++) {
    const lo = ringLow(v, start, nb);
    const hi = ringHigh(v, start, nb);
    if (hi > reach[lo + 1]) reach[lo + 1] = hi;
    if (lo < back[hi]) back[hi] = lo;
  }
  for (let b = 1; b <= n; b++) if (reach[b - 1] > reach[b]) reach[b] = reach[b - 1];
  for (let b = n - 1; b >= 0; b--) if (back[b + 1] < back[b]) back[b] = back[b + 1];
  const block = new Uint32Array(n);
  let boundary = 0;
  let index = 0;
  for (let b = 1; b < n; b++) {
    // The next boundary: the first whose rings all lie above the rings across the last one.
    if (back[b] > reach[boundary]) {
      boundary = b;
      index++;
    }
    block[b] = index;
  }
  return block;
}

/** The part of a constraint whose smallest and largest vertex are `lo` and `hi` (see vertexBlocks). */
function partOf(lo: number, hi: number, blocks: Uint32Array): number {
  const a = blocks[lo];
  const b = blocks[hi];
  return a === b ? (a & 1 ? PART_ODD : PART_EVEN) : b & 1 ? PART_ODD_SEAM : PART_EVEN_SEAM;
}

/**
 * Lists the edges with at least one end `included` (every edge when `included` is null), colour by colour: free edges,
 * held ones, unfolding ones. `weights` are the muscle weights along the surface; `unfolded` the length each edge may
 * reach before it resists stretching (the rest lengths by default: none unfolds). An unfolding edge unfolds even where
 * a muscle holds it (a closing lid's turn stretches the skin at its border most). Returns the number of listed edges.
 */
export function fillEdgeLists(
  into: EdgeLists,
  topology: SkinTopology,
  weights: Float32Array,
  included: Uint8Array | null,
  unfolded: Float32Array = topology.restLength,
): number {
  const E = topology.edges;
  const L = topology.restLength;
  const colourStart = topology.colourStart;
  const colours = colourStart.length - 1;
  const sorting = into.sorting;
  const end = sorting.length;
  let o = 0;
  // One walk over each colour: free edges are listed at once, held and unfolding ones set aside and listed after.
  for (let c = 0; c < colours; c++) {
    into.runs[EDGE_KINDS * c] = o;
    let held = 0;
    let unfolding = 0;
    for (let e = colourStart[c]; e < colourStart[c + 1]; e++) {
      const a = E[2 * e];
      const b = E[2 * e + 1];
      if (included !== null && included[a] === 0 && included[b] === 0) continue;
      if (unfolded[e] > L[e]) sorting[end - ++unfolding] = e;
      else if (weights[a] > 0 || weights[b] > 0) sorting[held++] = e;
      else o = listEdge(into, o, a, b, L[e], L[e]);
    }
    into.runs[EDGE_KINDS * c + 1] = o;
    for (let k = 0; k < held; k++) {
      const e = sorting[k];
      const a = E[2 * e];
      const b = E[2 * e + 1];
      o = listEdge(into, o, a, b, L[e], weights[a] > weights[b] ? weights[a] : weights[b]);
    }
    into.runs[EDGE_KINDS * c + 2] = o;
    for (let k = 1; k <= unfolding; k++) {
      const e = sorting[end - k];
      o = listEdge(into, o, E[2 * e], E[2 * e + 1], L[e], unfolded[e]);
    }
  }
  into.runs[EDGE_KINDS * colours] = o;
  return o;
}

/** Writes edge record `o` (see EdgeLists) and returns the next record's index. */
function listEdge(into: EdgeLists, o: number, a: number, b: number, rest: number, fourth: number): number {
  const r = EDGE_RECORD * o;
  into.ends[r] = 3 * a;
  into.ends[r + 1] = 3 * b;
  into.rest[r + 2] = rest;
  into.rest[r + 3] = fourth;
  return o + 1;
}

/** Triangles for the orientation constraints, part by part, in mesh order within a part. */
export interface TriangleLists {
  /** 3 * each corner's vertex, three per listed triangle. */
  corners: Uint32Array;
  /**
   * Per listed triangle: its rest unit normal and twice its least projected area (see `triangleFrames`); empty in lists
   * of corners alone.
   */
  frames: Float32Array;
  /** Part p is listed triangles `parts[p]..parts[p+1]`. */
  parts: Uint32Array;
  /** Scratch: the next free place of each part while filling. */
  readonly next: Uint32Array;
}

/**
 * Triangle lists with room for every triangle; their corners and frames in `kernel` when it has room. Without
 * `frames`, lists of corners alone (the normals' shaded triangles): their frames stay empty.
 */
export function createTriangleLists(
  topology: SkinTopology,
  memory: Memory = 'local',
  kernel: KernelMemory | null = null,
  frames = true,
): TriangleLists {
  const count = topology.triangles.length / 3;
  return {
    corners: allocate(Uint32Array, 3 * count, memory, kernel),
    frames: allocate(Float32Array, frames ? 4 * count : 0, memory, kernel),
    parts: allocate(Uint32Array, PARTS + 1, memory),
    next: new Uint32Array(PARTS),
  };
}

/**
 * Lists the triangles with at least one corner `included` (all when null), part by part (`blocks` from vertexBlocks),
 * in mesh order within a part; writes each triangle's place in the list into `places` (-1 if not listed) and returns
 * how many are listed.
 */
export function fillTriangleLists(
  into: TriangleLists,
  triangles: Uint32Array,
  frames: Float32Array,
  included: Uint8Array | null,
  places: Int32Array,
  blocks: Uint32Array,
): number {
  const count = triangles.length / 3;
  const C = into.corners;
  const F = into.frames;
  const parts = into.parts;
  parts.fill(0);
  // A counting sort, as for the edges; `places` holds each triangle's part in between.
  for (let t = 0; t < count; t++) {
    const a = triangles[3 * t];
    const b = triangles[3 * t + 1];
    const c = triangles[3 * t + 2];
    if (included !== null && included[a] === 0 && included[b] === 0 && included[c] === 0) {
      places[t] = -1;
      continue;
    }
    const lo = a < b ? (a < c ? a : c) : b < c ? b : c;
    const hi = a > b ? (a > c ? a : c) : b > c ? b : c;
    const p = partOf(lo, hi, blocks);
    places[t] = p;
    parts[p + 1]++;
  }
  for (let p = 0; p < PARTS; p++) parts[p + 1] += parts[p];
  const next = into.next;
  next.set(parts.subarray(0, PARTS));
  const withFrames = F.length > 0;
  for (let t = 0; t < count; t++) {
    const p = places[t];
    if (p < 0) continue;
    const o = next[p]++;
    places[t] = o;
    C[3 * o] = 3 * triangles[3 * t];
    C[3 * o + 1] = 3 * triangles[3 * t + 1];
    C[3 * o + 2] = 3 * triangles[3 * t + 2];
    if (!withFrames) continue;
    F[4 * o] = frames[4 * t];
    F[4 * o + 1] = frames[4 * t + 1];
    F[4 * o + 2] = frames[4 * t + 2];
    F[4 * o + 3] = frames[4 * t + 3];
  }
  return parts[PARTS];
}

/**
 * The bending constraints, one per vertex (the vertex and its ring of neighbours), part by part as the triangles
 * (see vertexBlocks), ascending within a part: first for a frame's first pass (the whole region), then for its later
 * passes (the region's vertices with more than one; see SkinSolver.setParameters).
 */
export interface BendingLists {
  vertices: Uint32Array;
  /** Part p of the first pass is `vertices[runs[p]..runs[p + 1]]`; of the later passes, at `PARTS + 1 + p`. */
  runs: Uint32Array;
}

/** Bending lists with room for every vertex's passes; the list in `kernel` when it has room (see wasm-kernels.ts). */
export function createBendingLists(vertexCount: number, memory: Memory = 'local', kernel: KernelMemory | null = null): BendingLists {
  return {
    vertices: allocate(Uint32Array, 2 * vertexCount, memory, kernel),
    runs: allocate(Uint32Array, 2 * (PARTS + 1), memory),
  };
}

/** Each vertex's bending part: the part of its ring (the vertex and its neighbours; see vertexBlocks). */
export function ringParts(topology: SkinTopology, blocks: Uint32Array): Uint8Array {
  const start = topology.neighbourStart;
  const nb = topology.neighbours;
  const out = new Uint8Array(topology.vertexCount);
  for (let v = 0; v < out.length; v++) out[v] = partOf(ringLow(v, start, nb), ringHigh(v, start, nb), blocks);
  return out;
}

/** The lowest vertex of vertex v's ring (v and its neighbours, CSR `start` / `nb`). */
function ringLow(v: number, start: Uint32Array, nb: Uint32Array): number {
  let lo = v;
  for (let j = start[v]; j < start[v + 1]; j++) if (nb[j] < lo) lo = nb[j];
  return lo;
}

/** The highest vertex of vertex v's ring. */
function ringHigh(v: number, start: Uint32Array, nb: Uint32Array): number {
  let hi = v;
  for (let j = start[v]; j < start[v + 1]; j++) if (nb[j] > hi) hi = nb[j];
  return hi;
}

/** Lists the region's vertices `V[0..count]` for bending, part by part (`part` from ringParts), as BendingLists says. */
export function fillBendingLists(into: BendingLists, V: Uint32Array, count: number, passes: Uint8Array, part: Uint8Array): void {
  let o = 0;
  for (let later = 0; later < 2; later++) {
    const base = later * (PARTS + 1);
    for (let p = 0; p < PARTS; p++) {
      into.runs[base + p] = o;
      for (let k = 0; k < count; k++) {
        const v = V[k];
        if (part[v] === p && (later === 0 || passes[v] > 1)) into.vertices[o++] = v;
      }
    }
    into.runs[base + PARTS] = o;
  }
}

/** The topology's neighbour lists with each neighbour stored as 3 * its vertex (same CSR starts). */
export function neighbourOffsets(topology: SkinTopology): Uint32Array {
  // A loop, not `Uint32Array.from` with a map function, which walks an iterator (90 ms on the high head).
  const nb = topology.neighbours;
  const out = new Uint32Array(nb.length);
  for (let j = 0; j < nb.length; j++) out[j] = 3 * nb[j];
  return out;
}
