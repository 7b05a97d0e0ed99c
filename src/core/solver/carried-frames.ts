/**
 * Orientation frames that turn with the skin the lids and the jaw carry: where a rotation muscle turns skin bodily
 * (thesis 3.2.2 and 4.4.3), each triangle's bound on turning over (see projectOrientationPart) is taken about its rest
 * normal turned as the muscles' targets turn it, not about the rest normal itself. A closing lid rolls its margin's
 * skin past edge-on against the rest normals at the eye's corners; bounded about those, the skin there pulled against
 * the lid until the solver's safety net (docs/solver-notes.md, "Orientation frames carried with the lids").
 */
import { rotationOffsetBy } from '../math3';
import { addFaceNormals } from './topology';

/** Scratch for one frame's turn (see turnFrame). */
const turn = new Float64Array(3);

/** The frames of a skin's triangles as its rotation muscles carry them (see `update`). */
export class CarriedFrames {
  /** The triangles' rest frames (xyz normal and bound, as triangleFrames makes them). */
  private readonly restFrames: Float32Array;
  /** The targets' mesh where the muscles hold the skin, rest elsewhere, xyz per vertex (at listed corners). */
  private readonly carried: Float32Array;
  /** That mesh's vertex normals (area-weighted sums), then each listed corner's turned normal (unit). */
  private readonly turned: Float32Array;
  /** Per vertex, 1 once its turned normal is made in the current update. */
  private readonly done: Uint8Array;
  /** 1 for a triangle whose frame is turned now. */
  private readonly turnedTriangles: Uint8Array;
  /** The corners (vertex indices) of the triangles with a turned corner, in their order. */
  private readonly list: Uint32Array;
  /** Those triangles' indices. */
  private readonly carriedTriangles: Uint32Array;

  constructor(
    private readonly rest: Float32Array,
    private readonly restNormals: Float32Array,
    private readonly triangles: Uint32Array,
    restFrames: Float32Array,
  ) {
    this.restFrames = Float32Array.from(restFrames);
    this.carried = new Float32Array(rest.length);
    this.turned = new Float32Array(rest.length);
    this.done = new Uint8Array(rest.length / 3);
    this.turnedTriangles = new Uint8Array(triangles.length / 3);
    this.list = new Uint32Array(triangles.length);
    this.carriedTriangles = new Uint32Array(triangles.length / 3);
  }

  /**
   * Writes into `frames` (triangleFrames' layout) the frame of each triangle with a corner whose turn weight is above
   * 0, and the rest frame of each one turned at the last update and not now; each also into `listed` at its place
   * there (`places[t]`, -1 for a triangle not listed), the orientation passes' list. A corner's
   * turned normal is its rest normal mixed, by its turn weight, with the normal of the targets' mesh there (the targets
   * where the muscles hold the skin, rest elsewhere): where the lid's turn fades, the targets' mesh turns further than
   * any one vertex's turn, and the skin follows it. A triangle's rest normal is turned by the rotation that takes its
   * corners' mean rest normal to their mean turned normal, so that it keeps its own tilt against its neighbours.
   * Allocates nothing.
   */
  update(
    targets: Float32Array,
    weights: Float32Array,
    normalWeights: Float32Array,
    turnWeights: Float32Array,
    frames: Float32Array,
    listed: Float32Array,
    places: Int32Array,
  ): void {
    const T = this.triangles;
    const R = this.restFrames;
    const was = this.turnedTriangles;
    for (let t = 0; t < was.length; t++) {
      if (was[t] === 0) continue;
      was[t] = 0;
      const o = 4 * t;
      frames[o] = R[o];
      frames[o + 1] = R[o + 1];
      frames[o + 2] = R[o + 2];
      copyFrame(frames, t, listed, places[t]);
    }
    const L = this.list;
    let count = 0;
    for (let t = 0; t < was.length; t++) {
      const a = T[3 * t];
      const b = T[3 * t + 1];
      const c = T[3 * t + 2];
      if (turnWeights[a] === 0 && turnWeights[b] === 0 && turnWeights[c] === 0) continue;
      L[3 * count] = a;
      L[3 * count + 1] = b;
      L[3 * count + 2] = c;
      this.carriedTriangles[count++] = t;
    }
    if (count === 0) return;
    const X = this.rest;
    const P = this.carried;
    const M = this.turned;
    for (let k = 0; k < 3 * count; k++) {
      const v = L[k];
      const i = 3 * v;
      const held = weights[v] > 0 || normalWeights[v] > 0;
      P[i] = held ? targets[i] : X[i];
      P[i + 1] = held ? targets[i + 1] : X[i + 1];
      P[i + 2] = held ? targets[i + 2] : X[i + 2];
      M[i] = M[i + 1] = M[i + 2] = 0;
      this.done[v] = 0;
    }
    // The targets' mesh's normals at the listed corners, over the listed triangles.
    addFaceNormals(P, L, 0, count, 3, M);
    const N = this.restNormals;
    for (let k = 0; k < 3 * count; k++) {
      const v = L[k];
      if (this.done[v] === 1) continue;
      this.done[v] = 1;
      const i = 3 * v;
      const s = turnWeights[v];
      const length = Math.hypot(M[i], M[i + 1], M[i + 2]);
      let x = N[i];
      let y = N[i + 1];
      let z = N[i + 2];
      if (s > 0 && length > 0) {
        x += s * (M[i] / length - x);
        y += s * (M[i + 1] / length - y);
        z += s * (M[i + 2] / length - z);
      }
      const mixed = Math.hypot(x, y, z) || 1;
      M[i] = x / mixed;
      M[i + 1] = y / mixed;
      M[i + 2] = z / mixed;
    }
    for (let k = 0; k < count; k++) {
      const t = this.carriedTriangles[k];
      turnFrame(N, M, 3 * L[3 * k], 3 * L[3 * k + 1], 3 * L[3 * k + 2], R, frames, 4 * t);
      was[t] = 1;
      copyFrame(frames, t, listed, places[t]);
    }
  }
}

/**
 * Writes into `frames[o..o+2]` the rest normal `R[o..o+2]` turned by the rotation that takes the mean of the corners'
 * rest normals (N at xyz offsets a, b, c) to the mean of their turned normals (M); the rest normal where either mean
 * vanishes or the two are parallel (or, never seen, opposite).
 */
function turnFrame(
  N: Float32Array,
  M: Float32Array,
  a: number,
  b: number,
  c: number,
  R: Float32Array,
  frames: Float32Array,
  o: number,
): void {
  const nx = R[o];
  const ny = R[o + 1];
  const nz = R[o + 2];
  frames[o] = nx;
  frames[o + 1] = ny;
  frames[o + 2] = nz;
  let fx = N[a] + N[b] + N[c];
  let fy = N[a + 1] + N[b + 1] + N[c + 1];
  let fz = N[a + 2] + N[b + 2] + N[c + 2];
  let tx = M[a] + M[b] + M[c];
  let ty = M[a + 1] + M[b + 1] + M[c + 1];
  let tz = M[a + 2] + M[b + 2] + M[c + 2];
  const fl = Math.hypot(fx, fy, fz);
  const tl = Math.hypot(tx, ty, tz);
  if (fl === 0 || tl === 0) return;
  fx /= fl;
  fy /= fl;
  fz /= fl;
  tx /= tl;
  ty /= tl;
  tz /= tl;
  // About k = f x t / |f x t|, by the angle whose sine is |f x t| and cosine f . t.
  const kx = fy * tz - fz * ty;
  const ky = fz * tx - fx * tz;
  const kz = fx * ty - fy * tx;
  const sine = Math.hypot(kx, ky, kz);
  if (sine < 1e-9) return;
  rotationOffsetBy(nx, ny, nz, 0, 0, 0, kx / sine, ky / sine, kz / sine, sine, 1 - (fx * tx + fy * ty + fz * tz), turn);
  frames[o] = nx + turn[0];
  frames[o + 1] = ny + turn[1];
  frames[o + 2] = nz + turn[2];
}

/** Copies triangle `t`'s frame (xyz normal and bound) to place `place` of a list's frames; nothing for place -1. */
function copyFrame(frames: Float32Array, t: number, into: Float32Array, place: number): void {
  if (place < 0) return;
  for (let k = 0; k < 4; k++) into[4 * place + k] = frames[4 * t + k];
}
