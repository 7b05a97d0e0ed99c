/**
 * Screenshots a softface page once its head is loaded:
 *   node scripts/screenshot.mjs <url> <out.png> [width] [height]
 * Start the app first (`npm start`, or `npm run build && npm run preview`).
 */
import { chromium } from '@playwright/test';
import { chromiumPath } from './chromium-path.mjs';

const [url, out, width = '1024', height = '768'] = process.argv.slice(2);
if (!url || !out) {
  console.error('usage: node scripts/screenshot.mjs <url> <out.png> [width] [height]');
  process.exit(1);
}
const browser = await chromium.launch({
  executablePath: chromiumPath(),
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-background-networking', '--no-first-run'],
});
try {
  const page = await browser.newPage({ viewport: { width: Number(width), height: Number(height) } });
  page.on('pageerror', (e) => console.error(`page error: ${e.message}`));
  await page.goto(url);
  await page.waitForFunction(() => document.documentElement.dataset.state, null, { timeout: 60_000 });
  const state = await page.evaluate(() => document.documentElement.dataset.state);
  if (state !== 'ready') throw new Error(`the page reports "${state}": ${await page.locator('#status').innerText()}`);
  // Let the skin settle first, so that an expression given in the URL hash is shown finished.
  await page.evaluate(() => window.face?.settle?.(60_000));
  await page.waitForTimeout(500);
  await page.screenshot({ path: out });
  console.log(`wrote ${out}`);
} finally {
  await browser.close();
}
