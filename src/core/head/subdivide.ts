import { buildEdges, faceCount, vertexCount, type PolyMesh } from './polymesh';

/**
 * One level of Catmull-Clark subdivision. Every n-gon becomes n quads; new vertices are ordered
 * [old vertices, edge points, face points], so the result is deterministic.
 *
 * Boundary edges (the neck cut, open helper meshes) use the crease rules: edge point at the midpoint, boundary
 * vertex at (6v + a + b) / 8 of its two boundary neighbours, so the cut stays a smooth loop. Texture coordinates are
 * face-varying and interpolated linearly inside each face, which keeps UV seams exact.
 */
export function catmullClark(mesh: PolyMesh): PolyMesh {
  const P = mesh.positions;
  const V = vertexCount(mesh);
  const F = faceCount(mesh);
  const edges = buildEdges(mesh);
  const E = edges.vertices.length / 2;
  const out = new Float64Array(3 * (V + E + F));

  // Face points: centroids.
  const facePoint = 3 * (V + E);
  for (let f = 0; f < F; f++) {
    const s = mesh.faceStart[f];
    const n = mesh.faceStart[f + 1] - s;
    for (let i = 0; i < n; i++) {
      const a = 3 * mesh.corners[s + i];
      for (let k = 0; k < 3; k++) out[facePoint + 3 * f + k] += P[a + k] / n;
    }
  }

  // Edge points: average of the two ends and the two face points; midpoint on the boundary.
  const boundaryNeighbours: number[][] = Array.from({ length: V }, () => []);
  for (let e = 0; e < E; e++) {
    const a = edges.vertices[2 * e];
    const b = edges.vertices[2 * e + 1];
    const f0 = edges.faces[2 * e];
    const f1 = edges.faces[2 * e + 1];
    const o = 3 * (V + e);
    for (let k = 0; k < 3; k++) {
      const mid = (P[3 * a + k] + P[3 * b + k]) / 2;
      out[o + k] = f1 < 0 ? mid : (mid + (out[facePoint + 3 * f0 + k] + out[facePoint + 3 * f1 + k]) / 2) / 2;
    }
    if (f1 < 0) {
      boundaryNeighbours[a].push(b);
      boundaryNeighbours[b].push(a);
    }
  }

  // Vertex points: (Q + 2R + (n - 3) S) / n inside, with Q the mean of the adjacent face points and R the mean of
  // the incident edge midpoints; crease rule on the boundary.
  const Q = new Float64Array(3 * V);
  const R = new Float64Array(3 * V);
  const faceValence = new Uint32Array(V);
  const edgeValence = new Uint32Array(V);
  for (let f = 0; f < F; f++) {
    for (let c = mesh.faceStart[f]; c < mesh.faceStart[f + 1]; c++) {
      const v = mesh.corners[c];
      faceValence[v]++;
      for (let k = 0; k < 3; k++) Q[3 * v + k] += out[facePoint + 3 * f + k];
    }
  }
  for (let e = 0; e < E; e++) {
    const a = edges.vertices[2 * e];
    const b = edges.vertices[2 * e + 1];
    edgeValence[a]++;
    edgeValence[b]++;
    for (let k = 0; k < 3; k++) {
      const mid = (P[3 * a + k] + P[3 * b + k]) / 2;
      R[3 * a + k] += mid;
      R[3 * b + k] += mid;
    }
  }
  for (let v = 0; v < V; v++) {
    const bn = boundaryNeighbours[v];
    for (let k = 0; k < 3; k++) {
      const S = P[3 * v + k];
      if (bn.length === 2) {
        out[3 * v + k] = (6 * S + P[3 * bn[0] + k] + P[3 * bn[1] + k]) / 8;
      } else if (bn.length > 0 || faceValence[v] === 0 || faceValence[v] !== edgeValence[v]) {
        out[3 * v + k] = S; // a corner, an isolated vertex or a pinch: keep it where it is
      } else {
        const n = faceValence[v];
        out[3 * v + k] = (Q[3 * v + k] / n + (2 * R[3 * v + k]) / n + (n - 3) * S) / n;
      }
    }
  }

  // Faces: corner i of an n-gon gives the quad (corner i, edge i, face point, edge i-1), keeping the winding.
  const corners = new Uint32Array(4 * mesh.corners.length);
  const cornerUVs = new Float64Array(8 * mesh.corners.length);
  const faceStart = new Uint32Array(mesh.corners.length + 1);
  let q = 0;
  for (let f = 0; f < F; f++) {
    const s = mesh.faceStart[f];
    const n = mesh.faceStart[f + 1] - s;
    let cu = 0;
    let cv = 0;
    for (let i = 0; i < n; i++) {
      cu += mesh.cornerUVs[2 * (s + i)] / n;
      cv += mesh.cornerUVs[2 * (s + i) + 1] / n;
    }
    for (let i = 0; i < n; i++) {
      const prev = (i + n - 1) % n;
      const next = (i + 1) % n;
      const o = 4 * q;
      corners[o] = mesh.corners[s + i];
      corners[o + 1] = V + edges.cornerEdge[s + i];
      corners[o + 2] = V + E + f;
      corners[o + 3] = V + edges.cornerEdge[s + prev];
      const uv = (c: number, k: number): number => mesh.cornerUVs[2 * (s + c) + k];
      const set = (j: number, u: number, v: number): void => {
        cornerUVs[2 * (o + j)] = u;
        cornerUVs[2 * (o + j) + 1] = v;
      };
      set(0, uv(i, 0), uv(i, 1));
      set(1, (uv(i, 0) + uv(next, 0)) / 2, (uv(i, 1) + uv(next, 1)) / 2);
      set(2, cu, cv);
      set(3, (uv(i, 0) + uv(prev, 0)) / 2, (uv(i, 1) + uv(prev, 1)) / 2);
      q++;
      faceStart[q] = 4 * q;
    }
  }
  return { positions: out, faceStart, corners, cornerUVs };
}
