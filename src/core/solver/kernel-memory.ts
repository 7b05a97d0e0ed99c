/**
 * The WebAssembly memory that holds what the solver's WebAssembly kernels read and write (the positions and muscle
 * inputs, the constraint lists, the bending's, orientation's, collisions' and normals' arrays, the frame's
 * bookkeeping), so that the kernels and the JavaScript loops share those arrays without a copy.
 */
import { COLLIDER_SHAPE } from './colliders';
import { EDGE_RECORD } from './constraint-lists';
import type { Memory, Room, TypedArrayType } from './memory';
import type { PartArrays } from './part-arrays';
import { ringStencils } from './second-ring';
import type { SkinTopology } from './topology';
import { kernelModule } from './wasm-kernel-module';

/** Bytes in a WebAssembly page. */
const WASM_PAGE = 65536;
/** Each array's start is a multiple of this (a 128-bit lane). */
const ALIGN = 16;
/** Room after the arrays: the held-edge kernel reads a whole group of four records past a list's last one. */
const TAIL = 64;
/** The arrays a skin's kernels read, at most: what forSkin makes room for (each start aligned). */
const KERNEL_ARRAYS = 51;
/** The colliders whose shapes forSkin makes room for (the default head has 18: two eyes and two rows of teeth). */
const COLLIDERS = 64;

/** A typed array type the kernel memory holds. */
export type KernelArray = Float32Array | Float64Array | Uint32Array | Int32Array | Uint8Array;

/** Each kernel memory by its buffer, so that a solver given positions finds the memory they lie in. */
const owners = new WeakMap<ArrayBufferLike, KernelMemory>();

/**
 * Sets which of a solver's passes run as WebAssembly, once, as the solver is made: every pass but the collisions
 * where every array they read and write lies in `kernel` (forSkin sizes it for them all; `p.kernelMemory` and
 * `p.kernelModule`, else null and the JavaScript loops run), and the collisions too where their candidates' arrays also
 * fit (`p.collisionKernel`).
 */
export function useKernels(p: PartArrays, kernel: KernelMemory | null): void {
  const r = p.secondRing;
  const t = p.triangles;
  const lengths = [p.positions, p.edges.ends, p.bulgeDirections, p.rest, p.targets, p.weights, p.normalWeights];
  const bending = [p.restNormals, p.neighbourStart, p.neighbourOffsets, p.bendRest, p.bendGain, p.inverseDegree, p.bendPasses];
  const ring = [p.bending.vertices, p.regionVertices, r.start, r.offsets, r.inverse, r.rest, r.gain, r.reach, r.ringMove, r.ownStep];
  const orientation = [t.corners, t.frames, p.unchecked, p.watched, p.vertexTriangleStart, p.vertexTriangles, p.listedTriangle];
  const normals = [p.normals, p.shadedTriangles.corners, p.shadedVertices];
  const frame = [p.previous, p.lastStep, p.relaxation, p.restart, p.calm, p.path];
  const held = kernel?.holds(...lengths, ...bending, ...ring, ...orientation, ...normals, ...frame) ? kernel : null;
  p.kernelMemory = held?.memory ?? null;
  p.kernelModule = held?.module ?? null;
  const candidates = [p.colliderShapes, p.colliderVertices, p.colliderClearance, p.colliderSide, p.activeCandidates];
  p.collisionKernel = held?.holds(...candidates) === true;
}

/** One WebAssembly memory of a fixed size, handed out front to back; it never grows, so views on it stay valid. */
export class KernelMemory implements Room {
  private next = 0;

  private constructor(
    readonly memory: WebAssembly.Memory,
    /** The kernels' module for this memory (see wasm-kernel-module.ts). */
    readonly module: WebAssembly.Module,
  ) {
    owners.set(memory.buffer, this);
  }

  /**
   * A memory with room for a skin's positions, edge records and bulge directions, for the bending's rest normals,
   * neighbours, constraint at rest, gains, inverse degrees, passes and list, for the second ring's arrays and the
   * region's vertex list, for the orientation's triangle lists, flags and vertex triangles, for the position
   * constraints' inputs, the normals and the collisions' candidates; shared when `memory` is `shared`. Null where the
   * kernels cannot run here (the solver then keeps its arrays in plain typed arrays and the JavaScript loops).
   */
  static forSkin(topology: SkinTopology, memory: Memory): KernelMemory | null {
    const shared = memory === 'shared';
    const module = kernelModule(shared);
    if (!module) return null;
    const n = topology.vertexCount;
    const edges = EDGE_RECORD * topology.restLength.length;
    const neighbours = topology.neighbourStart[n];
    const ring = ringStencils(topology).offsets.length;
    // Floats and words: positions, records, directions, normals, starts, offsets, gains, inverse degrees, the list
    // (two words a vertex); the second ring's starts, offsets, inverse sizes, gains, moves (three a vertex) and steps,
    // the region's vertices. Doubles: both rings' constraints at rest. Bytes: the passes, the second ring's reach.
    const first = 3 * n + edges + 3 * n + 3 * n + (n + 1) + neighbours + n + n + 2 * n;
    const second = n + 1 + ring + n + n + 3 * n + n + n;
    // The orientation's: corners (three a triangle), frames (four), places in the list, each vertex's triangles (CSR);
    // its unchecked and watched flags, a byte a triangle in whole words.
    const triangles = topology.triangles.length / 3;
    const orientation = 3 * triangles + 4 * triangles + triangles + (n + 1) + topology.vertexTriangles.length;
    const flags = 2 * 4 * Math.ceil(triangles / 4);
    // The position constraints': the rest positions, the muscles' targets, weights and normal weights.
    const positions = 3 * n + 3 * n + n + n;
    // The normals': the normals, the shaded triangles' corners (three a triangle), the shaded vertices.
    const normals = 3 * n + 3 * triangles + n;
    // The frame's bookkeeping: the previous places and last moves (three a vertex), the shares and ways; its turn
    // marks and calm counts are bytes.
    const frame = 3 * n + 3 * n + n + n;
    // The collisions': up to a candidate a vertex (the high head lists one for every third), each with its vertex,
    // its place in the frame's list, its clearance (words) and side (a byte), and up to COLLIDERS shapes. A skin with
    // more keeps its collisions in JavaScript (see useKernels).
    const collisions = 4 * 3 * n + n + 8 * COLLIDER_SHAPE * COLLIDERS;
    const bytes =
      4 * (first + second + orientation + positions + normals + frame) +
      8 * 2 * n +
      4 * n +
      flags +
      collisions +
      KERNEL_ARRAYS * ALIGN +
      TAIL;
    const pages = Math.ceil(bytes / WASM_PAGE);
    try {
      return new KernelMemory(new WebAssembly.Memory({ initial: pages, maximum: pages, shared }), module);
    } catch {
      return null;
    }
  }

  /** The kernel memory `array` lies in, if any: a solver whose positions lie in one runs its kernels there. */
  static of(array: ArrayBufferView): KernelMemory | null {
    return owners.get(array.buffer) ?? null;
  }

  /** `array` copied into `kernel` where it has room, else `array` itself. */
  static place<T extends KernelArray>(kernel: KernelMemory | null, array: T): T {
    return kernel?.copy(array) ?? array;
  }

  /** Whether every one of `arrays` lies in this memory. */
  holds(...arrays: ArrayBufferView[]): boolean {
    return arrays.every((array) => owners.get(array.buffer) === this);
  }

  /** A copy of `array` in the memory's free room; null when too little is left. */
  copy<T extends KernelArray>(array: T): T | null {
    const Type = array.constructor as unknown as TypedArrayType<T>;
    const out = this.allocate(Type, array.length);
    (out as KernelArray | null)?.set(array as never);
    return out;
  }

  /** A typed array of `length` elements from the memory's free room; null when too little is left. */
  allocate<T>(Type: TypedArrayType<T>, length: number): T | null {
    const start = Math.ceil(this.next / ALIGN) * ALIGN;
    const end = start + Type.BYTES_PER_ELEMENT * length;
    if (end + TAIL > this.memory.buffer.byteLength) return null;
    this.next = end;
    return new Type(this.memory.buffer, start, length);
  }
}
