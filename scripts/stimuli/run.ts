/**
 * Renders a stimulus list: `npm run stimuli -- list.json out/ [Playwright options]`. The list is checked and expanded
 * here (see stimulus-list.ts), its manifest written to `out/manifest.csv`, and each stimulus becomes one Playwright
 * test (render.spec.ts), so Playwright's `--workers` and `--shard=i/n` spread a large list over cores and machines.
 * A stimulus whose file is already in `out/` is skipped: a run that stopped goes on where it was.
 */
import { spawnSync } from 'node:child_process';
import { mkdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { jsonSyntaxMessage } from '../../src/core/rig/json-text';
import { expandStimulusList, stimulusManifest } from './stimulus-list';

/** The plan the Playwright side reads, beside the rendered files. */
export const PLAN_FILE = '.stimuli-plan.json';
const MAX_LIST_BYTES = 5 * 1024 * 1024;

const [listPath, outDir, ...playwrightArgs] = process.argv.slice(2);
if (!listPath || !outDir) {
  console.error('usage: npm run stimuli -- <list.json> <out folder> [Playwright options, e.g. --workers=2 --shard=1/4]');
  process.exit(2);
}
const fail = (message: string): never => {
  console.error(message);
  process.exit(1);
};
let text = '';
try {
  if (statSync(listPath).size > MAX_LIST_BYTES) fail(`${listPath}: larger than ${MAX_LIST_BYTES / 1024 / 1024} MB`);
  text = readFileSync(listPath, 'utf8');
} catch (error) {
  fail(`${listPath}: cannot be read (${(error as Error).message})`);
}
let json: unknown;
try {
  json = JSON.parse(text);
} catch (error) {
  fail(`${listPath}: ${jsonSyntaxMessage(text, error)}`);
}
let stimuli: ReturnType<typeof expandStimulusList> = [];
try {
  stimuli = expandStimulusList(json, basename(listPath));
} catch (error) {
  fail((error as Error).message);
}
mkdirSync(outDir, { recursive: true });
writeFileSync(join(outDir, 'manifest.csv'), stimulusManifest(stimuli));
writeFileSync(join(outDir, PLAN_FILE), JSON.stringify(stimuli));
console.log(`${stimuli.length} stimuli; manifest: ${join(outDir, 'manifest.csv')}`);

const here = dirname(fileURLToPath(import.meta.url));
const result = spawnSync('npx', ['playwright', 'test', '-c', join(here, 'playwright.config.ts'), ...playwrightArgs], {
  stdio: 'inherit',
  env: { ...process.env, STIMULI_OUT: resolve(outDir) },
});
process.exit(result.status ?? 1);
