/**
 * A head mesh brought from a file: checked, its UV seams welded, and turned into the app's frame (metres, +y up, the
 * face toward +z, the subject's left at +x, the midline at x = 0). Pure: no three.js, no DOM.
 */

/** The most triangles a loaded head may have: above it the solver would be too slow to be of use. */
export const MAX_HEAD_TRIANGLES = 200_000;

/** An indexed triangle mesh: xyz per vertex, three vertex indices per triangle, optional uv per vertex. */
export interface TriangleMesh {
  positions: Float32Array;
  indices: Uint32Array;
  uvs?: Float32Array;
}

/**
 * Throws, naming what is wrong, if the mesh cannot be a head: no triangles, too many, an index outside the vertices,
 * or a coordinate that is not finite (with the vertex's index).
 */
export function checkHeadMesh(mesh: TriangleMesh, source: string): void {
  const triangles = Math.floor(mesh.indices.length / 3);
  const vertices = Math.floor(mesh.positions.length / 3);
  if (triangles === 0 || vertices < 4) throw new Error(`${source}: the mesh has no triangles`);
  if (triangles > MAX_HEAD_TRIANGLES) {
    throw new Error(
      `${source}: the mesh has ${triangles.toLocaleString('en-US')} triangles, more than ` +
        `the ${MAX_HEAD_TRIANGLES.toLocaleString('en-US')} a head may have (decimate it first)`,
    );
  }
  for (let i = 0; i < 3 * vertices; i++) {
    if (!Number.isFinite(mesh.positions[i])) {
      throw new Error(`${source}: vertex ${Math.floor(i / 3)} has a non-finite ${'xyz'[i % 3]} coordinate (${mesh.positions[i]})`);
    }
  }
  for (let i = 0; i < mesh.indices.length; i++) {
    if (mesh.indices[i] >= vertices)
      throw new Error(`${source}: triangle ${Math.floor(i / 3)} uses vertex ${mesh.indices[i]}, but the mesh has ${vertices}`);
  }
}

/**
 * Welds UV seams: vertices closer than `tolerance` to an earlier vertex take its position exactly, so that the skin
 * solver (which welds equal positions) sees one surface. Exporters write a seam's copies from different arithmetic,
 * a float's last bits apart. Changes `positions` in place; returns how many vertices moved.
 */
export function weldSeams(positions: Float32Array, tolerance: number): number {
  const n = positions.length / 3;
  const cell = Math.max(tolerance, 1e-12);
  const grid = new Map<string, number[]>();
  const key = (i: number, j: number, k: number): string => `${i},${j},${k}`;
  let moved = 0;
  for (let v = 0; v < n; v++) {
    const x = positions[3 * v];
    const y = positions[3 * v + 1];
    const z = positions[3 * v + 2];
    const i = Math.floor(x / cell);
    const j = Math.floor(y / cell);
    const k = Math.floor(z / cell);
    let twin = -1;
    for (let di = -1; di <= 1 && twin < 0; di++) {
      for (let dj = -1; dj <= 1 && twin < 0; dj++) {
        for (let dk = -1; dk <= 1 && twin < 0; dk++) {
          for (const u of grid.get(key(i + di, j + dj, k + dk)) ?? []) {
            if (Math.hypot(positions[3 * u] - x, positions[3 * u + 1] - y, positions[3 * u + 2] - z) <= tolerance) {
              twin = u;
              break;
            }
          }
        }
      }
    }
    if (twin >= 0) {
      if (positions[3 * twin] !== x || positions[3 * twin + 1] !== y || positions[3 * twin + 2] !== z) moved++;
      positions[3 * v] = positions[3 * twin];
      positions[3 * v + 1] = positions[3 * twin + 1];
      positions[3 * v + 2] = positions[3 * twin + 2];
      continue;
    }
    const cellKey = key(i, j, k);
    const list = grid.get(cellKey);
    if (list) list.push(v);
    else grid.set(cellKey, [v]);
  }
  return moved;
}

/**
 * Merges vertices that are the same in position and uv (an OBJ reader gives every triangle corner its own vertex),
 * so that the render mesh is indexed; UV seams keep their copies. Returns a new mesh.
 */
export function mergeVertices(mesh: TriangleMesh): TriangleMesh {
  const { positions: P, uvs } = mesh;
  const index = new Map<string, number>();
  const positions: number[] = [];
  const outUvs: number[] = [];
  const remap = new Uint32Array(P.length / 3);
  for (let v = 0; v < remap.length; v++) {
    const key = uvs
      ? `${P[3 * v]},${P[3 * v + 1]},${P[3 * v + 2]},${uvs[2 * v]},${uvs[2 * v + 1]}`
      : `${P[3 * v]},${P[3 * v + 1]},${P[3 * v + 2]}`;
    let r = index.get(key);
    if (r === undefined) {
      r = positions.length / 3;
      index.set(key, r);
      positions.push(P[3 * v], P[3 * v + 1], P[3 * v + 2]);
      if (uvs) outUvs.push(uvs[2 * v], uvs[2 * v + 1]);
    }
    remap[v] = r;
  }
  return {
    positions: Float32Array.from(positions),
    indices: Uint32Array.from(mesh.indices, (v) => remap[v]),
    uvs: uvs ? Float32Array.from(outUvs) : undefined,
  };
}

/** An axis of the file's frame, with its sign. */
export const AXES = ['+x', '-x', '+y', '-y', '+z', '-z'] as const;
export type Axis = (typeof AXES)[number];

/** Units a file may be in, by their length in metres. */
export const UNITS = { m: 1, dm: 0.1, cm: 0.01, mm: 0.001 } as const;
export type Unit = keyof typeof UNITS;

/** How a file's head is placed, given or found: its units, and the file's axes that point up and out of the face. */
export interface HeadFrameOptions {
  units?: Unit | 'auto';
  up?: Axis | 'auto';
  forward?: Axis | 'auto';
}

/**
 * The transform found, from the file's coordinate frame into the app's: file point p goes to
 * `scale * rotation * p + offset` (rotation row-major).
 */
export interface HeadTransform {
  units: Unit;
  up: Axis;
  forward: Axis;
  scale: number;
  rotation: number[];
  offset: [number, number, number];
}

/** A head with its neck is about this tall: the units are those that make it closest. */
const HEAD_SIZE = 0.25;

/**
 * Finds the head's units and orientation, where options leave them to be found, and the shift that puts its
 * midline at x = 0:
 * - units: the power of ten (m, dm, cm, mm) that makes the mesh's largest extent closest to a head's 25 cm;
 * - up: a neck opening (the longest open boundary) is at the bottom; without one, +y (the glTF convention);
 * - forward: across the head, the face is on the axis the head is not mirror-symmetric across, at the end where
 *   the surface comes to a point (the nose) rather than a broad cap (the back of the head).
 * Throws, naming the size, if no unit makes the mesh head-sized.
 */
export function findHeadTransform(
  positions: Float32Array,
  indices: Uint32Array,
  options: HeadFrameOptions = {},
  source = 'the head',
): HeadTransform {
  const { min, max } = positionBounds(positions);
  const extent = Math.max(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
  let units: Unit;
  if (options.units && options.units !== 'auto') units = options.units;
  else {
    units = (Object.keys(UNITS) as Unit[]).reduce((a, b) =>
      Math.abs(Math.log((extent * UNITS[b]) / HEAD_SIZE)) < Math.abs(Math.log((extent * UNITS[a]) / HEAD_SIZE)) ? b : a,
    );
    const size = extent * UNITS[units];
    if (size < 0.1 || size > 0.6) {
      throw new Error(
        `${source}: the mesh is ${extent.toPrecision(3)} units across, not the size of a head in m, dm, cm or mm; give its units`,
      );
    }
  }
  const scale = UNITS[units];
  const up = options.up && options.up !== 'auto' ? options.up : findUp(positions, indices);
  const upAxis = axisIndex(up);
  let forward: Axis;
  if (options.forward && options.forward !== 'auto') forward = options.forward;
  else forward = findForward(positions, indices, upAxis, axisSign(up), scale);
  if (axisIndex(forward) === upAxis) throw new Error(`${source}: up (${up}) and forward (${forward}) must be different axes`);
  const u = unit(up);
  const f = unit(forward);
  // The subject's left: up x forward (for +y up and +z forward, +x).
  const l = [u[1] * f[2] - u[2] * f[1], u[2] * f[0] - u[0] * f[2], u[0] * f[1] - u[1] * f[0]];
  const rotation = [...l, ...u, ...f];
  // The midline: halfway between the extremes across the head.
  let lo = Infinity;
  let hi = -Infinity;
  for (let i = 0; i < positions.length; i += 3) {
    const x = scale * (l[0] * positions[i] + l[1] * positions[i + 1] + l[2] * positions[i + 2]);
    lo = Math.min(lo, x);
    hi = Math.max(hi, x);
  }
  return { units, up, forward, scale, rotation, offset: [-(lo + hi) / 2, 0, 0] };
}

/** Moves positions (xyz, in place) by the transform, into the app's frame. */
export function applyHeadTransform(positions: Float32Array, transform: HeadTransform): void {
  const R = transform.rotation;
  const s = transform.scale;
  for (let i = 0; i < positions.length; i += 3) {
    const x = positions[i];
    const y = positions[i + 1];
    const z = positions[i + 2];
    positions[i] = s * (R[0] * x + R[1] * y + R[2] * z) + transform.offset[0];
    positions[i + 1] = s * (R[3] * x + R[4] * y + R[5] * z) + transform.offset[1];
    positions[i + 2] = s * (R[6] * x + R[7] * y + R[8] * z) + transform.offset[2];
  }
}

const axisIndex = (a: Axis): number => 'xyz'.indexOf(a[1]);
const axisSign = (a: Axis): number => (a[0] === '-' ? -1 : 1);
function unit(a: Axis): number[] {
  const v = [0, 0, 0];
  v[axisIndex(a)] = axisSign(a);
  return v;
}
function axisOf(index: number, sign: number): Axis {
  return `${sign < 0 ? '-' : '+'}${'xyz'[index]}` as Axis;
}

/** The least and greatest coordinate of a position array, per axis. */
export function positionBounds(P: Float32Array): { min: number[]; max: number[] } {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < P.length; i++) {
    min[i % 3] = Math.min(min[i % 3], P[i]);
    max[i % 3] = Math.max(max[i % 3], P[i]);
  }
  return { min, max };
}

/**
 * Equal positions as one vertex: each vertex's welded index (`vertexOf`), the welded positions (xyz each) and the
 * first vertex of each welded one.
 */
export function weldExact(positions: ArrayLike<number>): { vertexOf: Uint32Array; positions: number[]; firstCopy: number[] } {
  const index = new Map<string, number>();
  const welded: number[] = [];
  const firstCopy: number[] = [];
  const vertexOf = new Uint32Array(positions.length / 3);
  for (let v = 0; v < vertexOf.length; v++) {
    const key = `${positions[3 * v]},${positions[3 * v + 1]},${positions[3 * v + 2]}`;
    let w = index.get(key);
    if (w === undefined) {
      w = welded.length / 3;
      index.set(key, w);
      welded.push(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
      firstCopy.push(v);
    }
    vertexOf[v] = w;
  }
  return { vertexOf, positions: welded, firstCopy };
}

/** Up: away from the longest open boundary (the neck), if there is one long enough to be it; otherwise +y. */
function findUp(P: Float32Array, T: Uint32Array): Axis {
  // Edges used by one triangle only, over positions welded exactly; each end named by its first copy, a vertex of P.
  const { vertexOf, firstCopy } = weldExact(P);
  const weld = vertexOf.map((w) => firstCopy[w]);
  const uses = new Map<string, number>();
  for (let t = 0; t + 2 < T.length; t += 3) {
    for (let k = 0; k < 3; k++) {
      const a = weld[T[t + k]];
      const b = weld[T[t + ((k + 1) % 3)]];
      const key = a < b ? `${a},${b}` : `${b},${a}`;
      uses.set(key, (uses.get(key) ?? 0) + 1);
    }
  }
  const { min, max } = positionBounds(P);
  const centre = [0, 1, 2].map((k) => (min[k] + max[k]) / 2);
  let length = 0;
  const middle = [0, 0, 0];
  for (const [key, n] of uses) {
    if (n !== 1) continue;
    const [a, b] = key.split(',').map(Number);
    const l = Math.hypot(P[3 * a] - P[3 * b], P[3 * a + 1] - P[3 * b + 1], P[3 * a + 2] - P[3 * b + 2]);
    length += l;
    for (let k = 0; k < 3; k++) middle[k] += (l * (P[3 * a + k] + P[3 * b + k])) / 2;
  }
  const extent = Math.max(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
  // A neck is a loop some 30 cm round on a 25 cm head; eye and mouth openings are much shorter.
  if (length < extent) return '+y';
  const d = [0, 1, 2].map((k) => middle[k] / length - centre[k]);
  const k = [0, 1, 2].reduce((a, b) => (Math.abs(d[b]) > Math.abs(d[a]) ? b : a));
  return axisOf(k, -Math.sign(d[k]));
}

/**
 * Forward: of the two axes across `up`, the one the head is not mirror-symmetric across, toward its pointed end.
 * Only the part above the lowest third is looked at, so that a neck or shoulders do not count.
 */
function findForward(P: Float32Array, T: Uint32Array, upAxis: number, upSign: number, scale: number): Axis {
  const { min, max } = positionBounds(P);
  const lowest = upSign > 0 ? min[upAxis] : -max[upAxis];
  const height = max[upAxis] - min[upAxis];
  const kept: number[] = [];
  for (let v = 0; v < P.length / 3; v++) if (upSign * P[3 * v + upAxis] - lowest > height / 3) kept.push(v);
  const across = [0, 1, 2].filter((k) => k !== upAxis);
  const asymmetry = across.map((k) => mirrorError(P, kept, k, (min[k] + max[k]) / 2));
  const forwardAxis = asymmetry[0] > asymmetry[1] ? across[0] : across[1];
  // The pointed end: less surface near the extreme plane (a nose tip, not the broad back of the skull).
  const depth = 0.015 / scale;
  const area = vertexAreas(P, T);
  let nearMax = 0;
  let nearMin = 0;
  for (const v of kept) {
    const x = P[3 * v + forwardAxis];
    if (x > max[forwardAxis] - depth) nearMax += area[v];
    if (x < min[forwardAxis] + depth) nearMin += area[v];
  }
  return axisOf(forwardAxis, nearMax <= nearMin ? 1 : -1);
}

/** A third of the area of each vertex's triangles. */
function vertexAreas(P: Float32Array, T: Uint32Array): Float64Array {
  const area = new Float64Array(P.length / 3);
  for (let t = 0; t + 2 < T.length; t += 3) {
    const a = 3 * T[t];
    const b = 3 * T[t + 1];
    const c = 3 * T[t + 2];
    const u = [P[b] - P[a], P[b + 1] - P[a + 1], P[b + 2] - P[a + 2]];
    const w = [P[c] - P[a], P[c + 1] - P[a + 1], P[c + 2] - P[a + 2]];
    const third = Math.hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]) / 6;
    area[T[t]] += third;
    area[T[t + 1]] += third;
    area[T[t + 2]] += third;
  }
  return area;
}

/** Mean distance from each of (up to 2,000 of) the vertices, mirrored across the plane `axis = at`, to the nearest vertex. */
function mirrorError(P: Float32Array, kept: number[], axis: number, at: number): number {
  const { min, max } = positionBounds(P);
  const cell = Math.max(max[0] - min[0], max[1] - min[1], max[2] - min[2]) / 64;
  const grid = new Map<string, number[]>();
  const key = (x: number, y: number, z: number): string => `${Math.floor(x / cell)},${Math.floor(y / cell)},${Math.floor(z / cell)}`;
  for (const v of kept) {
    const k = key(P[3 * v], P[3 * v + 1], P[3 * v + 2]);
    const list = grid.get(k);
    if (list) list.push(v);
    else grid.set(k, [v]);
  }
  const step = Math.max(1, Math.floor(kept.length / 2000));
  let total = 0;
  let count = 0;
  for (let i = 0; i < kept.length; i += step) {
    const v = kept[i];
    const q = [P[3 * v], P[3 * v + 1], P[3 * v + 2]];
    q[axis] = 2 * at - q[axis];
    let best = 2 * cell;
    const c = q.map((x) => Math.floor(x / cell));
    for (let di = -1; di <= 1; di++) {
      for (let dj = -1; dj <= 1; dj++) {
        for (let dk = -1; dk <= 1; dk++) {
          for (const u of grid.get(`${c[0] + di},${c[1] + dj},${c[2] + dk}`) ?? []) {
            best = Math.min(best, Math.hypot(P[3 * u] - q[0], P[3 * u + 1] - q[1], P[3 * u + 2] - q[2]));
          }
        }
      }
    }
    total += best;
    count++;
  }
  return count > 0 ? total / count : 0;
}
