import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, rmSync, statSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'vite';
import { expect, test } from './fixtures';

/**
 * The package as a web developer uses it: `npm pack` (of the library `npm test` has just built), unpacked into a
 * fresh Vite app's node_modules beside three.js, imported the ordinary way (`import { createFace } from 'softface'`,
 * `import 'softface/element'`), built by Vite with no configuration, and served without the isolation headers. The
 * face must show, an Action Unit must move it, and no request may fail: the head models, the rig and the environment
 * were found by the app's bundler through the package's `new URL('./…', import.meta.url)` and copied into the build.
 */
const project = fileURLToPath(new URL('..', import.meta.url));
const ORIGIN = 'http://localhost:4395';

test.describe.configure({ timeout: 240_000 });

let app: string;
let dist: string;
test.beforeAll(async () => {
  app = mkdtempSync(join(tmpdir(), 'softface-vite-app-'));
  // The library is already built (npm test builds it before the browser tests): pack it as it is.
  const tarball = execFileSync('npm', ['pack', '--ignore-scripts', '--silent', '--pack-destination', app], {
    cwd: project,
    encoding: 'utf8',
  })
    .trim()
    .split('\n')
    .pop()!;
  const installed = join(app, 'node_modules', 'softface');
  mkdirSync(installed, { recursive: true });
  execFileSync('tar', ['-xzf', join(app, tarball), '-C', installed, '--strip-components=1']);
  // Its one peer dependency, as the app would have installed it.
  symlinkSync(join(project, 'node_modules', 'three'), join(app, 'node_modules', 'three'), 'dir');
  writeFileSync(
    join(app, 'index.html'),
    '<!doctype html><html><body style="margin:0"><div id="face" style="width:480px;height:480px"></div>' +
      '<soft-face id="element" resolution="low" style="display:block;width:240px;height:240px"></soft-face>' +
      '<script type="module" src="./main.js"></script></body></html>',
  );
  writeFileSync(
    join(app, 'main.js'),
    "import { createFace } from 'softface';\nimport 'softface/element';\n" +
      "window.face = await createFace(document.getElementById('face'), { resolution: 'low' });\n" +
      "document.documentElement.dataset.state = 'ready';\n",
  );
  dist = join(app, 'dist');
  await build({ root: app, logLevel: 'silent', configFile: false, build: { outDir: dist, target: 'es2022' } });
});

test.afterAll(() => {
  if (app) rmSync(app, { recursive: true, force: true });
});

test('a fresh Vite app that imports the packed library builds, shows a face that moves, and fetches nothing missing', async ({ page }) => {
  // What the app's build holds: its own copies of the package's files, under hashed names.
  const files: string[] = [];
  const walk = (dir: string): void => {
    for (const name of readdirSync(dir)) (statSync(join(dir, name)).isDirectory() ? walk : (f: string) => files.push(f))(join(dir, name));
  };
  walk(dist);
  for (const stem of ['head-low', 'default', 'room'])
    expect(
      files.some((f) => f.includes(stem)),
      stem,
    ).toBe(true);

  const failed: string[] = [];
  page.on('requestfailed', (r) => failed.push(`${r.url()}: ${r.failure()?.errorText}`));
  page.on('response', (r) => {
    if (r.status() >= 400) failed.push(`${r.url()}: ${r.status()}`);
  });
  // A plain static host: the files as built, no COOP/COEP.
  await page.route(`${ORIGIN}/**`, (route) => {
    const path = decodeURIComponent(new URL(route.request().url()).pathname);
    const file = join(dist, path === '/' ? 'index.html' : path);
    if (!existsSync(file) || !statSync(file).isFile()) return route.fulfill({ status: 404, body: 'not found' });
    return route.fulfill({ path: file });
  });
  await page.goto(`${ORIGIN}/`);
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
  // The element from `softface/element` starts too, from the same copied files.
  await expect
    .poll(() => page.evaluate(() => (document.getElementById('element') as HTMLElement & { face?: unknown }).face !== undefined), {
      timeout: 120_000,
    })
    .toBe(true);
  expect(failed).toEqual([]);
});
