import { openFace } from './face';
import { expect, test } from './fixtures';

test('the cross-origin isolated page solves in shared mode and the status bar says so', async ({ page }) => {
  await openFace(page, '/');
  expect(await page.evaluate(() => window.face.stats().mode)).toBe('shared');
  await expect(page.locator('#status-solver')).toContainText(/^solver: shared, \d+\.\d ms per frame/);
});

test('?solver= picks the mode the status bar shows', async ({ page }) => {
  await openFace(page, '/?resolution=low&solver=main');
  expect(await page.evaluate(() => window.face.stats().mode)).toBe('main');
  await expect(page.locator('#status-solver')).toContainText('solver: main');
});
