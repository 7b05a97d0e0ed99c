/**
 * Carries a skin's shape from one resolution level to the next finer one, through the Catmull-Clark stencils that made
 * the finer level: the default heads are one quad mesh subdivided 0, 1 and 2 times, so a shape solved on the coarser
 * level gives, subdivided, the finer level's coarse shape (its folds apart) at a quarter of the cost. The stencils act
 * on any shape, not only the rest shape: subdivision is linear in the positions. Pure: no three.js, no DOM.
 */
import { buildEdges, faceCount, polyMeshFromFaces, vertexCount, type PolyMesh } from './polymesh';

/** How near (metres) a subdivided coarse vertex must come to a fine vertex at rest to be taken as that vertex. */
const MATCH = 1e-5;

/**
 * The coarse level's quads: its triangulation split each quad along a diagonal into two triangles, written one after
 * the other, so each pair of consecutive triangles that shares an edge is a quad. Null if a pair does not.
 */
function quadsOf(triangles: ArrayLike<number>): number[][] | null {
  if (triangles.length % 6 !== 0) return null;
  const quads: number[][] = [];
  for (let t = 0; t < triangles.length; t += 6) {
    const first = [triangles[t], triangles[t + 1], triangles[t + 2]];
    const second = [triangles[t + 3], triangles[t + 4], triangles[t + 5]];
    const lone = first.findIndex((v) => !second.includes(v));
    const other = second.filter((v) => !first.includes(v));
    if (lone < 0 || other.length !== 1 || first.filter((v) => second.includes(v)).length !== 2) return null;
    // First triangle (u, a, b) counter-clockwise shares a-b with (b, a, w): the quad is u, a, w, b.
    const u = first[lone];
    const a = first[(lone + 1) % 3];
    const b = first[(lone + 2) % 3];
    quads.push([u, a, other[0], b]);
  }
  return quads;
}

/** Sparse rows: fine vertex i is the sum over k in start[i]..start[i+1] of weight[k] times coarse vertex source[k]. */
interface Stencils {
  start: Uint32Array;
  source: Uint32Array;
  weight: Float64Array;
}

/**
 * One Catmull-Clark step as a sparse matrix, rows ordered as `catmullClark` orders its vertices (old vertices, edge
 * points, face points) and with its rules: the crease rules on the boundary, a corner or a pinch kept where it is.
 */
function subdivisionStencils(mesh: PolyMesh): Stencils {
  const V = vertexCount(mesh);
  const F = faceCount(mesh);
  const edges = buildEdges(mesh);
  const E = edges.vertices.length / 2;
  const rows: Map<number, number>[] = Array.from({ length: V + E + F }, () => new Map());
  const add = (row: Map<number, number>, v: number, w: number): void => {
    row.set(v, (row.get(v) ?? 0) + w);
  };
  const addFace = (row: Map<number, number>, f: number, w: number): void => {
    const s = mesh.faceStart[f];
    const n = mesh.faceStart[f + 1] - s;
    for (let i = 0; i < n; i++) add(row, mesh.corners[s + i], w / n);
  };
  for (let f = 0; f < F; f++) addFace(rows[V + E + f], f, 1);
  const boundary: number[][] = Array.from({ length: V }, () => []);
  for (let e = 0; e < E; e++) {
    const a = edges.vertices[2 * e];
    const b = edges.vertices[2 * e + 1];
    const f0 = edges.faces[2 * e];
    const f1 = edges.faces[2 * e + 1];
    const row = rows[V + e];
    if (f1 < 0) {
      add(row, a, 0.5);
      add(row, b, 0.5);
      boundary[a].push(b);
      boundary[b].push(a);
    } else {
      add(row, a, 0.25);
      add(row, b, 0.25);
      addFace(row, f0, 0.25);
      addFace(row, f1, 0.25);
    }
  }
  const faceValence = new Uint32Array(V);
  const edgeValence = new Uint32Array(V);
  for (let c = 0; c < mesh.corners.length; c++) faceValence[mesh.corners[c]]++;
  for (let e = 0; e < 2 * E; e++) edgeValence[edges.vertices[e]]++;
  for (let f = 0; f < F; f++)
    for (let c = mesh.faceStart[f]; c < mesh.faceStart[f + 1]; c++) {
      const v = mesh.corners[c];
      const n = faceValence[v];
      // (Q + 2R + (n - 3) S) / n: Q the mean of the faces' points, R of the edges' midpoints, S the vertex.
      if (boundary[v].length === 0 && n > 0 && n === edgeValence[v]) addFace(rows[v], f, 1 / (n * n));
    }
  for (let e = 0; e < E; e++)
    for (const [v, o] of [
      [edges.vertices[2 * e], edges.vertices[2 * e + 1]],
      [edges.vertices[2 * e + 1], edges.vertices[2 * e]],
    ]) {
      const n = faceValence[v];
      if (boundary[v].length === 0 && n > 0 && n === edgeValence[v]) {
        add(rows[v], v, 1 / (n * n));
        add(rows[v], o, 1 / (n * n));
      }
    }
  for (let v = 0; v < V; v++) {
    const bn = boundary[v];
    const n = faceValence[v];
    if (bn.length === 2) {
      add(rows[v], v, 0.75);
      add(rows[v], bn[0], 0.125);
      add(rows[v], bn[1], 0.125);
    } else if (bn.length > 0 || n === 0 || n !== edgeValence[v]) add(rows[v], v, 1);
    else add(rows[v], v, (n - 3) / n);
  }
  const start = new Uint32Array(rows.length + 1);
  rows.forEach((row, i) => (start[i + 1] = start[i] + row.size));
  const source = new Uint32Array(start[rows.length]);
  const weight = new Float64Array(start[rows.length]);
  rows.forEach((row, i) => {
    let k = start[i];
    for (const [v, w] of row) {
      source[k] = v;
      weight[k++] = w;
    }
  });
  return { start, source, weight };
}

/** Applies stencils to xyz positions. */
function applyStencils(s: Stencils, x: ArrayLike<number>, out: Float64Array | Float32Array, rows: ArrayLike<number> | null): void {
  const count = s.start.length - 1;
  for (let i = 0; i < count; i++) {
    let px = 0,
      py = 0,
      pz = 0;
    for (let k = s.start[i]; k < s.start[i + 1]; k++) {
      const v = 3 * s.source[k];
      const w = s.weight[k];
      px += w * x[v];
      py += w * x[v + 1];
      pz += w * x[v + 2];
    }
    const o = 3 * (rows ? rows[i] : i);
    out[o] = px;
    out[o + 1] = py;
    out[o + 2] = pz;
  }
}

/** A carry from a coarse skin level to the finer level subdivided from it (see `LevelCarry.between`). */
export class LevelCarry {
  private constructor(
    private readonly stencils: Stencils,
    /** The fine vertex each stencil row makes. */
    private readonly fineOf: Uint32Array,
    readonly fineCount: number,
  ) {}

  /**
   * The carry from the coarse skin (rest xyz and triangles in the order its quads were split, as the head's model
   * files keep them) to the fine one, or null if the fine skin is not the coarse one subdivided once: its triangles are
   * not quads in pairs, or a fine vertex at rest is not where the subdivision puts one (within 10 µm).
   */
  static between(coarseRest: ArrayLike<number>, coarseTriangles: ArrayLike<number>, fineRest: ArrayLike<number>): LevelCarry | null {
    const quads = quadsOf(coarseTriangles);
    if (!quads) return null;
    let mesh: PolyMesh;
    let stencils: Stencils;
    try {
      mesh = polyMeshFromFaces(
        Float64Array.from(coarseRest),
        quads.map((v) => ({ v, uv: [0, 0, 0, 0, 0, 0, 0, 0] })),
      );
      stencils = subdivisionStencils(mesh);
    } catch {
      return null; // not a manifold: no subdivision made the fine skin from it
    }
    const count = stencils.start.length - 1;
    const fineCount = fineRest.length / 3;
    if (count !== fineCount) return null;
    const made = new Float64Array(3 * count);
    applyStencils(stencils, coarseRest, made, null);
    // Each subdivided point to the fine vertex at its place, through a grid of cells a little larger than MATCH.
    const cell = 4 * MATCH;
    const grid = new Map<string, number[]>();
    const key = (x: number, y: number, z: number): string => `${Math.floor(x / cell)},${Math.floor(y / cell)},${Math.floor(z / cell)}`;
    for (let v = 0; v < fineCount; v++) {
      const k = key(fineRest[3 * v], fineRest[3 * v + 1], fineRest[3 * v + 2]);
      const list = grid.get(k);
      if (list) list.push(v);
      else grid.set(k, [v]);
    }
    const fineOf = new Uint32Array(count);
    const taken = new Uint8Array(fineCount);
    for (let i = 0; i < count; i++) {
      const [x, y, z] = [made[3 * i], made[3 * i + 1], made[3 * i + 2]];
      let found = -1;
      for (let dx = -1; dx <= 1 && found < 0; dx++)
        for (let dy = -1; dy <= 1 && found < 0; dy++)
          for (let dz = -1; dz <= 1 && found < 0; dz++)
            for (const v of grid.get(key(x + dx * cell, y + dy * cell, z + dz * cell)) ?? [])
              if (!taken[v] && Math.hypot(fineRest[3 * v] - x, fineRest[3 * v + 1] - y, fineRest[3 * v + 2] - z) <= MATCH) {
                found = v;
                break;
              }
      if (found < 0) return null;
      taken[found] = 1;
      fineOf[i] = found;
    }
    return new LevelCarry(stencils, fineOf, fineCount);
  }

  /** Writes into `out` (xyz per fine vertex) the fine skin's shape subdivided from the coarse skin's shape `coarse`. */
  carry(coarse: ArrayLike<number>, out: Float32Array): void {
    applyStencils(this.stencils, coarse, out, this.fineOf);
  }
}
