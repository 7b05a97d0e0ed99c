import { readdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { expect, test } from './fixtures';
import { STATIC_ORIGIN, STRICT_CSP, serveStatic } from './static-host';

declare global {
  interface Window {
    /** Content security policy violations the page reported. */
    violations: string[];
  }
}

test('the standalone module runs on a static host under a strict content security policy, without isolation', async ({ page }) => {
  const asked = await serveStatic(page, { 'Content-Security-Policy': STRICT_CSP });
  await page.addInitScript(() => {
    window.violations = [];
    document.addEventListener('securitypolicyviolation', (e) => window.violations.push(`${e.violatedDirective}: ${e.blockedURI}`));
  });
  await page.goto(`${STATIC_ORIGIN}/standalone.html`);
  await expect(page.locator('html')).toHaveAttribute('data-state', 'ready');
  const r = await page.evaluate(async () => {
    const element = document.querySelector('soft-face')!;
    if (!element.face) await new Promise((resolve) => element.addEventListener('ready', resolve, { once: true }));
    const box = document.getElementById('box')!;
    const face = await window.softface.createFace(box, { resolution: 'low' });
    face.setActionUnit('AU26', 1);
    await face.settle(45_000);
    const { rest, positions } = face.getSkin();
    let moved = 0;
    for (let i = 0; i < rest.length; i++) moved = Math.max(moved, Math.abs(positions[i] - rest[i]));
    return {
      // The page's own style wins over the element's default size.
      size: [element.offsetWidth, element.offsetHeight],
      isolated: crossOriginIsolated,
      modes: [element.face!.stats().mode, face.stats().mode],
      au12: element.face!.getActionUnits().AU12L,
      moved,
      violations: window.violations,
    };
  });
  // Without COOP/COEP the faces solve in transfer mode, and move: AU26 opens the jaw by centimetres.
  expect(r.size).toEqual([320, 240]);
  expect(r.isolated).toBe(false);
  expect(r.modes).toEqual(['transfer', 'transfer']);
  expect(r.au12).toBe(0.8);
  expect(r.moved).toBeGreaterThan(0.005);
  // Nothing the policy forbids was tried: no eval, no inline style or script, workers only from Blob URLs.
  expect(r.violations).toEqual([]);
  // The host served the page, its script, the module with its chunks (three.js, and the skin worker's, which starts it
  // from a Blob URL: no worker file), and the models, rig and lighting beside it: the module found them from its own
  // URL. Chunks by name without their hash.
  expect([...new Set(asked.map((path) => path.replace(/-[\w-]{8}\.js$/, '.js')))].sort()).toEqual([
    '/lib/environment/room.pmrem',
    '/lib/face-options.js',
    '/lib/head-pose.js',
    '/lib/models/head-low.glb',
    '/lib/neck-carry.js',
    '/lib/rigs/default.json',
    '/lib/softface.standalone.js',
    '/lib/spawn-skin-worker-inline.js',
    '/lib/three.core.js',
    '/standalone.css',
    '/standalone.html',
    '/standalone.js',
  ]);
});

test('no module of the library build evaluates code from strings', () => {
  const folder = fileURLToPath(new URL('../dist-lib/', import.meta.url));
  const modules = readdirSync(folder).filter((f) => f.endsWith('.js'));
  expect(modules).toEqual(expect.arrayContaining(['softface.js', 'element.js', 'softface.standalone.js']));
  for (const name of modules) {
    const code = readFileSync(folder + name, 'utf8');
    // The inlined worker's code is a string too: searching the whole file covers it.
    expect(code, name).not.toMatch(/\beval\s*\(|new\s+Function\s*\(|\bFunction\s*\(\s*["'`]/);
    expect(code, name).not.toMatch(/setTimeout\s*\(\s*["'`]|setInterval\s*\(\s*["'`]/);
  }
});
