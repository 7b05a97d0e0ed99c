import type { Page } from '@playwright/test';
import { openFace } from './face';
import { comparePictures, expect, test } from './fixtures';

/** The face at rest as the canvas shows it, as PNG bytes (the canvas only: no panels, no status bar). */
async function restPicture(page: Page): Promise<Buffer> {
  const base64 = await page.evaluate(async () => {
    await window.face.settle(30_000);
    const blob = await window.face.savePNG();
    const bytes = new Uint8Array(await blob.arrayBuffer());
    let text = '';
    for (let i = 0; i < bytes.length; i++) text += String.fromCharCode(bytes[i]);
    return btoa(text);
  });
  return Buffer.from(base64, 'base64');
}

test('the face is lit by the baked room environment, the very picture the view makes without it', async ({ page, browser }) => {
  test.setTimeout(90_000);
  const warnings: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'warning') warnings.push(m.text());
  });
  const requested: string[] = [];
  page.on('request', (r) => {
    if (r.url().endsWith('/environment/room.pmrem')) requested.push(r.url());
  });
  await openFace(page, '/?resolution=low');
  const baked = await restPicture(page);
  expect(requested).toHaveLength(1);
  expect(warnings.filter((w) => w.includes('lighting environment'))).toEqual([]);

  // A host that does not serve the file: the face says so and makes the environment itself.
  const other = await browser.newPage({ viewport: page.viewportSize()! });
  const otherWarnings: string[] = [];
  other.on('console', (m) => {
    if (m.type() === 'warning') otherWarnings.push(m.text());
  });
  await other.route('**/environment/room.pmrem', (route) => route.fulfill({ status: 404, body: 'not here' }));
  await openFace(other, '/?resolution=low');
  const made = await restPicture(other);
  expect(otherWarnings.some((w) => /lighting environment .*room\.pmrem could not be loaded \(HTTP 404\)/.test(w))).toBe(true);

  const difference = await comparePictures(page, baked, made);
  console.log(
    `baked vs made environment: mean difference ${difference.mean.toFixed(4)}, max ${difference.max}, ${difference.lit} lit pixels`,
  );
  expect(difference.sameSize).toBe(true);
  expect(difference.lit).toBeGreaterThan(20_000);
  // The file holds the generator's own half floats, so the pictures agree to the last rounding of a channel.
  expect(difference.max).toBeLessThanOrEqual(1);
  await other.close();
});
