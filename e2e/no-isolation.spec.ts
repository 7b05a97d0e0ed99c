import { PLAIN_PORT } from '../playwright.config';
import { BACKGROUND, expect, meanDistance, screenshotPatch, test, waitForHead } from './fixtures';

test('served without COOP/COEP headers, the page still shows the head', async ({ page }) => {
  const response = await page.goto(`http://127.0.0.1:${PLAIN_PORT}/`);
  expect(response!.headers()['cross-origin-embedder-policy']).toBeUndefined();
  await waitForHead(page);
  expect(await page.evaluate(() => crossOriginIsolated)).toBe(false);
  await expect(page.locator('#status-isolation')).toHaveText('not cross-origin isolated');
  const png = await page.screenshot();
  const { width, height } = page.viewportSize()!;
  expect(meanDistance(await screenshotPatch(page, png, width / 2, height / 2), BACKGROUND)).toBeGreaterThan(150);
});
