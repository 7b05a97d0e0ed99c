/** Where the solver's arrays live: plain memory, or shared memory so that a partner thread sees the same arrays. */
export type Memory = 'local' | 'shared';

/** A typed array of `length` elements, on a SharedArrayBuffer when `memory` is `shared`. */
export function allocate<T>(Type: { new (buffer: ArrayBufferLike): T; BYTES_PER_ELEMENT: number }, length: number, memory: Memory): T {
  const bytes = Type.BYTES_PER_ELEMENT * length;
  return new Type(memory === 'shared' ? new SharedArrayBuffer(bytes) : new ArrayBuffer(bytes));
}
