/**
 * The WebAssembly memory that holds what the solver's WebAssembly kernel reads and writes (the positions, the edge
 * records and the bulge directions), so that the kernel and the JavaScript loops share those arrays without a copy.
 */
import { EDGE_RECORD } from './constraint-lists';
import type { Memory } from './memory';
import type { SkinTopology } from './topology';
import { lengthKernelModule } from './wasm-lengths';

/** Bytes in a WebAssembly page. */
const WASM_PAGE = 65536;
/** Each array's start is a multiple of this (a 128-bit lane). */
const ALIGN = 16;
/** Room after the arrays: the held-edge kernel reads a whole group of four records past a list's last one. */
const TAIL = 64;

/** Each kernel memory by its buffer, so that a solver given positions finds the memory they lie in. */
const owners = new WeakMap<ArrayBufferLike, KernelMemory>();

/** One WebAssembly memory of a fixed size, handed out front to back; it never grows, so views on it stay valid. */
export class KernelMemory {
  private next = 0;

  private constructor(readonly memory: WebAssembly.Memory) {
    owners.set(memory.buffer, this);
  }

  /**
   * A memory with room for a skin's positions, edge records and bulge directions, shared when `memory` is `shared`; null where the
   * length kernel cannot run here (the solver then keeps its arrays in plain typed arrays and the JavaScript loops).
   */
  static forSkin(topology: SkinTopology, memory: Memory): KernelMemory | null {
    const shared = memory === 'shared';
    if (!lengthKernelModule(shared)) return null;
    const n = topology.vertexCount;
    const bytes = 4 * (3 * n + EDGE_RECORD * topology.restLength.length + 3 * n) + 3 * ALIGN + TAIL;
    const pages = Math.ceil(bytes / WASM_PAGE);
    try {
      return new KernelMemory(new WebAssembly.Memory({ initial: pages, maximum: pages, shared }));
    } catch {
      return null;
    }
  }

  /** The kernel memory `array` lies in, if any. */
  static of(array: ArrayBufferView): KernelMemory | null {
    return owners.get(array.buffer) ?? null;
  }

  /** A typed array of `length` elements from the memory's free room; null when too little is left. */
  allocate<T>(
    Type: { new (buffer: ArrayBufferLike, offset: number, length: number): T; BYTES_PER_ELEMENT: number },
    length: number,
  ): T | null {
    const start = Math.ceil(this.next / ALIGN) * ALIGN;
    const end = start + Type.BYTES_PER_ELEMENT * length;
    if (end + TAIL > this.memory.buffer.byteLength) return null;
    this.next = end;
    return new Type(this.memory.buffer, start, length);
  }
}
