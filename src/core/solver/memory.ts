/** Where the solver's arrays live: plain memory, or shared memory so that a partner thread sees the same arrays. */
export type Memory = 'local' | 'shared';

/** A typed array of `length` elements, on a SharedArrayBuffer when `memory` is `shared`. */
export function allocate<T>(Type: { new (buffer: ArrayBufferLike): T; BYTES_PER_ELEMENT: number }, length: number, memory: Memory): T {
  const bytes = Type.BYTES_PER_ELEMENT * length;
  return new Type(memory === 'shared' ? new SharedArrayBuffer(bytes) : new ArrayBuffer(bytes));
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
