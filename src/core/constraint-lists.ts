/**
 * Flat lists that the solver's per-frame loops walk, built once or when the muscle inputs change, never per frame:
 * vertex indices are stored already multiplied by 3 (the offset of x in an xyz array), so the loops neither multiply
 * nor look an index up twice, and each list holds only what its loop reads, in the order it reads it.
 */
import type { SkinTopology } from './topology';

/**
 * The length constraints, colour by colour as the topology orders them. Within a colour no two edges share a vertex,
 * so their order within the colour does not change the result: each colour lists first the edges no muscle holds
 * (a plain length projection), then the held ones (which also bulge when compressed), so that neither loop branches
 * on the muscle weight.
 *
 * Each listed edge is one record of three 32-bit words, so that the loop reads one stream: listed edge e has its ends'
 * xyz offsets (3 * vertex) at `ends[3e]` and `ends[3e + 1]`, and its rest length at `rest[3e + 2]` (two views of one
 * buffer).
 */
export interface EdgeLists {
  ends: Uint32Array;
  rest: Float32Array;
  /**
   * Three per listed edge, read only for the held edges: the larger muscle weight of the two ends, then each end's
   * bulge seed (see SkinSolver).
   */
  held: Float32Array;
  /** Colour c's free edges are `runs[2c]..runs[2c+1]`, its held edges `runs[2c+1]..runs[2c+2]`. */
  runs: Uint32Array;
}

/** Edge lists with room for every edge of the topology. */
export function createEdgeLists(topology: SkinTopology): EdgeLists {
  const m = topology.restLength.length;
  const colours = topology.colourStart.length - 1;
  const buffer = new ArrayBuffer(12 * m);
  return { ends: new Uint32Array(buffer), rest: new Float32Array(buffer), held: new Float32Array(3 * m), runs: new Uint32Array(2 * colours + 1) };
}

/**
 * Lists the edges with at least one end `included` (every edge when `included` is null), colour by colour, free edges
 * before held ones. `weights` are the muscle weights along the surface, `seed` the per-vertex bulge seeds. Returns the
 * number of listed edges.
 */
export function fillEdgeLists(into: EdgeLists, topology: SkinTopology, weights: Float32Array, seed: Float32Array, included: Uint8Array | null): number {
  const E = topology.edges;
  const L = topology.restLength;
  const colourStart = topology.colourStart;
  const colours = colourStart.length - 1;
  let o = 0;
  for (let c = 0; c < colours; c++) {
    into.runs[2 * c] = o;
    for (let pass = 0; pass < 2; pass++) {
      if (pass === 1) into.runs[2 * c + 1] = o;
      for (let e = colourStart[c]; e < colourStart[c + 1]; e++) {
        const a = E[2 * e];
        const b = E[2 * e + 1];
        if (included !== null && included[a] === 0 && included[b] === 0) continue;
        const held = weights[a] > weights[b] ? weights[a] : weights[b];
        if (held > 0 !== (pass === 1)) continue;
        into.ends[3 * o] = 3 * a;
        into.ends[3 * o + 1] = 3 * b;
        into.rest[3 * o + 2] = L[e];
        into.held[3 * o] = held;
        into.held[3 * o + 1] = seed[a];
        into.held[3 * o + 2] = seed[b];
        o++;
      }
    }
  }
  into.runs[2 * colours] = o;
  return o;
}

/** Triangles for the orientation constraints, in mesh order. */
export interface TriangleLists {
  /** 3 * each corner's vertex, three per listed triangle. */
  corners: Uint32Array;
  /** Per listed triangle: its rest unit normal and twice its least projected area (see `triangleFrames`). */
  frames: Float32Array;
}

export function createTriangleLists(topology: SkinTopology): TriangleLists {
  const count = topology.triangles.length / 3;
  return { corners: new Uint32Array(3 * count), frames: new Float32Array(4 * count) };
}

/**
 * Lists the triangles with at least one corner `included` (all when null), in mesh order; returns how many. With
 * `places`, writes each triangle's place in the list there (-1 if not listed).
 */
export function fillTriangleLists(into: TriangleLists, triangles: Uint32Array, frames: Float32Array, included: Uint8Array | null, places?: Int32Array): number {
  const count = triangles.length / 3;
  const C = into.corners;
  const F = into.frames;
  let o = 0;
  for (let t = 0; t < count; t++) {
    const a = triangles[3 * t];
    const b = triangles[3 * t + 1];
    const c = triangles[3 * t + 2];
    if (included !== null && included[a] === 0 && included[b] === 0 && included[c] === 0) {
      if (places) places[t] = -1;
      continue;
    }
    if (places) places[t] = o;
    C[3 * o] = 3 * a;
    C[3 * o + 1] = 3 * b;
    C[3 * o + 2] = 3 * c;
    F[4 * o] = frames[4 * t];
    F[4 * o + 1] = frames[4 * t + 1];
    F[4 * o + 2] = frames[4 * t + 2];
    F[4 * o + 3] = frames[4 * t + 3];
    o++;
  }
  return o;
}

/** The topology's neighbour lists with each neighbour stored as 3 * its vertex (same CSR starts). */
export function neighbourOffsets(topology: SkinTopology): Uint32Array {
  return Uint32Array.from(topology.neighbours, (v) => 3 * v);
}
