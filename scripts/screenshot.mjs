/**
 * Screenshots a softface page once its head is loaded:
 *   node scripts/screenshot.mjs <url> <out.png> [width] [height] [--head <file.glb|.gltf|.obj>]
 * Start the app first (`npm start`, or `npm run build && npm run preview`). `--head` loads that head into the page's
 * face first (`face.loadHead`), the expression in the URL carrying over to it.
 */
import { readFileSync } from 'node:fs';
import { basename } from 'node:path';
import { finishedPicture, launchBrowser, openApp } from './browser.mjs';

const argv = process.argv.slice(2);
const headIndex = argv.indexOf('--head');
const headFile = headIndex >= 0 ? argv.splice(headIndex, 2)[1] : undefined;
const [url, out, width = '1024', height = '768'] = argv;
if (!url || !out) {
  console.error('usage: node scripts/screenshot.mjs <url> <out.png> [width] [height]');
  process.exit(1);
}
const browser = await launchBrowser();
try {
  const page = await browser.newPage({ viewport: { width: Number(width), height: Number(height) } });
  page.on('pageerror', (e) => console.error(`page error: ${e.message}`));
  await openApp(page, url);
  if (headFile) {
    const bytes = [...readFileSync(headFile)];
    await page.evaluate(async ({ name, bytes }) => window.face.loadHead(new File([new Uint8Array(bytes)], name)), {
      name: basename(headFile),
      bytes,
    });
  }
  // Let the skin settle first, so that an expression given in the URL hash is shown finished.
  await page.evaluate(() => window.face?.settle?.(60_000));
  await finishedPicture(page);
  await page.screenshot({ path: out });
  console.log(`wrote ${out}`);
} finally {
  await browser.close();
}
