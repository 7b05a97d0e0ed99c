import { BACKGROUND, expect, meanDistance, screenshotPatch, test, waitForHead } from './fixtures';

test('the page is cross-origin isolated and shows a lit head', async ({ page }) => {
  await page.goto('/');
  await waitForHead(page);
  expect(await page.evaluate(() => crossOriginIsolated)).toBe(true);
  await expect(page.locator('#status-isolation')).toHaveText('cross-origin isolated');
  await expect(page.locator('#status-model')).toContainText('medium head: 17,091 vertices');

  const png = await page.screenshot();
  const { width, height } = page.viewportSize()!;
  const centre = await screenshotPatch(page, png, width / 2, height / 2);
  const corner = await screenshotPatch(page, png, 20, 20);
  // The corner shows the background; the centre shows skin, far from it.
  expect(meanDistance(corner, BACKGROUND)).toBeLessThan(6);
  expect(meanDistance(centre, BACKGROUND)).toBeGreaterThan(150);
  // Skin-coloured: red above green above blue.
  const [r, g, b] = [0, 1, 2].map((k) => centre.reduce((s, p) => s + p[k], 0) / centre.length);
  expect(r).toBeGreaterThan(g);
  expect(g).toBeGreaterThan(b);
});

test('each resolution loads, with its vertex count', async ({ page }) => {
  for (const [resolution, vertices] of [
    ['low', '4,284'],
    ['high', '68,277'],
  ]) {
    await page.goto(`/?resolution=${resolution}`);
    await waitForHead(page);
    await expect(page.locator('#status-model')).toContainText(`${resolution} head: ${vertices} vertices`);
  }
});
