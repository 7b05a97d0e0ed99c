import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchWithFakeCamera } from './fake-camera';
import { expect, test } from './fixtures';
import { failedRequests, serveFiles } from './packed-app';

/**
 * The live input's example pages on a static host with the library's build beside them as `softface/`:
 * `examples/openface-file` plays a picked OpenFace file, `examples/webcam` starts the tracker on a camera (here
 * Chromium's own fake one, a test pattern with no face in it) and says what it sees. Neither fetches anything missing.
 */
const ORIGIN = 'http://localhost:4399';
const root = (p: string): string => fileURLToPath(new URL(`../${p}`, import.meta.url));
const files = (example: string) => (path: string) =>
  path.startsWith('/softface/') ? join(root('dist-lib'), path.slice('/softface/'.length)) : join(root(`examples/${example}`), path);

test('the OpenFace example plays a picked file on the face and names a bad one’s line and column', async ({ page }) => {
  test.setTimeout(120_000);
  const failed = failedRequests(page);
  await serveFiles(page, ORIGIN, files('openface-file'));
  await page.goto(`${ORIGIN}/`);
  await expect(page.locator('#status')).toHaveText('pick an OpenFace CSV', { timeout: 90_000 });
  await expect.poll(() => page.evaluate(() => document.querySelector('soft-face')?.face?.isDisposed() === false)).toBe(true);
  const csv = [
    'frame, face_id, timestamp, confidence, success, AU12_r, AU26_r',
    '1, 0, 0.0, 0.98, 1, 0, 0',
    '2, 0, 1.5, 0.98, 1, 5, 2',
  ].join('\n');
  await page.locator('input[type=file]').setInputFiles({ name: 'clip.csv', mimeType: 'text/csv', buffer: Buffer.from(csv) });
  await expect(page.locator('#status')).toHaveText('clip.csv: 2 Action Units, 1.5 s');
  expect(await page.evaluate(() => document.querySelector('soft-face')!.face!.timelineState().playing)).toBe(true);
  await page
    .locator('input[type=file]')
    .setInputFiles({ name: 'bad.csv', mimeType: 'text/csv', buffer: Buffer.from(csv.replace('5, 2', 'x, 2')) });
  await expect(page.locator('#status')).toHaveText('bad.csv: line 3, column 6: AU12_r: expected a number, got "x"');
  expect(failed).toEqual([]);
});

test('the webcam example starts the tracker on a camera and says there is no face in the test pattern', async () => {
  test.setTimeout(120_000);
  const browser = await launchWithFakeCamera();
  try {
    const page = await browser.newPage({ viewport: { width: 600, height: 600 } });
    const failed = failedRequests(page);
    await serveFiles(page, ORIGIN, files('webcam'));
    await page.goto(`${ORIGIN}/`);
    await expect(page.locator('button')).toBeEnabled({ timeout: 90_000 });
    await page.locator('button').click();
    await expect(page.locator('#status')).toHaveText(/^no face in view · \d+ frames\/s$/, { timeout: 60_000 });
    expect(await page.evaluate(() => document.querySelector('soft-face')!.face!.trackingState().frames)).toBeGreaterThan(0);
    await page.locator('button').click();
    await expect(page.locator('#status')).toHaveText('off');
    expect(failed).toEqual([]);
  } finally {
    await browser.close();
  }
});
