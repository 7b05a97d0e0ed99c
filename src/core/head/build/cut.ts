import { buildEdges, chainLoops, edgeKey, faceCount, polyMeshFromFaces, vertexCount, type PolyMesh } from '../polymesh';

/** Per-vertex neighbours and incident faces of a polygon mesh. */
interface Adjacency {
  neighbours: number[][];
  faces: number[][];
}

function adjacency(mesh: PolyMesh): Adjacency {
  const V = vertexCount(mesh);
  const neighbours: Set<number>[] = Array.from({ length: V }, () => new Set());
  const faces: number[][] = Array.from({ length: V }, () => []);
  for (let f = 0; f < faceCount(mesh); f++) {
    const s = mesh.faceStart[f];
    const n = mesh.faceStart[f + 1] - s;
    for (let i = 0; i < n; i++) {
      const v = mesh.corners[s + i];
      faces[v].push(f);
      neighbours[v].add(mesh.corners[s + ((i + 1) % n)]);
      neighbours[v].add(mesh.corners[s + ((i + n - 1) % n)]);
    }
  }
  return { neighbours: neighbours.map((s) => [...s].sort((a, b) => a - b)), faces };
}

function faceHas(mesh: PolyMesh, f: number, v: number): boolean {
  for (let c = mesh.faceStart[f]; c < mesh.faceStart[f + 1]; c++) if (mesh.corners[c] === v) return true;
  return false;
}

/**
 * Follows the quad edge loop that starts with the edge (start, next): at every regular (valence 4) vertex the loop
 * goes on along the edge that shares no face with the edge it came in on. Returns the loop's vertices, start first,
 * without repeating it; throws if the loop meets an irregular vertex or does not close, because a cut along such a
 * path would leave ragged faces.
 */
export function findEdgeLoop(mesh: PolyMesh, start: number, next: number, maxLength = 10_000): number[] {
  const adj = adjacency(mesh);
  if (!adj.neighbours[start].includes(next)) throw new Error(`vertices ${start} and ${next} share no edge`);
  const loop = [start];
  let prev = start;
  let cur = next;
  while (cur !== start) {
    if (loop.length > maxLength) throw new Error(`edge loop from ${start} did not close within ${maxLength} vertices`);
    loop.push(cur);
    const nb = adj.neighbours[cur];
    if (nb.length !== 4) throw new Error(`edge loop from ${start} meets vertex ${cur} of valence ${nb.length}: not a clean quad loop`);
    const incoming = adj.faces[cur].filter((f) => faceHas(mesh, f, prev));
    const candidates = nb.filter((n) => n !== prev && !incoming.some((f) => faceHas(mesh, f, n)));
    if (candidates.length !== 1) throw new Error(`edge loop from ${start} is ambiguous at vertex ${cur}`);
    prev = cur;
    cur = candidates[0];
  }
  return loop;
}

/** The part of a mesh cut off along a closed edge loop, with the map back to the source vertices. */
export interface CutResult {
  mesh: PolyMesh;
  /** Source vertex index of each vertex of the cut mesh, ascending. */
  sourceVertex: Uint32Array;
  /** Source face index of each face of the cut mesh, ascending. */
  sourceFace: Uint32Array;
}

/**
 * Keeps the faces connected to `seedFace` without crossing the loop, so the cut follows the loop's edges exactly.
 * Vertices keep their source order (the cut mesh's vertex i is the i-th kept source vertex).
 */
export function cutAlongLoop(mesh: PolyMesh, loop: readonly number[], seedFace: number): CutResult {
  const edges = buildEdges(mesh);
  const blocked = new Set<number>();
  for (let i = 0; i < loop.length; i++) {
    const e = edges.index.get(edgeKey(loop[i], loop[(i + 1) % loop.length]));
    if (e === undefined) throw new Error(`loop vertices ${loop[i]} and ${loop[(i + 1) % loop.length]} share no edge`);
    blocked.add(e);
  }
  const F = faceCount(mesh);
  const keep = new Uint8Array(F);
  const stack = [seedFace];
  keep[seedFace] = 1;
  while (stack.length > 0) {
    const f = stack.pop()!;
    for (let c = mesh.faceStart[f]; c < mesh.faceStart[f + 1]; c++) {
      const e = edges.cornerEdge[c];
      if (blocked.has(e)) continue;
      const other = edges.faces[2 * e] === f ? edges.faces[2 * e + 1] : edges.faces[2 * e];
      if (other >= 0 && !keep[other]) {
        keep[other] = 1;
        stack.push(other);
      }
    }
  }
  const kept: number[] = [];
  for (let f = 0; f < F; f++) if (keep[f]) kept.push(f);
  if (kept.length === F) throw new Error('the loop does not separate the mesh: every face is still connected to the seed');
  return subsetFaces(mesh, kept);
}

/** The faces `kept` (ascending) of a mesh, with only the vertices they use, in source order. */
export function subsetFaces(mesh: PolyMesh, kept: readonly number[]): CutResult {
  const usedVertex = new Uint8Array(vertexCount(mesh));
  for (const f of kept) for (let c = mesh.faceStart[f]; c < mesh.faceStart[f + 1]; c++) usedVertex[mesh.corners[c]] = 1;
  const remap = new Int32Array(usedVertex.length).fill(-1);
  const sourceVertex: number[] = [];
  usedVertex.forEach((used, v) => {
    if (used) {
      remap[v] = sourceVertex.length;
      sourceVertex.push(v);
    }
  });
  const positions = new Float64Array(3 * sourceVertex.length);
  sourceVertex.forEach((v, i) => positions.set(mesh.positions.subarray(3 * v, 3 * v + 3), 3 * i));
  const faces = kept.map((f) => {
    const s = mesh.faceStart[f];
    const e = mesh.faceStart[f + 1];
    return { v: Array.from(mesh.corners.subarray(s, e), (v) => remap[v]), uv: Array.from(mesh.cornerUVs.subarray(2 * s, 2 * e)) };
  });
  return { mesh: polyMeshFromFaces(positions, faces), sourceVertex: Uint32Array.from(sourceVertex), sourceFace: Uint32Array.from(kept) };
}

/** Boundary loops of a mesh (edges with one face), each as a vertex list; an empty list for a closed mesh. */
export function boundaryLoops(mesh: PolyMesh): number[][] {
  const edges = buildEdges(mesh);
  const nextOf = new Map<number, number>();
  for (let f = 0; f < faceCount(mesh); f++) {
    const s = mesh.faceStart[f];
    const n = mesh.faceStart[f + 1] - s;
    for (let i = 0; i < n; i++) {
      const e = edges.cornerEdge[s + i];
      if (edges.faces[2 * e + 1] < 0) nextOf.set(mesh.corners[s + i], mesh.corners[s + ((i + 1) % n)]);
    }
  }
  return chainLoops(
    nextOf,
    [...nextOf.keys()].sort((a, b) => a - b),
  );
}
