import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import { expect, test } from '@playwright/test';

/**
 * What a page downloads before its first face: the module it imports and every chunk that imports statically (the
 * workers, the panels, video encoding and decimation are chunks fetched when first used). The goals: the library's
 * entry at most 120 kB gzipped, the standalone module with three.js inside at most 350 kB (docs/embedding.md lists
 * every module's size).
 */
const LIB = fileURLToPath(new URL('../dist-lib/', import.meta.url));
const ENTRY_GZIP_LIMIT = 120_000;
const STANDALONE_GZIP_LIMIT = 350_000;
/** The stems of the chunks a face fetches only when first used. */
const LAZY = ['spawn-skin-worker-inline-', 'spawn-identity-worker-inline-', 'panels-', 'video-sinks-', 'meshoptimizer-'];

/** A module and the chunks it imports statically, each once (`import … from "./x.js"`, not `import("./x.js")`). */
function staticGraph(file: string, seen = new Set<string>()): Set<string> {
  if (seen.has(file)) return seen;
  seen.add(file);
  const text = readFileSync(LIB + file, 'utf8');
  for (const m of text.matchAll(/(?:^|[\n;])\s*(?:import|export)\b[^;(]*?\bfrom\s*"\.\/([^"]+)"|(?:^|[\n;])\s*import\s*"\.\/([^"]+)"/g))
    staticGraph(m[1] ?? m[2], seen);
  return seen;
}

const gzipped = (file: string): number => gzipSync(readFileSync(LIB + file)).length;

/** The gzip size of `module` with what it imports statically, after checking that the lazy parts are not in it. */
function firstDownload(module: string): number {
  const names = [...staticGraph(module)];
  for (const lazy of LAZY)
    expect(
      names.some((f) => f.startsWith(lazy)),
      lazy,
    ).toBe(false);
  const total = names.reduce((sum, f) => sum + gzipped(f), 0);
  console.log(`${module}: ${names.join(', ')}: ${(total / 1000).toFixed(1)} kB gzip`);
  return total;
}

test('the library entry with what it imports statically is at most 120 kB gzipped, the workers and the panels apart', () => {
  // The entry does reach the face (so the check measures the real thing).
  expect([...staticGraph('softface.js')].some((f) => f.startsWith('embedded-face-'))).toBe(true);
  expect(firstDownload('softface.js')).toBeLessThanOrEqual(ENTRY_GZIP_LIMIT);
});

test('the standalone module with what it imports statically is at most 350 kB gzipped, three.js inside', () => {
  // three.js is in it (so the check measures what a static page downloads): its WebGL renderer's class.
  const graph = [...staticGraph('softface.standalone.js')];
  expect(graph.some((f) => readFileSync(LIB + f, 'utf8').includes('WebGLRenderer'))).toBe(true);
  expect(firstDownload('softface.standalone.js')).toBeLessThanOrEqual(STANDALONE_GZIP_LIMIT);
});
