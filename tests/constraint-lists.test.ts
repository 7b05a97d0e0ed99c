import { describe, expect, it } from 'vitest';
import {
  createEdgeLists,
  createTriangleLists,
  EDGE_RECORD,
  fillEdgeLists,
  fillTriangleLists,
  neighbourOffsets,
  PART_EVEN,
  PART_EVEN_SEAM,
  PART_ODD,
  PART_ODD_SEAM,
  PARTS,
  vertexBlocks,
} from '../src/core/solver/constraint-lists';
import { buildTopology } from '../src/core/solver/topology';
import { triangleGrid } from './fixtures/grids';

describe('constraint lists', () => {
  const g = triangleGrid(0.02, 0.01, 0.001);
  const t = buildTopology(g.positions, g.indices);
  const n = t.vertexCount;
  const weights = new Float32Array(n);
  for (let v = 0; v < n; v++) if (t.rest[3 * v] > 0.004) weights[v] = 0.25 + 0.5 * (v % 3 === 0 ? 1 : 0);
  const colours = t.colourStart.length - 1;
  const blocks = vertexBlocks(t);
  const ring = (v: number) => [v, ...t.neighbours.subarray(t.neighbourStart[v], t.neighbourStart[v + 1])];

  /** The part a constraint over these vertices belongs to: within an even or odd block, or across a boundary. */
  const partOf = (vertices: number[]) => {
    const lo = Math.min(...vertices.map((v) => blocks[v]));
    const hi = Math.max(...vertices.map((v) => blocks[v]));
    if (lo === hi) return lo % 2 === 0 ? PART_EVEN : PART_ODD;
    return hi % 2 === 0 ? PART_EVEN_SEAM : PART_ODD_SEAM;
  };

  it('split the vertices into blocks that no ring spans and no vertex crosses twice', () => {
    const count = blocks[n - 1] + 1;
    // Consecutive vertices, numbered in order from 0.
    for (let v = 1; v < n; v++) expect(blocks[v] - blocks[v - 1]).toBeGreaterThanOrEqual(0);
    for (let v = 1; v < n; v++) expect(blocks[v] - blocks[v - 1]).toBeLessThanOrEqual(1);
    expect(count).toBeGreaterThanOrEqual(4);
    // Each vertex is reached by rings across at most one boundary, and every ring lies in one block or two neighbours.
    const boundaryOf = new Int32Array(n).fill(-1);
    for (let v = 0; v < n; v++) {
      const r = ring(v).map((u) => blocks[u]);
      const lo = Math.min(...r);
      const hi = Math.max(...r);
      expect(hi - lo).toBeLessThanOrEqual(1);
      if (hi === lo) continue;
      for (const u of ring(v)) {
        if (boundaryOf[u] !== -1) expect(boundaryOf[u]).toBe(hi);
        boundaryOf[u] = hi;
      }
    }
  });

  /** The topology's edge index of each listed edge, in list order. */
  function listedEdges(included: Uint8Array | null, unfolded: Float32Array = t.restLength) {
    const lists = createEdgeLists(t);
    const count = fillEdgeLists(lists, t, weights, included, unfolded);
    const byEnds = new Map<string, number>();
    for (let e = 0; e < t.restLength.length; e++) byEnds.set(`${t.edges[2 * e]},${t.edges[2 * e + 1]}`, e);
    const order: number[] = [];
    for (let e = 0; e < count; e++) order.push(byEnds.get(`${lists.ends[EDGE_RECORD * e] / 3},${lists.ends[EDGE_RECORD * e + 1] / 3}`)!);
    return { lists, count, order };
  }
  const colourOf = (e: number) => {
    let c = 0;
    while (c < colours && t.colourStart[c + 1] <= e) c++;
    return c;
  };

  it('list every edge once, colour by colour, the free ones of each colour before the held ones', () => {
    const { lists, count, order } = listedEdges(null);
    expect(count).toBe(t.restLength.length);
    expect(new Set(order).size).toBe(count);
    expect(lists.runs[3 * colours]).toBe(count);
    let heldEdges = 0;
    for (let c = 0; c < colours; c++) {
      for (let k = lists.runs[3 * c]; k < lists.runs[3 * c + 2]; k++) {
        const e = order[k];
        const [a, b] = [t.edges[2 * e], t.edges[2 * e + 1]];
        expect(colourOf(e)).toBe(c);
        const held = Math.max(weights[a], weights[b]);
        expect(held > 0).toBe(k >= lists.runs[3 * c + 1]);
        expect(lists.rest[EDGE_RECORD * k + 2]).toBe(t.restLength[e]);
        // A held edge carries its larger muscle weight, which scales its bulge.
        if (held > 0) {
          heldEdges++;
          expect(lists.rest[EDGE_RECORD * k + 3]).toBe(Math.fround(held));
        }
      }
    }
    expect(heldEdges).toBeGreaterThan(0);
    expect(heldEdges).toBeLessThan(count);
  });

  it('list the unfolding edges last in their colour, held or not, with their unfolded length, and each in order', () => {
    // Edges whose lower end lies in the patch's upper half unfold to 1.5 times their length (held ones among them).
    const unfolded = t.restLength.slice();
    for (let e = 0; e < unfolded.length; e++)
      if (Math.min(t.rest[3 * t.edges[2 * e] + 1], t.rest[3 * t.edges[2 * e + 1] + 1]) > 0) unfolded[e] *= 1.5;
    const { lists, count, order } = listedEdges(null, unfolded);
    const plain = listedEdges(null).order;
    expect(count).toBe(t.restLength.length);
    expect(new Set(order).size).toBe(count);
    let unfolding = 0;
    let heldUnfolding = 0;
    for (let c = 0; c < colours; c++) {
      const listed = order.slice(lists.runs[3 * c], lists.runs[3 * c + 3]);
      for (let k = lists.runs[3 * c]; k < lists.runs[3 * c + 3]; k++) {
        const e = order[k];
        const grows = unfolded[e] > t.restLength[e];
        expect(grows).toBe(k >= lists.runs[3 * c + 2]);
        expect(lists.rest[EDGE_RECORD * k + 2]).toBe(t.restLength[e]);
        const heldEdge = Math.max(weights[t.edges[2 * e]], weights[t.edges[2 * e + 1]]) > 0;
        // A free edge takes up to its rest length without resisting.
        if (!grows && !heldEdge) expect(lists.rest[EDGE_RECORD * k + 3]).toBe(t.restLength[e]);
        if (grows) {
          unfolding++;
          if (Math.max(weights[t.edges[2 * e]], weights[t.edges[2 * e + 1]]) > 0) heldUnfolding++;
          expect(lists.rest[EDGE_RECORD * k + 3]).toBe(unfolded[e]);
        }
      }
      // Within each kind, the colour's own order: free, held and unfolding, each as the plain list has them.
      const kinds = (e: number) =>
        unfolded[e] > t.restLength[e] ? 2 : Math.max(weights[t.edges[2 * e]], weights[t.edges[2 * e + 1]]) > 0 ? 1 : 0;
      const inColour = plain.filter((e) => colourOf(e) === c);
      expect(listed).toEqual([0, 1, 2].flatMap((kind) => inColour.filter((e) => kinds(e) === kind).sort((p, q) => p - q)));
    }
    expect(unfolding).toBeGreaterThan(0);
    expect(heldUnfolding).toBeGreaterThan(0);
  });

  it('list only the edges and triangles with an included vertex, in the same order, the triangles part by part', () => {
    const included = new Uint8Array(n);
    for (let v = 0; v < n; v++) if (Math.hypot(t.rest[3 * v], t.rest[3 * v + 1]) < 0.003) included[v] = 1;
    const all = listedEdges(null).order;
    const some = listedEdges(included).order;
    const touches = (e: number) => included[t.edges[2 * e]] === 1 || included[t.edges[2 * e + 1]] === 1;
    expect(some.length).toBeGreaterThan(0);
    expect(some).toEqual(all.filter((e) => touches(e)).sort((p, q) => colourOf(p) - colourOf(q) || all.indexOf(p) - all.indexOf(q)));

    const frames = Float32Array.from({ length: (4 * t.triangles.length) / 3 }, (_, i) => i);
    const lists = createTriangleLists(t);
    const places = new Int32Array(t.triangles.length / 3);
    const count = fillTriangleLists(lists, t.triangles, frames, included, places, blocks);
    const listed: number[][] = [[], [], [], []];
    for (let k = 0; k < t.triangles.length / 3; k++) {
      const corners = [...t.triangles.subarray(3 * k, 3 * k + 3)];
      if (corners.some((v) => included[v])) listed[partOf(corners)].push(k);
      else expect(places[k]).toBe(-1);
    }
    const expected = listed.flat();
    expect(count).toBe(expected.length);
    expect([...lists.parts]).toEqual([0, 1, 2, 3, 4].map((p) => listed.slice(0, p).flat().length));
    // Every part has triangles, and the odd parts (a partner thread's) about as many as the even ones.
    const all3 = createTriangleLists(t);
    fillTriangleLists(all3, t.triangles, frames, null, new Int32Array(t.triangles.length / 3), blocks);
    const size = (p: number) => all3.parts[p + 1] - all3.parts[p];
    for (let p = 0; p < PARTS; p++) expect(size(p)).toBeGreaterThan(0);
    expect(size(PART_ODD) / size(PART_EVEN)).toBeGreaterThan(0.5);
    expect(size(PART_ODD) / size(PART_EVEN)).toBeLessThan(2);
    expected.forEach((k, o) => {
      expect(places[k]).toBe(o);
      expect([...lists.corners.subarray(3 * o, 3 * o + 3)]).toEqual([...t.triangles.subarray(3 * k, 3 * k + 3)].map((v) => 3 * v));
      expect([...lists.frames.subarray(4 * o, 4 * o + 4)]).toEqual([...frames.subarray(4 * k, 4 * k + 4)]);
    });
  });

  it('store neighbours as xyz offsets', () => {
    expect([...neighbourOffsets(t)]).toEqual([...t.neighbours].map((v) => 3 * v));
  });
});
