import { execFileSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, rmSync, statSync, symlinkSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Page } from '@playwright/test';
import { build } from 'vite';
import { expect, test } from './fixtures';

const project = fileURLToPath(new URL('..', import.meta.url));

let tarball: string | undefined;

/** The package as `npm pack` makes it, once per test worker (each app unpacks its own copy). */
function packed(): string {
  if (tarball && existsSync(tarball)) return tarball;
  const folder = mkdtempSync(join(tmpdir(), 'softface-pack-'));
  process.once('exit', () => rmSync(folder, { recursive: true, force: true }));
  const name = execFileSync('npm', ['pack', '--ignore-scripts', '--silent', '--pack-destination', folder], {
    cwd: project,
    encoding: 'utf8',
  })
    .trim()
    .split('\n')
    .pop()!;
  tarball = join(folder, name);
  return tarball;
}

/**
 * A fresh copy of one of the project's examples (`examples/<name>`) with the package installed as `npm pack` makes it
 * (of the library `npm test` has just built), unpacked into its node_modules beside three.js, its one peer dependency,
 * and the example's own dependencies named in `linked` (such as react), both linked from the project's node_modules.
 */
export function packedApp(example: string, linked: readonly string[] = []): string {
  const app = mkdtempSync(join(tmpdir(), `softface-${example}-`));
  // What a developer's own runs of the example left there is not part of it.
  cpSync(join(project, 'examples', example), app, { recursive: true, filter: (path) => !/[\\/](node_modules|dist)$/.test(path) });
  const installed = join(app, 'node_modules', 'softface');
  mkdirSync(installed, { recursive: true });
  execFileSync('tar', ['-xzf', packed(), '-C', installed, '--strip-components=1']);
  for (const name of ['three', ...linked]) {
    symlinkSync(join(project, 'node_modules', name), join(app, 'node_modules', name), 'dir');
  }
  return app;
}

/** How long an example app's install and build may take on a loaded machine (a hook's timeout is the config's otherwise). */
export const BUILD_TIMEOUT_MS = 180_000;

/**
 * A Vite example with the package installed (see `packedApp`), built once before the file's tests and removed after
 * them: returns the getter of its folder (the build is in its `dist/`).
 */
export function builtViteApp(example: string, linked: string[] = []): () => string {
  let app = '';
  test.beforeAll(async () => {
    // A hook's timeout is the config's, not the describe's.
    test.setTimeout(BUILD_TIMEOUT_MS);
    app = packedApp(example, linked);
    await build({
      root: app,
      logLevel: 'silent',
      configFile: join(app, 'vite.config.js'),
      build: { outDir: join(app, 'dist'), target: 'es2022' },
    });
  });
  test.afterAll(() => {
    if (app) rmSync(app, { recursive: true, force: true });
  });
  return () => app;
}

/** Every file under `dir`. */
export function filesUnder(dir: string): string[] {
  const out: string[] = [];
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) out.push(...filesUnder(path));
    else out.push(path);
  }
  return out;
}

/** The page's failed requests and error responses from now on (`url: reason`), gathered as they happen. */
export function failedRequests(page: Page): string[] {
  const failed: string[] = [];
  page.on('requestfailed', (r) => failed.push(`${r.url()}: ${r.failure()?.errorText}`));
  page.on('response', (r) => {
    if (r.status() >= 400) failed.push(`${r.url()}: ${r.status()}`);
  });
  return failed;
}

/**
 * Answers `page`'s requests to `origin` as a plain static host would (no COOP/COEP): each path from the file `fileOf`
 * names for it (`/` is `/index.html`), a missing one a 404.
 */
export async function serveFiles(page: Page, origin: string, fileOf: (path: string) => string): Promise<void> {
  await page.route(`${origin}/**`, (route) => {
    const path = decodeURIComponent(new URL(route.request().url()).pathname);
    const file = fileOf(path === '/' ? '/index.html' : path);
    if (!existsSync(file) || !statSync(file).isFile()) return route.fulfill({ status: 404, body: 'not found' });
    return route.fulfill({ path: file });
  });
}

/**
 * Serves `dir` to `page` at `origin` as a plain static host, opens it, and checks what a user would: the face shows
 * on a page that is not cross-origin isolated, AU12 moves its skin, the element starts too, and no request fails.
 */
export async function checkPackedApp(page: Page, origin: string, dir: string): Promise<void> {
  const failed = failedRequests(page);
  await serveFiles(page, origin, (path) => join(dir, path));
  await page.goto(`${origin}/`);
  await expect(page.locator('html')).toHaveAttribute('data-state', 'ready', { timeout: 120_000 });
  const moved = await page.evaluate(async () => {
    const face = window.face;
    await face.ready;
    const before = face.getSkin();
    face.setActionUnit('AU12', 1);
    await face.settle(60_000);
    const after = face.getSkin().positions;
    let most = 0;
    for (let i = 0; i < after.length; i++) most = Math.max(most, Math.abs(after[i] - before.rest[i]));
    return { isolated: crossOriginIsolated, mm: 1000 * most, vertices: before.rest.length / 3 };
  });
  expect(moved.isolated).toBe(false);
  expect(moved.vertices).toBe(4284);
  expect(moved.mm).toBeGreaterThan(2);
  await expect
    .poll(() => page.evaluate(() => (document.getElementById('element') as HTMLElement & { face?: unknown }).face !== undefined), {
      timeout: 120_000,
    })
    .toBe(true);
  expect(failed).toEqual([]);
}
