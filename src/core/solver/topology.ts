/**
 * Skin topology: the welded simulation mesh behind a render mesh (thesis 4.3.1, "simulation vertices").
 * Pure data, no three.js: runs in Node, on the main thread and in the worker.
 */
import { VertexKeyCounts } from './vertex-key-counts';

/** What was left out of an input mesh, and why. */
export interface TopologyReport {
  /** Render vertices merged into another with the same position (UV seams). */
  weldedDuplicates: number;
  /** Triangles with a repeated vertex or zero area. */
  degenerateTriangles: number;
  /** Triangles that repeat another's three vertices. */
  duplicateTriangles: number;
  /** Triangles dropped because an edge already had two triangles. */
  nonManifoldTriangles: number;
  /** Simulation vertices used by no triangle (kept still). */
  isolatedVertices: number;
}

/** The welded skin: vertices in a cache-friendly order, edges grouped by colour, and adjacency in CSR form. */
export interface SkinTopology {
  vertexCount: number;
  /** Rest positions, xyz per simulation vertex. */
  rest: Float32Array;
  /** Triangles over simulation vertices, counter-clockwise from outside. */
  triangles: Uint32Array;
  /** Simulation vertex of each render vertex (several render vertices share one along UV seams). */
  renderToSim: Uint32Array;
  /** Edge end points, two per edge, ordered colour by colour. */
  edges: Uint32Array;
  /** Rest length of each edge. */
  restLength: Float32Array;
  /** Edges of colour c are `colourStart[c]..colourStart[c+1]`; no two edges of a colour share a vertex. */
  colourStart: Uint32Array;
  /** Triangles of vertex v are `vertexTriangles[vertexTriangleStart[v]..vertexTriangleStart[v+1]]`. */
  vertexTriangleStart: Uint32Array;
  vertexTriangles: Uint32Array;
  /** Edge-neighbours of vertex v, CSR like the triangles. */
  neighbourStart: Uint32Array;
  neighbours: Uint32Array;
  /** Area-weighted unit normals at rest. */
  restNormals: Float32Array;
  /** The rest spacing of the mesh at each vertex across its finest direction (see finestSpacing). */
  spacing: Float32Array;
  /** Diagonal of the rest bounding box: the mesh size that tolerances are relative to. */
  size: number;
  report: TopologyReport;
}

/** One line for the log: the skin's size and what was merged or skipped building it. */
export function describeTopology(t: SkinTopology): string {
  const r = t.report;
  const skipped = [
    [r.degenerateTriangles, 'degenerate triangles'],
    [r.duplicateTriangles, 'duplicate triangles'],
    [r.nonManifoldTriangles, 'triangles on non-manifold edges'],
    [r.isolatedVertices, 'isolated vertices (kept still)'],
  ]
    .filter(([n]) => (n as number) > 0)
    .map(([n, what]) => `${n} ${what}`);
  return (
    `skin: ${t.vertexCount} vertices (${r.weldedDuplicates} seam duplicates welded), ${t.restLength.length} edges in ` +
    `${t.colourStart.length - 1} colours, ${t.triangles.length / 3} triangles; skipped: ${skipped.length ? skipped.join(', ') : 'nothing'}`
  );
}

/** Builds the simulation topology of an indexed triangle mesh. Bad triangles are skipped and counted in `report`. */
export function buildTopology(renderPositions: ArrayLike<number>, indices: ArrayLike<number>): SkinTopology {
  const renderCount = Math.floor(renderPositions.length / 3);
  for (let i = 0; i < renderCount * 3; i++) {
    if (!Number.isFinite(renderPositions[i]))
      throw new Error(`vertex ${Math.floor(i / 3)} has a non-finite coordinate (${renderPositions[i]})`);
  }
  for (let i = 0; i < indices.length; i++) {
    const v = indices[i];
    if (!Number.isInteger(v) || v < 0 || v >= renderCount) throw new Error(`index ${i} is ${v}, outside the ${renderCount} vertices`);
  }

  // 1. Weld render vertices that share a position exactly (UV seams), in first-seen order: found by sorting them by
  // position, not by a string of their coordinates per vertex (docs/page-notes.md, "Building the skin").
  const byPosition = Array.from({ length: renderCount }, (_, r) => r).sort(
    (p, q) =>
      renderPositions[3 * p] - renderPositions[3 * q] ||
      renderPositions[3 * p + 1] - renderPositions[3 * q + 1] ||
      renderPositions[3 * p + 2] - renderPositions[3 * q + 2] ||
      p - q,
  );
  // Each render vertex's first-seen twin (itself if it is the first at its position).
  const firstAt = new Uint32Array(renderCount);
  for (let k = 0; k < renderCount; k++) {
    const r = byPosition[k];
    const before = k > 0 ? byPosition[k - 1] : -1;
    const same =
      before >= 0 &&
      renderPositions[3 * r] === renderPositions[3 * before] &&
      renderPositions[3 * r + 1] === renderPositions[3 * before + 1] &&
      renderPositions[3 * r + 2] === renderPositions[3 * before + 2];
    firstAt[r] = same ? firstAt[before] : r;
  }
  const weldOf = new Uint32Array(renderCount);
  const weldedPositions: number[] = [];
  for (let r = 0; r < renderCount; r++) {
    if (firstAt[r] === r) {
      weldOf[r] = weldedPositions.length / 3;
      weldedPositions.push(renderPositions[3 * r], renderPositions[3 * r + 1], renderPositions[3 * r + 2]);
    } else weldOf[r] = weldOf[firstAt[r]];
  }
  const weldedCount = weldedPositions.length / 3;

  // 2. Keep the triangles that are sound: no repeated vertex, non-zero area, not a repeat, at most two per edge.
  const report: TopologyReport = {
    weldedDuplicates: renderCount - weldedCount,
    degenerateTriangles: 0,
    duplicateTriangles: 0,
    nonManifoldTriangles: 0,
    isolatedVertices: 0,
  };
  const triangleCount = Math.floor(indices.length / 3);
  const seenTriangles = new VertexKeyCounts(triangleCount);
  const edgeUse = new VertexKeyCounts(3 * triangleCount);
  const kept: number[] = [];
  const P = weldedPositions;
  for (let t = 0; t + 2 < indices.length; t += 3) {
    const a = weldOf[indices[t]];
    const b = weldOf[indices[t + 1]];
    const c = weldOf[indices[t + 2]];
    if (a === b || b === c || a === c || triangleArea2(P, a, b, c) === 0) {
      report.degenerateTriangles++;
      continue;
    }
    const lo = Math.min(a, b, c);
    const hi = Math.max(a, b, c);
    const mid = a + b + c - lo - hi;
    if (seenTriangles.get(lo, mid, hi) > 0) {
      report.duplicateTriangles++;
      continue;
    }
    if (
      edgeUse.get(Math.min(a, b), Math.max(a, b)) >= 2 ||
      edgeUse.get(Math.min(b, c), Math.max(b, c)) >= 2 ||
      edgeUse.get(Math.min(c, a), Math.max(c, a)) >= 2
    ) {
      report.nonManifoldTriangles++;
      continue;
    }
    seenTriangles.add(lo, mid, hi);
    edgeUse.add(Math.min(a, b), Math.max(a, b));
    edgeUse.add(Math.min(b, c), Math.max(b, c));
    edgeUse.add(Math.min(c, a), Math.max(c, a));
    kept.push(a, b, c);
  }

  // 3. Order vertices for memory locality: reverse Cuthill-McKee over the edge graph, component by component.
  const adjacency = adjacencyLists(weldedCount, kept);
  const order = reverseCuthillMcKee(adjacency);
  const simOf = new Uint32Array(weldedCount);
  for (let s = 0; s < order.length; s++) simOf[order[s]] = s;
  const n = weldedCount;
  const rest = new Float32Array(3 * n);
  for (let w = 0; w < n; w++) for (let k = 0; k < 3; k++) rest[3 * simOf[w] + k] = weldedPositions[3 * w + k];
  const triangles = new Uint32Array(kept.length);
  for (let i = 0; i < kept.length; i++) triangles[i] = simOf[kept[i]];
  const renderToSim = new Uint32Array(renderCount);
  for (let r = 0; r < renderCount; r++) renderToSim[r] = simOf[weldOf[r]];

  // 4. CSR adjacency in simulation order.
  const vertexTriangleStart = new Uint32Array(n + 1);
  for (const v of triangles) vertexTriangleStart[v + 1]++;
  for (let v = 0; v < n; v++) vertexTriangleStart[v + 1] += vertexTriangleStart[v];
  const vertexTriangles = new Uint32Array(triangles.length);
  const fill = vertexTriangleStart.slice(0, n);
  for (let i = 0; i < triangles.length; i++) vertexTriangles[fill[triangles[i]]++] = Math.floor(i / 3);
  const simAdjacency: number[][] = Array.from({ length: n }, () => []);
  for (let w = 0; w < n; w++) {
    // Renumbered, then sorted by insertion (a handful of neighbours each).
    const list = adjacency[w].map((u) => simOf[u]);
    for (let i = 1; i < list.length; i++) {
      const u = list[i];
      let k = i;
      for (; k > 0 && list[k - 1] > u; k--) list[k] = list[k - 1];
      list[k] = u;
    }
    simAdjacency[simOf[w]] = list;
  }
  const neighbourStart = new Uint32Array(n + 1);
  for (let v = 0; v < n; v++) neighbourStart[v + 1] = neighbourStart[v] + simAdjacency[v].length;
  const neighbours = new Uint32Array(neighbourStart[n]);
  for (let v = 0; v < n; v++) neighbours.set(simAdjacency[v], neighbourStart[v]);
  for (let v = 0; v < n; v++) if (neighbourStart[v + 1] === neighbourStart[v]) report.isolatedVertices++;

  // 5. Unique edges, greedily coloured so that no two edges of a colour share a vertex.
  const { edges, colourStart } = colourEdges(n, simAdjacency);
  const restLength = new Float32Array(edges.length / 2);
  for (let e = 0; e < restLength.length; e++) restLength[e] = distance(rest, edges[2 * e], edges[2 * e + 1]);

  const restNormals = new Float32Array(3 * n);
  computeNormals(rest, triangles, restNormals);
  const spacing = finestSpacing(rest, restNormals, neighbourStart, neighbours);
  return {
    vertexCount: n,
    rest,
    triangles,
    renderToSim,
    edges,
    restLength,
    colourStart,
    vertexTriangleStart,
    vertexTriangles,
    neighbourStart,
    neighbours,
    restNormals,
    spacing,
    size: boundsDiagonal(rest),
    report,
  };
}

/**
 * The rest spacing of the mesh at each vertex in the direction in which it is finest: sqrt(2 mu), mu the smaller
 * eigenvalue of the mean second moment (1/d) sum e e^T of its d edges in the rest tangent plane. The mean of the
 * neighbours minus the vertex is (1/2d) sum e e^T : grad grad of a field, so this is the spacing over which a fold
 * across the finest direction is bent; on equilateral triangles it is the edge length. Face meshes are not even:
 * their quads run along the wrinkle lines and are short across them (about 2.6 by 4.7 mm on the 17k forehead), where
 * the mean edge length overstated the spacing 1.6 times.
 */
function finestSpacing(rest: Float32Array, normals: Float32Array, start: Uint32Array, neighbours: Uint32Array): Float32Array {
  const n = rest.length / 3;
  const spacing = new Float32Array(n);
  for (let v = 0; v < n; v++) {
    const degree = start[v + 1] - start[v];
    if (degree === 0) continue;
    const i = 3 * v;
    const nx = normals[i],
      ny = normals[i + 1],
      nz = normals[i + 2];
    // A tangent basis (t, b) around the normal: t = x cross n, or x itself for a normal along x.
    const side = ny * ny + nz * nz > 1e-12;
    let tx = side ? 0 : 1,
      ty = side ? -nz : 0,
      tz = side ? ny : 0;
    const length = Math.hypot(tx, ty, tz);
    tx /= length;
    ty /= length;
    tz /= length;
    const bx = ny * tz - nz * ty,
      by = nz * tx - nx * tz,
      bz = nx * ty - ny * tx;
    let stt = 0,
      stb = 0,
      sbb = 0;
    for (let j = start[v]; j < start[v + 1]; j++) {
      const k = 3 * neighbours[j];
      const ex = rest[k] - rest[i],
        ey = rest[k + 1] - rest[i + 1],
        ez = rest[k + 2] - rest[i + 2];
      const et = ex * tx + ey * ty + ez * tz;
      const eb = ex * bx + ey * by + ez * bz;
      stt += et * et;
      stb += et * eb;
      sbb += eb * eb;
    }
    // Smaller eigenvalue of [[stt, stb], [stb, sbb]] / degree.
    const mean = (stt + sbb) / (2 * degree);
    const half = Math.hypot(stt - sbb, 2 * stb) / (2 * degree);
    spacing[v] = Math.sqrt(2 * Math.max(0, mean - half));
  }
  return spacing;
}

/**
 * Area-weighted vertex normals (thesis 4.3.5, with each face weighted by its area instead of a plain average, so
 * slivers do not tilt the normal). Writes into `out`; allocates nothing, so it can run every frame.
 */
export function computeNormals(positions: Float32Array, triangles: Uint32Array, out: Float32Array): void {
  out.fill(0);
  addFaceNormals(positions, triangles, 0, triangles.length / 3, 3, out);
  // An isolated vertex gets +z: any unit vector keeps the shading finite.
  for (let i = 0; i < out.length; i += 3) normalize(out, i);
}

/**
 * Adds each of the triangles `t0..t1`'s area-weighted normal (its cross product, twice its area long) to its corners
 * in `out`. A corner's offset into the xyz arrays is `scale` times its entry in `corners` (3 for vertex indices, 1 for
 * corners listed as 3 * vertex).
 */
export function addFaceNormals(
  positions: Float32Array,
  corners: Uint32Array,
  t0: number,
  t1: number,
  scale: number,
  out: Float32Array,
): void {
  for (let t = 3 * t0; t < 3 * t1; t += 3) {
    const a = scale * corners[t];
    const b = scale * corners[t + 1];
    const c = scale * corners[t + 2];
    const ux = positions[b] - positions[a];
    const uy = positions[b + 1] - positions[a + 1];
    const uz = positions[b + 2] - positions[a + 2];
    const vx = positions[c] - positions[a];
    const vy = positions[c + 1] - positions[a + 1];
    const vz = positions[c + 2] - positions[a + 2];
    const nx = uy * vz - uz * vy;
    const ny = uz * vx - ux * vz;
    const nz = ux * vy - uy * vx;
    out[a] += nx;
    out[a + 1] += ny;
    out[a + 2] += nz;
    out[b] += nx;
    out[b + 1] += ny;
    out[b + 2] += nz;
    out[c] += nx;
    out[c + 1] += ny;
    out[c + 2] += nz;
  }
}

/** Scales xyz at `i` to unit length, as computeNormals does (an isolated vertex's zero normal becomes +z). */
export function normalize(out: Float32Array, i: number): void {
  const len = Math.sqrt(out[i] * out[i] + out[i + 1] * out[i + 1] + out[i + 2] * out[i + 2]);
  if (len > 0) {
    out[i] /= len;
    out[i + 1] /= len;
    out[i + 2] /= len;
  } else {
    out[i + 2] = 1;
  }
}

function triangleArea2(P: number[], a: number, b: number, c: number): number {
  const ux = P[3 * b] - P[3 * a];
  const uy = P[3 * b + 1] - P[3 * a + 1];
  const uz = P[3 * b + 2] - P[3 * a + 2];
  const vx = P[3 * c] - P[3 * a];
  const vy = P[3 * c + 1] - P[3 * a + 1];
  const vz = P[3 * c + 2] - P[3 * a + 2];
  return Math.hypot(uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx);
}

function distance(P: Float32Array, a: number, b: number): number {
  return Math.hypot(P[3 * a] - P[3 * b], P[3 * a + 1] - P[3 * b + 1], P[3 * a + 2] - P[3 * b + 2]);
}

function boundsDiagonal(P: Float32Array): number {
  if (P.length === 0) return 0;
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < P.length; i++) {
    min[i % 3] = Math.min(min[i % 3], P[i]);
    max[i % 3] = Math.max(max[i % 3], P[i]);
  }
  return Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
}

function adjacencyLists(n: number, triangles: number[]): number[][] {
  // Each edge in both directions as one number (from * n + to), sorted: each vertex's neighbours come out in a run,
  // ascending, a repeat beside its twin (a Set per vertex cost the high head a fifth of a second).
  const pairs = new Float64Array(2 * triangles.length);
  let o = 0;
  for (let t = 0; t < triangles.length; t += 3) {
    for (let k = 0; k < 3; k++) {
      const a = triangles[t + k];
      const b = triangles[t + ((k + 1) % 3)];
      pairs[o++] = a * n + b;
      pairs[o++] = b * n + a;
    }
  }
  pairs.sort();
  const lists: number[][] = Array.from({ length: n }, () => []);
  for (let i = 0; i < pairs.length; i++) {
    if (i > 0 && pairs[i] === pairs[i - 1]) continue;
    const from = Math.floor(pairs[i] / n);
    lists[from].push(pairs[i] - from * n);
  }
  return lists;
}

/** Reverse Cuthill-McKee: breadth-first from a low-degree vertex, neighbours by rising degree, then reversed. */
function reverseCuthillMcKee(adjacency: number[][]): number[] {
  const n = adjacency.length;
  const visited = new Uint8Array(n);
  const degree = new Uint32Array(n);
  for (let v = 0; v < n; v++) degree[v] = adjacency[v].length;
  // Lower degree first, then lower index: the order the breadth-first search takes neighbours in.
  const before = (a: number, b: number): boolean => degree[a] < degree[b] || (degree[a] === degree[b] && a < b);
  const order: number[] = [];
  const byDegree = Array.from({ length: n }, (_, i) => i).sort((a, b) => degree[a] - degree[b] || a - b);
  const queue = new Uint32Array(n);
  for (const start of byDegree) {
    if (visited[start]) continue;
    visited[start] = 1;
    let tail = 0;
    queue[tail++] = start;
    for (let head = 0; head < tail; head++) {
      const v = queue[head];
      order.push(v);
      // The unvisited neighbours, appended to the queue and sorted there by insertion (a handful each).
      const first = tail;
      for (const u of adjacency[v]) {
        if (visited[u]) continue;
        visited[u] = 1;
        let k = tail++;
        while (k > first && before(u, queue[k - 1])) {
          queue[k] = queue[k - 1];
          k--;
        }
        queue[k] = u;
      }
    }
  }
  return order.reverse();
}

/**
 * Greedy edge colouring: each edge takes the lowest colour free at both of its ends, so edges of one colour share
 * no vertex and can be projected in any order (or in parallel) with the same result. At most 2 * degree - 1 colours.
 */
function colourEdges(n: number, adjacency: number[][]): { edges: Uint32Array; colourStart: Uint32Array } {
  // The colours taken at each vertex as bits, `words` 32-bit words a vertex: at most 2 * degree - 1 colours.
  let maxDegree = 0;
  for (let v = 0; v < n; v++) maxDegree = Math.max(maxDegree, adjacency[v].length);
  const words = Math.max(1, Math.ceil((2 * maxDegree) / 32));
  const used = new Uint32Array(n * words);
  const taken = (v: number, c: number): number => used[v * words + (c >>> 5)] & (1 << (c & 31));
  const take = (v: number, c: number): void => {
    used[v * words + (c >>> 5)] |= 1 << (c & 31);
  };
  const byColour: number[][] = [];
  for (let a = 0; a < n; a++) {
    for (const b of adjacency[a]) {
      if (b <= a) continue;
      let c = 0;
      while (taken(a, c) || taken(b, c)) c++;
      take(a, c);
      take(b, c);
      byColour[c] ??= [];
      byColour[c].push(a, b);
    }
  }
  const colourStart = new Uint32Array(byColour.length + 1);
  byColour.forEach((list, c) => (colourStart[c + 1] = colourStart[c] + list.length / 2));
  const edges = new Uint32Array(2 * colourStart[byColour.length]);
  byColour.forEach((list, c) => edges.set(list, 2 * colourStart[c]));
  return { edges, colourStart };
}
