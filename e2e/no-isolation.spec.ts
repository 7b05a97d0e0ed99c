import { PLAIN_PORT } from '../playwright.config';
import { openFace, pullForehead } from './face';
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

test('served without COOP/COEP headers, the solver runs in transfer mode and the skin still deforms', async ({ page }) => {
  await openFace(page, `http://127.0.0.1:${PLAIN_PORT}/?resolution=low`);
  await expect(page.locator('#status-solver')).toContainText('solver: transfer');
  const skin = await pullForehead(page);
  expect(skin.mode).toBe('transfer');
  expect(skin.moved).toBeGreaterThan(0.003);
});
