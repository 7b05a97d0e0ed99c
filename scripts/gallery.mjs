/**
 * Contact sheet of every Action Unit and preset at full intensity: `npm run gallery [-- low|medium|high]`.
 * Builds the app, serves it, sets each expression through `window.face`, waits for the skin to settle and writes
 * docs/images/gallery.jpg (tiles labelled with the expression; "not settled" if it did not within the time limit).
 */
import { spawn, execSync } from 'node:child_process';
import { mkdirSync, writeFileSync } from 'node:fs';
import { chromium } from '@playwright/test';
import { chromiumPath } from './chromium-path.mjs';

const resolution = process.argv[2] ?? 'medium';
const PORT = 4180;
const TILE = { width: 300, height: 390 };
const SETTLE_MS = 30_000;

execSync('npx vite build', { stdio: 'ignore' });
const server = spawn('npx', ['vite', 'preview', '--host', '127.0.0.1', '--port', String(PORT), '--strictPort'], { stdio: 'ignore', detached: true });
const browser = await chromium.launch({
  executablePath: chromiumPath(),
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-background-networking', '--no-first-run'],
});
try {
  const page = await browser.newPage({ viewport: { width: 640, height: 640 } });
  for (let i = 0; ; i++) {
    try {
      await page.goto(`http://127.0.0.1:${PORT}/?resolution=${resolution}`);
      break;
    } catch (error) {
      if (i > 50) throw error;
      await new Promise((r) => setTimeout(r, 200));
    }
  }
  await page.evaluate(() => window.face.ready);
  const items = await page.evaluate(() => [
    'neutral',
    ...window.face.listActionUnits().map((au) => au.id),
    ...window.face.listPresets().map((p) => p.name),
  ]);
  const tiles = [];
  for (const item of items) {
    const settled = await page.evaluate(
      async ({ item, timeout }) => {
        const face = window.face;
        face.reset();
        if (item.startsWith('AU')) face.setActionUnit(item, 1);
        else if (item !== 'neutral') face.applyPreset(item, 1);
        try {
          await face.settle(timeout);
          return true;
        } catch {
          return false;
        }
      },
      { item, timeout: SETTLE_MS },
    );
    await page.waitForTimeout(200); // let the renderer show the newest frame
    const png = await page.screenshot({ clip: { x: 170, y: 150, width: TILE.width, height: TILE.height } });
    tiles.push({ label: settled ? item : `${item} (not settled)`, data: png.toString('base64') });
    console.log(`${item}: ${settled ? 'settled' : 'not settled'}`);
  }
  const sheet = await page.evaluate(
    async ({ tiles, tile }) => {
      const columns = 6;
      const label = 22;
      const canvas = document.createElement('canvas');
      canvas.width = columns * tile.width;
      canvas.height = Math.ceil(tiles.length / columns) * (tile.height + label);
      const ctx = canvas.getContext('2d');
      ctx.fillStyle = '#1d2024';
      ctx.fillRect(0, 0, canvas.width, canvas.height);
      ctx.font = '15px sans-serif';
      ctx.fillStyle = '#e8e6e3';
      for (let i = 0; i < tiles.length; i++) {
        const img = new Image();
        img.src = `data:image/png;base64,${tiles[i].data}`;
        await img.decode();
        const x = (i % columns) * tile.width;
        const y = Math.floor(i / columns) * (tile.height + label);
        ctx.drawImage(img, x, y + label);
        ctx.fillText(tiles[i].label, x + 8, y + 16);
      }
      return canvas.toDataURL('image/jpeg', 0.85).split(',')[1];
    },
    { tiles, tile: TILE },
  );
  mkdirSync('docs/images', { recursive: true });
  writeFileSync('docs/images/gallery.jpg', Buffer.from(sheet, 'base64'));
  console.log(`wrote docs/images/gallery.jpg (${tiles.length} expressions, ${resolution} head)`);
} finally {
  await browser.close();
  process.kill(-server.pid);
}
