/**
 * Records a short clip of a softface page with `face.recordVideo` (frame by frame, see docs/video.md):
 *   node scripts/record-clip.mjs <url> <out.webm> [width] [height] [fps] [--timeline <file.json>]
 * Start the app first (`npm start`, or `npm run build && npm run preview`). Without `--timeline` it records a smile
 * that turns into raised brows. The page's canvas is the clip's size, so the clip frames the head as the page does.
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { launchBrowser, openApp } from './browser.mjs';

const argv = process.argv.slice(2);
const timelineIndex = argv.indexOf('--timeline');
const timelineFile = timelineIndex >= 0 ? argv.splice(timelineIndex, 2)[1] : undefined;
const [url, out, width = '480', height = '360', fps = '15'] = argv;
if (!url || !out) {
  console.error('usage: node scripts/record-clip.mjs <url> <out.webm> [width] [height] [fps] [--timeline <file.json>]');
  process.exit(1);
}

const timeline = timelineFile
  ? JSON.parse(readFileSync(timelineFile, 'utf8'))
  : {
      format: 'softface-timeline',
      version: 1,
      duration: 4,
      actions: [
        { target: 'AU12', start: 0.2, intensity: 0.9, onset: 0.6, apex: 0.8, offset: 0.6 },
        { target: 'AU6', start: 0.3, intensity: 0.6, onset: 0.6, apex: 0.7, offset: 0.6 },
        { target: 'AU1', start: 2.1, intensity: 1, onset: 0.4, apex: 0.6, offset: 0.6 },
        { target: 'AU2', start: 2.1, intensity: 1, onset: 0.4, apex: 0.6, offset: 0.6 },
        { target: 'AU5', start: 2.2, intensity: 0.6, onset: 0.3, apex: 0.5, offset: 0.5 },
      ],
    };

const browser = await launchBrowser();
try {
  const page = await browser.newPage({ viewport: { width: Number(width), height: Number(height) } });
  page.on('pageerror', (e) => console.error(`page error: ${e.message}`));
  await openApp(page, url);
  const bytes = await page.evaluate(
    async ({ timeline, width, height, fps }) => {
      const blob = await window.face.recordVideo({ timeline, width, height, fps });
      return Array.from(new Uint8Array(await blob.arrayBuffer()));
    },
    { timeline, width: Number(width), height: Number(height), fps: Number(fps) },
  );
  writeFileSync(out, new Uint8Array(bytes));
  console.log(`wrote ${out} (${bytes.length} bytes)`);
} finally {
  await browser.close();
}
