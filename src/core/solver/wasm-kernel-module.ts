/**
 * The solver's WebAssembly kernels compiled from their bytes (scripts/build-kernels.mjs), once per thread that makes
 * solvers. A partner thread gets the compiled module with the solver's arrays (PartArrays.kernelModule) and so carries
 * no bytes of its own.
 */
import { KERNELS } from './wasm-kernels-bytes';

/** The compiled modules for a plain and a shared memory; null where they cannot be compiled, undefined before. */
const modules: (WebAssembly.Module | null | undefined)[] = [undefined, undefined];
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
