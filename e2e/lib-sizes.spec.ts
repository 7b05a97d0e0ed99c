import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import { expect, test } from '@playwright/test';

/**
 * What a page that imports the library downloads before its first face: the entry module and every chunk it imports
 * statically (the workers, the panels, video encoding and decimation are chunks fetched when first used). The goal:
 * at most 120 kB gzipped (docs/embedding.md lists every module's size).
 */
const LIB = fileURLToPath(new URL('../dist-lib/', import.meta.url));
const ENTRY_GZIP_LIMIT = 120_000;

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

test('the library entry with what it imports statically is at most 120 kB gzipped, the workers and the panels apart', () => {
  const entry = staticGraph('softface.js');
  const names = [...entry];
  // The entry does reach the face (so the check measures the real thing) and leaves the lazy parts out.
  expect(names.some((f) => f.startsWith('embedded-face-'))).toBe(true);
  for (const lazy of ['spawn-skin-worker-inline-', 'spawn-identity-worker-inline-', 'panels-', 'video-sinks-', 'meshoptimizer-'])
    expect(
      names.some((f) => f.startsWith(lazy)),
      lazy,
    ).toBe(false);
  const total = names.reduce((sum, f) => sum + gzipped(f), 0);
  console.log(`entry: ${names.join(', ')}: ${(total / 1000).toFixed(1)} kB gzip`);
  expect(total).toBeLessThanOrEqual(ENTRY_GZIP_LIMIT);
});
