/**
 * A polygon mesh with face-varying texture coordinates: the shape the head takes between the cut and the GLB.
 * Faces are stored flat (`faceStart` offsets into `corners`), so quads and the odd triangle can sit side by side.
 */
export interface PolyMesh {
  /** xyz per vertex. */
  positions: Float64Array;
  /** `faceStart[f]..faceStart[f+1]` are face f's corners; length is face count + 1. */
  faceStart: Uint32Array;
  /** Vertex index per face corner, counter-clockwise seen from outside. */
  corners: Uint32Array;
  /** uv per face corner (so UV seams need no duplicated positions). */
  cornerUVs: Float64Array;
}

/** Number of faces of a mesh. */
export const faceCount = (mesh: PolyMesh): number => mesh.faceStart.length - 1;

/** Number of vertices of a mesh. */
export const vertexCount = (mesh: PolyMesh): number => mesh.positions.length / 3;

/** Builds a PolyMesh from faces given as corner lists. */
export function polyMeshFromFaces(positions: Float64Array, faces: readonly { v: readonly number[]; uv: readonly number[] }[]): PolyMesh {
  const faceStart = new Uint32Array(faces.length + 1);
  let n = 0;
  faces.forEach((f, i) => {
    n += f.v.length;
    faceStart[i + 1] = n;
  });
  const corners = new Uint32Array(n);
  const cornerUVs = new Float64Array(2 * n);
  faces.forEach((f, i) => {
    corners.set(f.v, faceStart[i]);
    cornerUVs.set(f.uv, 2 * faceStart[i]);
  });
  return { positions, faceStart, corners, cornerUVs };
}

/** Key of the undirected edge (a, b) for maps. */
export const edgeKey = (a: number, b: number): number => (a < b ? a * 0x4000000 + b : b * 0x4000000 + a);

/** Unique undirected edges and the faces on each side, in order of first appearance. */
export interface EdgeTable {
  /** Two vertex indices per edge. */
  vertices: Uint32Array;
  /** Up to two faces per edge; -1 where the edge is on the boundary. */
  faces: Int32Array;
  /** Edge index of each face corner's outgoing edge (corner i to corner i+1). */
  cornerEdge: Uint32Array;
  index: Map<number, number>;
}

/** Builds the edge table; throws if an edge has more than two faces (the subdivision needs a manifold). */
export function buildEdges(mesh: PolyMesh): EdgeTable {
  const index = new Map<number, number>();
  const verts: number[] = [];
  const faces: number[] = [];
  const cornerEdge = new Uint32Array(mesh.corners.length);
  for (let f = 0; f < faceCount(mesh); f++) {
    const s = mesh.faceStart[f];
    const n = mesh.faceStart[f + 1] - s;
    for (let i = 0; i < n; i++) {
      const a = mesh.corners[s + i];
      const b = mesh.corners[s + ((i + 1) % n)];
      const key = edgeKey(a, b);
      let e = index.get(key);
      if (e === undefined) {
        e = verts.length / 2;
        index.set(key, e);
        verts.push(a, b);
        faces.push(f, -1);
      } else if (faces[2 * e + 1] === -1) {
        faces[2 * e + 1] = f;
      } else {
        throw new Error(`edge ${a}-${b} has more than two faces: the mesh is not manifold`);
      }
      cornerEdge[s + i] = e;
    }
  }
  return { vertices: Uint32Array.from(verts), faces: Int32Array.from(faces), cornerEdge, index };
}

/** A triangle mesh ready for the GPU: UV seams are split into separate render vertices. */
export interface RenderMesh {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  indices: Uint32Array;
  /** Which PolyMesh vertex each render vertex came from (equal for the copies along a seam). */
  sourceVertex: Uint32Array;
}

/**
 * Triangulates (quads along their shorter diagonal, other polygons as fans), splits vertices where the uv differs,
 * and gives every render vertex the area-weighted normal of its PolyMesh vertex, so seams do not show in the shading.
 */
export function toRenderMesh(mesh: PolyMesh, scale = 1): RenderMesh {
  const P = mesh.positions;
  const normals = vertexNormals(mesh);
  const keyToRender = new Map<string, number>();
  const source: number[] = [];
  const uv: number[] = [];
  const cornerRender = new Uint32Array(mesh.corners.length);
  for (let c = 0; c < mesh.corners.length; c++) {
    const v = mesh.corners[c];
    const u0 = mesh.cornerUVs[2 * c];
    const u1 = mesh.cornerUVs[2 * c + 1];
    const key = `${v}:${u0}:${u1}`;
    let r = keyToRender.get(key);
    if (r === undefined) {
      r = source.length;
      keyToRender.set(key, r);
      source.push(v);
      uv.push(u0, u1);
    }
    cornerRender[c] = r;
  }
  const tris: number[] = [];
  const d2 = (a: number, b: number): number =>
    (P[3 * a] - P[3 * b]) ** 2 + (P[3 * a + 1] - P[3 * b + 1]) ** 2 + (P[3 * a + 2] - P[3 * b + 2]) ** 2;
  for (let f = 0; f < faceCount(mesh); f++) {
    const s = mesh.faceStart[f];
    const n = mesh.faceStart[f + 1] - s;
    const c = (i: number): number => cornerRender[s + i];
    const v = (i: number): number => mesh.corners[s + i];
    if (n === 4 && d2(v(1), v(3)) < d2(v(0), v(2))) {
      tris.push(c(0), c(1), c(3), c(1), c(2), c(3));
    } else {
      for (let i = 1; i + 1 < n; i++) tris.push(c(0), c(i), c(i + 1));
    }
  }
  const count = source.length;
  const positions = new Float32Array(3 * count);
  const outNormals = new Float32Array(3 * count);
  for (let r = 0; r < count; r++) {
    for (let k = 0; k < 3; k++) {
      positions[3 * r + k] = P[3 * source[r] + k] * scale;
      outNormals[3 * r + k] = normals[3 * source[r] + k];
    }
  }
  return {
    positions,
    normals: outNormals,
    uvs: Float32Array.from(uv),
    indices: Uint32Array.from(tris),
    sourceVertex: Uint32Array.from(source),
  };
}

/** Area-weighted vertex normals of a polygon mesh (each polygon's Newell normal, whose length is twice its area). */
function vertexNormals(mesh: PolyMesh): Float64Array {
  const P = mesh.positions;
  const N = new Float64Array(P.length);
  for (let f = 0; f < faceCount(mesh); f++) {
    const s = mesh.faceStart[f];
    const n = mesh.faceStart[f + 1] - s;
    let nx = 0;
    let ny = 0;
    let nz = 0;
    for (let i = 0; i < n; i++) {
      const a = 3 * mesh.corners[s + i];
      const b = 3 * mesh.corners[s + ((i + 1) % n)];
      nx += (P[a + 1] - P[b + 1]) * (P[a + 2] + P[b + 2]);
      ny += (P[a + 2] - P[b + 2]) * (P[a] + P[b]);
      nz += (P[a] - P[b]) * (P[a + 1] + P[b + 1]);
    }
    for (let i = 0; i < n; i++) {
      const a = 3 * mesh.corners[s + i];
      N[a] += nx;
      N[a + 1] += ny;
      N[a + 2] += nz;
    }
  }
  for (let i = 0; i < N.length; i += 3) {
    const len = Math.hypot(N[i], N[i + 1], N[i + 2]);
    if (len > 0) {
      N[i] /= len;
      N[i + 1] /= len;
      N[i + 2] /= len;
    } else {
      N[i + 1] = 1; // an isolated vertex: any unit vector keeps the shader finite
    }
  }
  return N;
}

/**
 * Chains boundary edges into loops: `next` maps each boundary edge's first vertex to its second; each loop starts at
 * the first of `starts` not yet in a loop and follows `next` until it comes back (or the chain breaks).
 */
export function chainLoops(next: ReadonlyMap<number, number>, starts: Iterable<number> = next.keys()): number[][] {
  const loops: number[][] = [];
  const seen = new Set<number>();
  for (const start of starts) {
    if (seen.has(start)) continue;
    const loop: number[] = [];
    let v: number | undefined = start;
    while (v !== undefined && !seen.has(v)) {
      seen.add(v);
      loop.push(v);
      v = next.get(v);
    }
    loops.push(loop);
  }
  return loops;
}
