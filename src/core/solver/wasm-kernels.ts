/**
 * The solver's WebAssembly kernels: the length passes' loops (projectFreeEdges, projectHeldEdges in length-kernels.ts)
 * four edges at a time in 128-bit lanes of 32-bit floats, about twice as fast as the JavaScript loops; both rings'
 * bending (projectBendingPart, projectSecondRingPart), the orientation passes (projectOrientationPart) and the position
 * constraints (projectPositions) one item at a time in their loops' own arithmetic, to the bit (docs/solver-notes.md,
 * "The length kernel in WebAssembly" and the sections after it). Their bytes come from scripts/build-kernels.mjs. Where
 * WebAssembly, its lanes or its compilation are not allowed (an old browser, a page whose content security policy
 * forbids it), the solver keeps the JavaScript loops.
 */
import { KERNELS } from './wasm-kernels-bytes';

/** The kernels' entry points on one memory; every array argument is a byte address in that memory. */
export interface WasmKernels {
  /**
   * Projects the free edges whose records are the words `j0..j1` (four a record) of the records at byte `records`,
   * on the positions at byte `positions`, each end moving by `share` (twice the stiffness) times the Padé error.
   */
  free(positions: number, records: number, share: number, j0: number, j1: number): void;
  /**
   * Projects the held edges of records `j0..j1` as projectHeldEdges does: `half` is half the stiffness, `bulge` the
   * skin's, `slack` the band's lower end (1 - pretension); the bulge directions lie at byte `directions`.
   */
  held(positions: number, records: number, directions: number, half: number, bulge: number, slack: number, j0: number, j1: number): void;
  /**
   * Projects the first ring's bending of list entries `r0..r1` in pass `pass`, as projectBendingPart does: the
   * positions, rest normals, neighbour starts and offsets, constraint at rest, gains, inverse degrees, passes and the
   * list at their byte addresses.
   */
  bend(
    positions: number,
    normals: number,
    starts: number,
    offsets: number,
    atRest: number,
    gains: number,
    inverse: number,
    passes: number,
    list: number,
    r0: number,
    r1: number,
    pass: number,
  ): void;
  /** The second ring's steps and moves of region entries `k0..k1` (the first half of projectSecondRingPart). */
  ringSteps(
    positions: number,
    normals: number,
    region: number,
    starts: number,
    offsets: number,
    inverse: number,
    atRest: number,
    gains: number,
    moves: number,
    steps: number,
    k0: number,
    k1: number,
  ): void;
  /**
   * Projects the orientation of listed triangles `t0..t1` as projectOrientationPart does (`mode` one of its modes,
   * `floor` its share of the bound); returns 1 if a triangle was more than a hair under its bound, else 0.
   */
  orient(
    positions: number,
    corners: number,
    frames: number,
    unchecked: number,
    watched: number,
    vertexTriangleStart: number,
    vertexTriangles: number,
    listed: number,
    t0: number,
    t1: number,
    mode: number,
    floor: number,
  ): number;
  /**
   * Projects the position and muscle constraints of region entries `k0..k1` as projectPositions does (the position
   * stiffness, the extra stiffness of skin sunk in, the muscle stiffness).
   */
  positions(
    positions: number,
    rest: number,
    normals: number,
    targets: number,
    weights: number,
    normalWeights: number,
    region: number,
    stiffness: number,
    extra: number,
    muscleStiffness: number,
    k0: number,
    k1: number,
  ): void;
  /** Each region vertex of entries `k0..k1` takes its step less its rings' moves (the second half). */
  ringGather(
    positions: number,
    normals: number,
    region: number,
    starts: number,
    offsets: number,
    reach: number,
    moves: number,
    steps: number,
    k0: number,
    k1: number,
  ): void;
  /**
   * Projects the collisions of listed candidates `k0..k1` against one collider as projectCollisions does: the
   * positions, the collider's shape, the list, and the candidates' vertices, clearances and sides at their byte
   * addresses.
   */
  collide(
    positions: number,
    shape: number,
    list: number,
    vertices: number,
    clearances: number,
    sides: number,
    k0: number,
    k1: number,
  ): void;
  /** Adds the area-weighted normals of listed triangles `t0..t1` to their corners' as addFaceNormals does. */
  faces(positions: number, corners: number, normals: number, t0: number, t1: number): void;
  /** Scales the normals of list entries `k0..k1` to unit length as normalize does. */
  units(normals: number, vertices: number, k0: number, k1: number): void;
}

/** The compiled modules for a plain and a shared memory; null where they cannot be compiled, undefined before. */
const modules: (WebAssembly.Module | null | undefined)[] = [undefined, undefined];
/** Each memory's instance, made once per thread. */
const instances = new WeakMap<WebAssembly.Memory, WasmKernels>();

/** Whether `memory` is a shared WebAssembly memory (its buffer a SharedArrayBuffer). */
function isSharedMemory(memory: WebAssembly.Memory): boolean {
  return typeof SharedArrayBuffer !== 'undefined' && memory.buffer instanceof SharedArrayBuffer;
}

/** The byte of the memory import's limits flags in a module's binary: after `memory` and its kind; -1 if none. */
function importFlags(bytes: Uint8Array): number {
  const name = [6, 0x6d, 0x65, 0x6d, 0x6f, 0x72, 0x79, 2, 3];
  for (let i = 0; i + name.length <= bytes.length; i++) {
    let k = 0;
    while (k < name.length && bytes[i + k] === name[k]) k++;
    if (k === name.length) return i + name.length - 1;
  }
  return -1;
}

/** The kernels' module for a plain or shared memory; null where this runtime cannot compile it. */
export function kernelModule(shared: boolean): WebAssembly.Module | null {
  const k = shared ? 1 : 0;
  if (modules[k] !== undefined) return modules[k];
  modules[k] = null;
  try {
    if (typeof WebAssembly === 'undefined' || typeof atob === 'undefined') return null;
    const text = atob(KERNELS);
    const bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
    if (!shared) {
      // The binary imports a shared memory; a plain one differs only in the import's limits flags (shared and a
      // maximum, 3, against a maximum alone, 1), which follow the import's name and kind (2, a memory).
      const at = importFlags(bytes);
      if (at < 0) return null;
      bytes[at] = 1;
    }
    // A small module compiles synchronously on any thread; validate first so that a runtime without the lanes says
    // so instead of throwing.
    if (WebAssembly.validate(bytes)) modules[k] = new WebAssembly.Module(bytes);
  } catch {
    modules[k] = null;
  }
  return modules[k];
}

/** The kernels on `memory` (made on first use in this thread); null where they cannot be made. */
export function wasmKernels(memory: WebAssembly.Memory): WasmKernels | null {
  const known = instances.get(memory);
  if (known) return known;
  const module = kernelModule(isSharedMemory(memory));
  if (!module) return null;
  try {
    const instance = new WebAssembly.Instance(module, { env: { memory } });
    const kernels = instance.exports as unknown as WasmKernels;
    instances.set(memory, kernels);
    return kernels;
  } catch {
    return null;
  }
}
