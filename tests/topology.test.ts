import { describe, expect, it } from 'vitest';
import { buildTopology, computeNormals, describeTopology } from '../src/core/solver/topology';
import { triangleGrid } from './fixtures/grids';

/** A 3 x 3 grid split into two UV islands along its middle column: the seam vertices appear twice. */
function seamedGrid() {
  const g = triangleGrid(0.004, 0.004, 0.002);
  // Duplicate the vertices of column 1 (x = 0) and let the right half's triangles use the copies.
  const positions = Array.from(g.positions);
  const copyOf = new Map<number, number>();
  for (let j = 0; j < g.ny; j++) {
    const v = j * g.nx + 1;
    copyOf.set(v, positions.length / 3);
    positions.push(g.positions[3 * v], g.positions[3 * v + 1], g.positions[3 * v + 2]);
  }
  const indices = Array.from(g.indices);
  for (let t = 0; t < indices.length; t += 3) {
    const tri = indices.slice(t, t + 3);
    const right = tri.some((v) => v % g.nx === 2);
    if (right) for (let k = 0; k < 3; k++) indices[t + k] = copyOf.get(tri[k]) ?? tri[k];
  }
  return { positions: Float32Array.from(positions), indices: Uint32Array.from(indices), copyOf };
}

describe('skin topology', () => {
  it('welds vertices that share a position, so a UV seam is one surface', () => {
    const { positions, indices, copyOf } = seamedGrid();
    const t = buildTopology(positions, indices);
    expect(t.vertexCount).toBe(9);
    expect(t.report.weldedDuplicates).toBe(3);
    for (const [v, copy] of copyOf) expect(t.renderToSim[copy]).toBe(t.renderToSim[v]);
    // Welded, the grid has the edges of one 3 x 3 grid: 12 sides and 4 diagonals.
    expect(t.restLength.length).toBe(16);
  });

  it('gives seam vertices one normal: no shading seam', () => {
    const { positions, indices } = seamedGrid();
    const t = buildTopology(positions, indices);
    for (let v = 0; v < t.vertexCount; v++) expect(t.restNormals[3 * v + 2]).toBeCloseTo(1, 6);
  });

  it('colours edges so that no two edges of a colour share a vertex, and lists every edge once', () => {
    const g = triangleGrid(0.03, 0.02, 0.002, 0.05);
    const t = buildTopology(g.positions, g.indices);
    const seen = new Set<string>();
    for (let c = 0; c + 1 < t.colourStart.length; c++) {
      const used = new Set<number>();
      for (let e = t.colourStart[c]; e < t.colourStart[c + 1]; e++) {
        const a = t.edges[2 * e];
        const b = t.edges[2 * e + 1];
        expect(used.has(a) || used.has(b)).toBe(false);
        used.add(a);
        used.add(b);
        seen.add(a < b ? `${a},${b}` : `${b},${a}`);
      }
    }
    expect(seen.size).toBe(t.restLength.length);
    // A grid of (nx x ny) vertices with one diagonal per cell has nx(ny-1) + ny(nx-1) + (nx-1)(ny-1) edges.
    expect(t.restLength.length).toBe(g.nx * (g.ny - 1) + g.ny * (g.nx - 1) + (g.nx - 1) * (g.ny - 1));
    // Greedy colouring needs at most 2 * (max degree) - 1 colours; degree is at most 6 on this grid.
    expect(t.colourStart.length - 1).toBeLessThanOrEqual(11);
  });

  it('keeps consistent incidence: each triangle is listed at each of its vertices', () => {
    const g = triangleGrid(0.01, 0.01, 0.002);
    const t = buildTopology(g.positions, g.indices);
    for (let v = 0; v < t.vertexCount; v++) {
      for (let k = t.vertexTriangleStart[v]; k < t.vertexTriangleStart[v + 1]; k++) {
        const tri = t.vertexTriangles[k];
        expect(Array.from(t.triangles.subarray(3 * tri, 3 * tri + 3))).toContain(v);
      }
    }
    expect(t.vertexTriangleStart[t.vertexCount]).toBe(t.triangles.length);
  });

  it('orders vertices so that neighbours sit close in memory (reverse Cuthill-McKee)', () => {
    // A 41 x 41 grid given in a shuffled order: bandwidth (max index distance along an edge) must drop to about a row.
    const g = triangleGrid(0.08, 0.08, 0.002);
    const n = g.positions.length / 3;
    const perm = Array.from({ length: n }, (_, i) => i);
    let s = 12345;
    for (let i = n - 1; i > 0; i--) {
      s = (s * 1103515245 + 12345) & 0x7fffffff;
      const j = s % (i + 1);
      [perm[i], perm[j]] = [perm[j], perm[i]];
    }
    const shuffled = new Float32Array(3 * n);
    perm.forEach((p, i) => shuffled.set(g.positions.subarray(3 * p, 3 * p + 3), 3 * i));
    const inv = new Uint32Array(n);
    perm.forEach((p, i) => (inv[p] = i));
    const t = buildTopology(
      shuffled,
      Uint32Array.from(g.indices, (v) => inv[v]),
    );
    let bandwidth = 0;
    for (let e = 0; e < t.restLength.length; e++) bandwidth = Math.max(bandwidth, Math.abs(t.edges[2 * e] - t.edges[2 * e + 1]));
    expect(bandwidth).toBeLessThanOrEqual(2 * g.nx + 2);
  });

  it('skips degenerate, duplicate and non-manifold triangles and counts them and the isolated vertices', () => {
    const g = triangleGrid(0.004, 0.004, 0.002);
    const positions = Float32Array.from([...g.positions, 1, 1, 1, 0.001, 0.001, 0.05]);
    const extraIsolated = g.positions.length / 3;
    const apex = extraIsolated + 1;
    const [a, b, c] = Array.from(g.indices.subarray(0, 3));
    const indices = Uint32Array.from([
      ...g.indices,
      a,
      a,
      b, // repeated vertex
      a,
      b,
      c, // duplicate of the first triangle
      a,
      c,
      apex, // a third triangle on the cell's diagonal a-c, which has two already: non-manifold
    ]);
    const t = buildTopology(positions, indices);
    expect(t.report).toMatchObject({ degenerateTriangles: 1, duplicateTriangles: 1, nonManifoldTriangles: 1, isolatedVertices: 2 });
    expect(t.triangles.length).toBe(g.indices.length);
    for (const x of t.restNormals) expect(Number.isFinite(x)).toBe(true);
    expect(describeTopology(t)).toContain(
      'skipped: 1 degenerate triangles, 1 duplicate triangles, 1 triangles on non-manifold edges, 2 isolated vertices (kept still)',
    );
  });

  it('names a non-finite coordinate or an index out of range', () => {
    expect(() => buildTopology([0, 0, 0, 1, 0, 0, 0, NaN, 0], [0, 1, 2])).toThrow('vertex 2 has a non-finite coordinate (NaN)');
    expect(() => buildTopology([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 3])).toThrow('index 2 is 3, outside the 3 vertices');
  });
});

describe('vertex normals', () => {
  it('are the sphere normals on a sphere, area-weighted per welded vertex', () => {
    // An octahedron subdivided four times and pushed onto the unit sphere.
    const { positions, indices } = icosphere(4);
    const t = buildTopology(positions, indices);
    const out = new Float32Array(3 * t.vertexCount);
    computeNormals(t.rest, t.triangles, out);
    let worst = 0;
    for (let v = 0; v < t.vertexCount; v++) {
      const dot = out[3 * v] * t.rest[3 * v] + out[3 * v + 1] * t.rest[3 * v + 1] + out[3 * v + 2] * t.rest[3 * v + 2];
      worst = Math.max(worst, 1 - dot);
    }
    expect(worst).toBeLessThan(1e-3);
  });
});

/** An octahedron subdivided `levels` times with every vertex projected onto the unit sphere. */
function icosphere(levels: number) {
  let P: number[][] = [
    [1, 0, 0],
    [-1, 0, 0],
    [0, 1, 0],
    [0, -1, 0],
    [0, 0, 1],
    [0, 0, -1],
  ];
  let T: number[][] = [
    [0, 2, 4],
    [2, 1, 4],
    [1, 3, 4],
    [3, 0, 4],
    [2, 0, 5],
    [1, 2, 5],
    [3, 1, 5],
    [0, 3, 5],
  ];
  for (let l = 0; l < levels; l++) {
    const mid = new Map<string, number>();
    const m = (a: number, b: number) => {
      const k = a < b ? `${a},${b}` : `${b},${a}`;
      if (!mid.has(k)) {
        const p = [0, 1, 2].map((i) => (P[a][i] + P[b][i]) / 2);
        const len = Math.hypot(p[0], p[1], p[2]);
        P.push(p.map((x) => x / len));
        mid.set(k, P.length - 1);
      }
      return mid.get(k)!;
    };
    T = T.flatMap(([a, b, c]) => {
      const [ab, bc, ca] = [m(a, b), m(b, c), m(c, a)];
      return [
        [a, ab, ca],
        [ab, b, bc],
        [ca, bc, c],
        [ab, bc, ca],
      ];
    });
    P = P.slice();
  }
  return { positions: Float32Array.from(P.flat()), indices: Uint32Array.from(T.flat()) };
}
