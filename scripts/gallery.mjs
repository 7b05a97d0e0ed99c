/**
 * Contact sheet of every Action Unit and preset at full intensity: `npm run gallery [-- low|medium|high] [options]`;
 * resolutions joined by commas (`medium,high`) give a row of the same expressions per head.
 * Builds the app, serves it, sets each expression through `window.face`, waits for the skin to settle and writes
 * docs/images/gallery.jpg (tiles labelled with the expression; "not settled" if it did not within the time limit).
 *
 * Options:
 *   --only AU1+AU2,AU4,happiness   these expressions only (`+` combines Action Units and presets in one tile)
 *   --region forehead|brows|eyes|nose|mouth|chin|face   a close-up of part of the face (default: face)
 *   --identities                   each stock identity (face.listIdentities()), neutral and with happiness, in place of
 *                                  the expressions (docs/images/identities.jpg)
 *   --columns N                    tiles per row (default 6)
 *   --out docs/images/name.jpg     where to write the sheet
 *   --no-build                     serve the last build (dist/) as it is
 */
import { spawn, execSync } from 'node:child_process';
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname } from 'node:path';
import { launchBrowser, openApp } from './browser.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(`--${name}`);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
};
const resolutions = (args[0] && !args[0].startsWith('--') ? args[0] : 'medium').split(',');
const resolution = resolutions.join(' and ');
const only = option('only', '').split(',').filter(Boolean);
const out = option('out', args.includes('--identities') ? 'docs/images/identities.jpg' : 'docs/images/gallery.jpg');
const columns = Number(option('columns', '6'));
/** Page areas (CSS pixels of the 640 x 640 view) framing parts of the face; close-ups are shot at 3x. */
const REGIONS = {
  face: { x: 170, y: 150, width: 300, height: 390, scale: 1 },
  forehead: { x: 240, y: 165, width: 160, height: 90, scale: 3 },
  brows: { x: 250, y: 228, width: 140, height: 80, scale: 3 },
  eyes: { x: 220, y: 248, width: 200, height: 80, scale: 3 },
  nose: { x: 260, y: 270, width: 120, height: 110, scale: 3 },
  mouth: { x: 245, y: 371, width: 150, height: 100, scale: 3 },
  chin: { x: 255, y: 420, width: 130, height: 100, scale: 3 },
};
const regionName = option('region', 'face');
const region = REGIONS[regionName];
if (!region) throw new Error(`--region must be one of ${Object.keys(REGIONS).join(', ')}, got ${regionName}`);
const TILE = { width: region.width * region.scale, height: region.height * region.scale };
const PORT = 4180;
const SETTLE_MS = 60_000;

if (!args.includes('--no-build')) execSync('npx vite build', { stdio: 'ignore' });
const server = spawn('npx', ['vite', 'preview', '--host', '127.0.0.1', '--port', String(PORT), '--strictPort'], {
  stdio: 'ignore',
  detached: true,
});
const browser = await launchBrowser();
try {
  const page = await browser.newPage({ viewport: { width: 640, height: 640 }, deviceScaleFactor: region.scale });
  const tiles = [];
  let items = null;
  for (const head of resolutions) {
    // Tried again while the server starts.
    await openApp(page, `http://127.0.0.1:${PORT}/?resolution=${head}`, { timeout: 120_000, retries: 51, retryMs: 200 });
    // The page's panel column (280 px on the right) would cover part of the face in this 640 px window.
    await page.addStyleTag({ content: '.softface-panels, #status { display: none !important; }' });
    // With --identities an item is `<identity>|<expression>`.
    items ??= args.includes('--identities')
      ? (await page.evaluate(() => window.face.listIdentities().map((i) => i.name))).flatMap((n) => [`${n}|neutral`, `${n}|happiness`])
      : only.length > 0
        ? only
        : await page.evaluate(() => [
            'neutral',
            ...window.face.listActionUnits().map((au) => au.id),
            ...window.face.listPresets().map((p) => p.name),
          ]);
    for (const entry of items) {
      const [person, item] = entry.includes('|') ? entry.split('|') : [null, entry];
      if (person) await page.evaluate((person) => window.face.setIdentity(person), person);
      const settled = await page.evaluate(
        async ({ item, timeout }) => {
          const face = window.face;
          face.reset();
          for (const part of item.split('+')) {
            if (part.startsWith('AU')) face.setActionUnit(part, 1);
            else if (part !== 'neutral') face.applyPreset(part, 1);
          }
          try {
            await face.settle(timeout);
            return true;
          } catch {
            return false;
          }
        },
        { item, timeout: SETTLE_MS },
      );
      // The tile is what face.savePNG draws (a still of the newest skin, as a picture is saved), not a screenshot:
      // after the change, the page's own frames may still be at the moving face's lower resolution, and a screenshot
      // taken before that frame was drawn showed it, jagged (the neutral tile, right after the page opened).
      const png = await page.evaluate(
        async ({ region, tile }) => {
          const whole = await createImageBitmap(await window.face.savePNG());
          // After savePNG, whose draw marks the face's canvas (a page may not have drawn it yet before).
          const canvas = document.querySelector('canvas[data-quality]');
          // The picture's pixels per CSS pixel (the view caps its pixel ratio at 2; close-ups are scaled up to the tile).
          const s = whole.width / canvas.clientWidth;
          const picture = await createImageBitmap(whole, region.x * s, region.y * s, region.width * s, region.height * s);
          const out = document.createElement('canvas');
          out.width = tile.width;
          out.height = tile.height;
          const ctx = out.getContext('2d');
          ctx.imageSmoothingQuality = 'high';
          ctx.drawImage(picture, 0, 0, tile.width, tile.height);
          return out.toDataURL('image/png').split(',')[1];
        },
        { region, tile: TILE },
      );
      const named = person ? (item === 'neutral' ? person : item) : item;
      const label = resolutions.length > 1 ? `${named}, ${head} head` : named;
      tiles.push({ label: settled ? label : `${label} (not settled)`, data: png });
      console.log(`${entry}: ${settled ? 'settled' : 'not settled'}`);
    }
  }
  const sheet = await page.evaluate(
    async ({ tiles, tile, columns }) => {
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
    { tiles, tile: TILE, columns: resolutions.length > 1 ? items.length : Math.min(columns, tiles.length) },
  );
  mkdirSync(dirname(out), { recursive: true });
  writeFileSync(out, Buffer.from(sheet, 'base64'));
  console.log(`wrote ${out} (${tiles.length} expressions, ${resolution} head)`);
} finally {
  await browser.close();
  process.kill(-server.pid);
}
