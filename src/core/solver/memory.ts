/** Where the solver's arrays live: plain memory, or shared memory so that a partner thread sees the same arrays. */
export type Memory = 'local' | 'shared';

/** A typed array constructor, as `allocate` and a Room call it. */
export interface TypedArrayType<T> {
  new (buffer: ArrayBufferLike, offset?: number, length?: number): T;
  BYTES_PER_ELEMENT: number;
}

/** Memory that hands out typed arrays from its free room, null once too little is left (a KernelMemory). */
export interface Room {
  allocate<T>(Type: TypedArrayType<T>, length: number): T | null;
}

/**
 * A typed array of `length` elements: in `room` while it has room (the arrays the WebAssembly kernels read), else on
 * a SharedArrayBuffer when `memory` is `shared`, else on an ArrayBuffer.
 */
export function allocate<T>(Type: TypedArrayType<T>, length: number, memory: Memory, room: Room | null = null): T {
  const placed = room?.allocate(Type, length);
  if (placed) return placed;
  const bytes = Type.BYTES_PER_ELEMENT * length;
  return new Type(memory === 'shared' ? new SharedArrayBuffer(bytes) : new ArrayBuffer(bytes));
}

/** A copy of `array`, placed as `allocate` places a new one. */
export function allocateCopy<T extends Float32Array | Float64Array | Uint32Array | Int32Array | Uint8Array | Int8Array>(
  array: T,
  memory: Memory,
  room: Room | null = null,
): T {
  const out = allocate(array.constructor as unknown as TypedArrayType<T>, array.length, memory, room);
  out.set(array as never);
  return out;
}

/** Bytes in a page of memory, as the systems the solver runs on map it (4 KiB; larger pages are whole multiples). */
const PAGE_BYTES = 4096;

/**
 * Writes one byte of each page of `buffer`, its own value back (atomically: a shared buffer may be in use by another
 * thread), so that the system maps the pages now. A fresh buffer's pages are mapped at their first write, and on a
 * machine with slow page faults the first input's constraint lists and the first frame's output wrote the high head's
 * fresh pages for 40 to 60 ms (docs/page-notes.md, "The first input's pages").
 */
export function touchPages(buffer: ArrayBufferLike): void {
  const bytes = new Uint8Array(buffer);
  for (let i = 0; i < bytes.length; i += PAGE_BYTES) Atomics.add(bytes, i, 0);
}

/**
 * The buffers of every typed array reachable from `root` through its own fields, arrays and nested objects, at most
 * `depth` objects deep, each once: what touchPages should map for a solver.
 */
export function reachableBuffers(root: object, depth = 3): ArrayBufferLike[] {
  const seen = new Set<unknown>();
  const buffers: ArrayBufferLike[] = [];
  const visit = (value: unknown, level: number): void => {
    if (value === null || typeof value !== 'object' || seen.has(value)) return;
    seen.add(value);
    if (ArrayBuffer.isView(value)) {
      if (seen.has(value.buffer)) return;
      seen.add(value.buffer);
      buffers.push(value.buffer);
      return;
    }
    if (level >= depth) return;
    for (const field of Object.values(value)) visit(field, level + 1);
  };
  visit(root, 0);
  return buffers;
}
