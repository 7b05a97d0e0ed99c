/**
 * Pictures and render timing of the skin, eyes and teeth: `node scripts/look.mjs [--bench] [--shots] [--no-build] [--port N]`.
 * Builds the app, serves it and, in headless Chromium at 1024 x 768 with the medium head:
 *   --shots  writes docs/images/neutral.png (the neutral face) and docs/images/closeup-wrinkles.png (forehead and
 *            eyes at twice the pixel density, brows raised by AU1 + AU2 so the solver folds the forehead);
 *   --bench  prints `face.measureRender(100)` three times with the brows and lashes and three times without: main-thread
 *            ms per `renderer.render`, ms to pose the hair, and `renderer.info`.
 */
import { execSync, spawn } from 'node:child_process';
import { launchBrowser, openApp } from './browser.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(`--${name}`);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
};
const PORT = Number(option('port', '4375'));
const VIEWPORT = { width: 1024, height: 768 };
/** CSS pixels of the close-up: forehead and eyes, shot at 2x so the picture is 1024 x 768. */
const CLOSEUP = { x: 256, y: 150, width: 512, height: 384 };

if (!args.includes('--no-build')) execSync('npx vite build', { stdio: 'ignore' });
const server = spawn('npx', ['vite', 'preview', '--host', '127.0.0.1', '--port', String(PORT), '--strictPort'], {
  stdio: 'ignore',
  detached: true,
});
const browser = await launchBrowser();

/** Opens the page (retrying while the server starts) and waits for the head. */
async function open(deviceScaleFactor) {
  const page = await browser.newPage({ viewport: VIEWPORT, deviceScaleFactor });
  page.on('pageerror', (e) => console.error(`page error: ${e.message}`));
  page.on('console', (m) => m.type() === 'error' && console.error(`console error: ${m.text()}`));
  await openApp(page, `http://127.0.0.1:${PORT}/?resolution=medium`, { retries: 51, retryMs: 300 });
  // The panels would cover part of the face in close-ups; pictures show the head alone.
  await page.addStyleTag({ content: '.lil-gui { display: none !important; }' });
  return page;
}

try {
  if (args.includes('--shots')) {
    const page = await open(1);
    await page.evaluate(() => window.face.settle(60_000));
    await finishedPicture(page);
    await page.screenshot({ path: 'docs/images/neutral.png' });
    console.log('wrote docs/images/neutral.png');
    await page.close();

    const close = await open(2);
    await close.evaluate(async () => {
      window.face.setActionUnit('AU1', 1);
      window.face.setActionUnit('AU2', 1);
      await window.face.settle(60_000);
    });
    await finishedPicture(close);
    await close.screenshot({ path: 'docs/images/closeup-wrinkles.png', clip: CLOSEUP });
    console.log('wrote docs/images/closeup-wrinkles.png');
    await close.close();
  }
  if (args.includes('--bench')) {
    const page = await open(1);
    await page.evaluate(() => window.face.settle(60_000));
    // With the brows and lashes as they are, then without them: their cost is the difference in render time plus
    // the time to pose them (`hairMeanMs`, `hairMedianMs`).
    for (const hair of [true, false]) {
      await page.evaluate((on) => window.face.setAppearance({ brows: on, lashes: on }), hair);
      for (let run = 0; run < 3; run++)
        console.log(`hair ${hair ? 'on ' : 'off'}`, JSON.stringify(await page.evaluate(() => window.face.measureRender(100))));
    }
    await page.close();
  }
} finally {
  await browser.close();
  process.kill(-server.pid);
}
