/**
 * The solver's WebAssembly kernels: the length passes' loops (projectFreeEdges, projectHeldEdges in length-kernels.ts)
 * four edges at a time in 128-bit lanes of 32-bit floats, about twice as fast as the JavaScript loops; both rings'
 * bending (projectBendingPart, projectSecondRingPart), the orientation passes (projectOrientationPart), the position
 * constraints (projectPositions), the collisions (projectCollisions), the normals (projectNormals) and the frame's
 * bookkeeping (startFramePart, relaxPart, recordStepsPart) one item at a time
 * in their loops' own arithmetic, to the bit (docs/solver-notes.md, "The length kernel in WebAssembly" and the sections
 * after it). Their bytes come from scripts/build-kernels.mjs, compiled in wasm-kernel-module.ts. Where WebAssembly, its
 * lanes or its compilation are not allowed (an old browser, a page whose content security policy forbids it), the
 * solver keeps the JavaScript loops.
 */
import type { PartArrays } from './part-arrays';

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
  /** The frame's start of region entries `k0..k1` as startFramePart does (`carry` 1 to carry the momentum). */
  start(
    positions: number,
    previous: number,
    normals: number,
    last: number,
    restart: number,
    share: number,
    vertices: number,
    beta: number,
    extra: number,
    carry: number,
    k0: number,
    k1: number,
  ): void;
  /** The relaxation of region entries `k0..k1` as relaxPart does, with its least share and its turns' window. */
  relax(
    positions: number,
    previous: number,
    last: number,
    share: number,
    calm: number,
    restart: number,
    vertices: number,
    cap: number,
    least: number,
    within: number,
    k0: number,
    k1: number,
  ): void;
  /** The moves of region entries `k0..k1` recorded as recordStepsPart does; returns the largest squared move. */
  steps(positions: number, previous: number, last: number, path: number, vertices: number, k0: number, k1: number): number;
}

/** Each memory's instance, made once per thread. */
const instances = new WeakMap<WebAssembly.Memory, WasmKernels>();

/**
 * The kernels a solver's passes run (made on first use in this thread from the arrays' memory and module); null where
 * the JavaScript loops run (no kernel memory, or an instance that cannot be made).
 */
export function wasmKernels(a: Pick<PartArrays, 'kernelMemory' | 'kernelModule'>): WasmKernels | null {
  const memory = a.kernelMemory;
  if (!memory || !a.kernelModule) return null;
  const known = instances.get(memory);
  if (known) return known;
  try {
    const instance = new WebAssembly.Instance(a.kernelModule, { env: { memory } });
    const kernels = instance.exports as unknown as WasmKernels;
    instances.set(memory, kernels);
    return kernels;
  } catch {
    return null;
  }
}
