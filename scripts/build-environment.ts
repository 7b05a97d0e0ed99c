/**
 * Bakes the lighting environment the face is lit by: three.js's RoomEnvironment, prefiltered by its PMREMGenerator
 * exactly as the view would make it at start-up, read back level by level and written as
 * `public/environment/room.pmrem` (see src/render/environment.ts for the format). A browser without a GPU spends
 * seconds making it at every page load; the page loads these bytes instead.
 *   npm run build:environment
 */
import { createServer } from 'node:http';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import { launchBrowser } from './browser.mjs';
import { encodeEnvironment } from '../src/core/baked-environment';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const out = join(root, 'public/environment/room.pmrem');
/** The blur fromScene gets, as in HeadView: it softens the room's lamps into broad highlights. */
const SIGMA = 0.04;

const page = `<!doctype html><meta charset="utf-8">
<script type="importmap">{ "imports": { "three": "/three/build/three.module.js", "three/addons/": "/three/examples/jsm/" } }</script>
<script type="module">
  import { WebGLRenderer, PMREMGenerator, DataUtils, FloatType } from 'three';
  import { RoomEnvironment } from 'three/addons/environments/RoomEnvironment.js';
  window.bake = () => {
    const renderer = new WebGLRenderer();
    const pmrem = new PMREMGenerator(renderer);
    const room = new RoomEnvironment();
    const target = pmrem.fromScene(room, ${SIGMA});
    const gl = renderer.getContext();
    const mips = target.texture.mipmaps;
    const halves = [];
    for (let level = 0; level < mips.length; level++) {
      const size = mips[level].width;
      const pixels = new Float32Array(size * size * 4);
      for (let face = 0; face < 6; face++) {
        renderer.setRenderTarget(target, face, level);
        gl.readPixels(0, 0, size, size, gl.RGBA, gl.FLOAT, pixels);
        const h = new Uint16Array(pixels.length);
        for (let i = 0; i < pixels.length; i++) h[i] = DataUtils.toHalfFloat(pixels[i]);
        halves.push(Array.from(h));
      }
    }
    return { size: mips[0].width, levels: mips.length, halves };
  };
  document.documentElement.dataset.state = 'ready';
</script>`;

const server = createServer((req, res) => {
  const path = decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname);
  if (path === '/') return res.writeHead(200, { 'content-type': 'text/html' }).end(page);
  const file = normalize(join(root, 'node_modules', path));
  if (!file.startsWith(join(root, 'node_modules'))) return res.writeHead(403).end();
  let body: Buffer;
  try {
    body = readFileSync(file);
  } catch {
    return res.writeHead(404).end();
  }
  res.writeHead(200, { 'content-type': 'text/javascript' }).end(body);
});
await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
const browser = await launchBrowser();
try {
  const tab = await browser.newPage();
  tab.on('pageerror', (e) => console.error(`page error: ${e.message}`));
  const { port } = server.address() as { port: number };
  await tab.goto(`http://127.0.0.1:${port}/`);
  await tab.waitForFunction(() => document.documentElement.dataset.state === 'ready');
  const baked: { size: number; levels: number; halves: number[][] } = await tab.evaluate(() =>
    (window as unknown as { bake(): never }).bake(),
  );
  const { size, levels } = baked;
  const faces = Array.from({ length: levels }, (_, l) => Array.from({ length: 6 }, (_, f) => Uint16Array.from(baked.halves[6 * l + f])));
  const bytes = gzipSync(encodeEnvironment({ size, levels, faces }), { level: 9 });
  mkdirSync(dirname(out), { recursive: true });
  writeFileSync(out, bytes);
  console.log(`wrote public/environment/room.pmrem: ${size} px faces, ${levels} levels, ${bytes.length} bytes`);
} finally {
  await browser.close();
  server.close();
}
