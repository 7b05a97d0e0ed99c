/**
 * Resolution levels for a loaded head, as the default head has them: each level aims at the default head's triangle
 * count for it, reached by Catmull-Clark subdivision (a coarse head) or by decimation (a dense one, done by the
 * caller with a simplifier), never above the triangle limit. Pure: no three.js, no DOM.
 */
import { MAX_HEAD_TRIANGLES, weldExact, type TriangleMesh } from './head-mesh';
import { faceCount, polyMeshFromFaces, type PolyMesh } from './polymesh';
import { catmullClark } from './subdivide';

/** Triangles of the default head at each resolution (public/models/CREDITS.md). */
export const LEVEL_TRIANGLES = Object.freeze({ low: 8_524, medium: 34_096, high: 136_384 });
export type HeadLevel = keyof typeof LEVEL_TRIANGLES;

/** How to bring a head of `triangles` triangles to a level: subdivide some times, or decimate to a count. */
export type LevelPlan = { subdivisions: number } | { decimateTo: number };

/**
 * The plan whose triangle count is nearest the level's (on a log scale): Catmull-Clark turns each triangle into three
 * quads (six triangles) the first time and each quad into four after, and decimation takes a head down to the
 * level's count when it has more than half as many again.
 */
export function levelPlan(triangles: number, level: HeadLevel): LevelPlan {
  const target = LEVEL_TRIANGLES[level];
  if (triangles > 1.5 * target) return { decimateTo: target };
  const counts = [triangles];
  while (counts.length < 4) {
    const next = counts[counts.length - 1] * (counts.length === 1 ? 6 : 4);
    if (next > MAX_HEAD_TRIANGLES) break;
    counts.push(next);
  }
  const off = (count: number): number => Math.abs(Math.log(count / target));
  return { subdivisions: counts.reduce((best, count, n) => (off(count) < off(counts[best]) ? n : best), 0) };
}

/**
 * Subdivides a triangle mesh `levels` times by Catmull-Clark, over its welded positions (equal positions are one
 * vertex, so UV seams stay closed) with its uvs per corner, and triangulates the result. Triangles on an edge that
 * already has two are left out first: the scheme needs a manifold.
 */
export function subdivideHead(mesh: TriangleMesh, levels: number): TriangleMesh {
  if (levels <= 0) return mesh;
  const { positions, indices, uvs } = mesh;
  const { vertexOf, positions: welded } = weldExact(positions);
  const edgeUse = new Map<string, number>();
  const faces: { v: number[]; uv: number[] }[] = [];
  for (let t = 0; t + 2 < indices.length; t += 3) {
    const corners = [indices[t], indices[t + 1], indices[t + 2]];
    const v = corners.map((c) => vertexOf[c]);
    if (v[0] === v[1] || v[1] === v[2] || v[0] === v[2]) continue;
    const keys = [0, 1, 2].map((k) => {
      const a = v[k];
      const b = v[(k + 1) % 3];
      return a < b ? `${a},${b}` : `${b},${a}`;
    });
    if (keys.some((k) => (edgeUse.get(k) ?? 0) >= 2)) continue;
    for (const k of keys) edgeUse.set(k, (edgeUse.get(k) ?? 0) + 1);
    faces.push({ v, uv: corners.flatMap((c) => (uvs ? [uvs[2 * c], uvs[2 * c + 1]] : [0, 0])) });
  }
  let poly: PolyMesh = polyMeshFromFaces(Float64Array.from(welded), faces);
  for (let i = 0; i < levels; i++) poly = catmullClark(poly);
  return triangulate(poly, !!uvs);
}

/**
 * Decimates a triangle mesh to about `target` triangles with meshoptimizer's simplifier, over its welded positions
 * (so that UV seams do not hold it back); each kept vertex keeps the uv of its first copy. Open edges (a neck cut)
 * stay where they are.
 */
export async function decimateHead(mesh: TriangleMesh, target: number): Promise<TriangleMesh> {
  // Loaded only when a head is decimated: the simplifier is a WebAssembly module of its own.
  const { MeshoptSimplifier } = await import('meshoptimizer');
  await MeshoptSimplifier.ready;
  const { positions, indices, uvs } = mesh;
  const { vertexOf, positions: welded, firstCopy } = weldExact(positions);
  const triangles = Uint32Array.from(indices, (i) => vertexOf[i]);
  const [simplified] = MeshoptSimplifier.simplify(triangles, Float32Array.from(welded), 3, 3 * target, 0.05, ['LockBorder']);
  const renumber = new Map<number, number>();
  const out = Uint32Array.from(simplified, (v) => {
    let r = renumber.get(v);
    if (r === undefined) {
      r = renumber.size;
      renumber.set(v, r);
    }
    return r;
  });
  const kept = new Float32Array(3 * renumber.size);
  const keptUvs = uvs ? new Float32Array(2 * renumber.size) : undefined;
  for (const [v, r] of renumber) {
    kept.set(welded.slice(3 * v, 3 * v + 3), 3 * r);
    if (keptUvs && uvs) keptUvs.set(uvs.subarray(2 * firstCopy[v], 2 * firstCopy[v] + 2), 2 * r);
  }
  return { positions: kept, indices: out, uvs: keptUvs };
}

/** A polygon mesh as indexed triangles, one render vertex per distinct (vertex, uv), quads along their shorter diagonal. */
function triangulate(mesh: PolyMesh, withUvs: boolean): TriangleMesh {
  const P = mesh.positions;
  const key = new Map<string, number>();
  const positions: number[] = [];
  const uvs: number[] = [];
  const render = new Uint32Array(mesh.corners.length);
  for (let c = 0; c < mesh.corners.length; c++) {
    const v = mesh.corners[c];
    const k = `${v}:${mesh.cornerUVs[2 * c]}:${mesh.cornerUVs[2 * c + 1]}`;
    let r = key.get(k);
    if (r === undefined) {
      r = positions.length / 3;
      key.set(k, r);
      positions.push(P[3 * v], P[3 * v + 1], P[3 * v + 2]);
      uvs.push(mesh.cornerUVs[2 * c], mesh.cornerUVs[2 * c + 1]);
    }
    render[c] = r;
  }
  const d2 = (a: number, b: number): number =>
    (P[3 * a] - P[3 * b]) ** 2 + (P[3 * a + 1] - P[3 * b + 1]) ** 2 + (P[3 * a + 2] - P[3 * b + 2]) ** 2;
  const triangles: number[] = [];
  for (let f = 0; f < faceCount(mesh); f++) {
    const s = mesh.faceStart[f];
    const n = mesh.faceStart[f + 1] - s;
    const v = (i: number): number => mesh.corners[s + i];
    const c = (i: number): number => render[s + i];
    if (n === 4 && d2(v(1), v(3)) < d2(v(0), v(2))) triangles.push(c(0), c(1), c(3), c(1), c(2), c(3));
    else for (let i = 1; i + 1 < n; i++) triangles.push(c(0), c(i), c(i + 1));
  }
  return {
    positions: Float32Array.from(positions),
    indices: Uint32Array.from(triangles),
    uvs: withUvs ? Float32Array.from(uvs) : undefined,
  };
}
