import { expect, test } from './fixtures';
import { ISOLATION_HEADERS, STATIC_ORIGIN, serveStatic } from './static-host';

test("the ES modules run with the page's own three.js, and solve on shared memory where the host isolates", async ({ page }) => {
  const asked = await serveStatic(page, ISOLATION_HEADERS);
  await page.goto(`${STATIC_ORIGIN}/modules.html`);
  await expect(page.locator('html')).toHaveAttribute('data-state', 'ready');
  const r = await page.evaluate(async () => {
    const element = document.querySelector('soft-face')!;
    if (!element.face) await new Promise((resolve) => element.addEventListener('ready', resolve, { once: true }));
    const face = element.face!;
    await face.settle(45_000);
    const { rest, positions } = face.getSkin();
    let moved = 0;
    for (let i = 0; i < rest.length; i++) moved = Math.max(moved, Math.abs(positions[i] - rest[i]));
    // A second face with two solver workers: the partner worker is inlined in the skin worker too.
    const url = '/lib/softface.js';
    const lib = await import(url);
    const box = document.createElement('div');
    box.style.width = '200px';
    box.style.height = '150px';
    document.body.append(box);
    const second = await lib.createFace(box, { resolution: 'low', workers: 2 });
    second.setActionUnit('AU26', 1);
    await second.settle(45_000);
    const workers = second.stats().workers;
    second.dispose();
    return {
      isolated: crossOriginIsolated,
      mode: face.stats().mode,
      happiness: face.listPresets().find((p) => p.name === 'happiness')!.weight,
      moved,
      workers,
    };
  });
  expect(r).toMatchObject({ isolated: true, mode: 'shared', happiness: 1, workers: 2 });
  expect(r.moved).toBeGreaterThan(0.003);
  const files = [...new Set(asked)];
  // three.js came from the page's import map, once; the library brought no copy of its own and no worker file.
  expect(files.filter((f) => f.startsWith('/three/'))).toEqual(
    expect.arrayContaining([
      '/three/build/three.module.js',
      '/three/examples/jsm/loaders/GLTFLoader.js',
      '/three/examples/jsm/controls/OrbitControls.js',
    ]),
  );
  expect(files.filter((f) => f.startsWith('/lib/')).sort()).toEqual([
    '/lib/element.js',
    expect.stringMatching(/^\/lib\/embedded-face-[\w-]+\.js$/),
    '/lib/environment/room.pmrem',
    // Code the entry shares with the solver's own chunk (which a worker mode never fetches), named after one of its modules.
    expect.stringMatching(/^\/lib\/head-pose-[\w-]+\.js$/),
    '/lib/models/head-low.glb',
    '/lib/rigs/default.json',
    '/lib/softface.js',
    // The skin worker's code, fetched as the face starts.
    expect.stringMatching(/^\/lib\/spawn-skin-worker-inline-[\w-]+\.js$/),
  ]);
});
