import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, openFolder } from './panels';

test('a face that stands still draws no frames, and a change draws it again', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  await openFolder(page, 'Outputs');
  const fps = async (): Promise<number> => Number(await control(page, 'output-fps').locator('input').inputValue());
  // Once the skin sleeps and the camera rests, the view stops drawing: the panel's rate falls to 0.
  await page.evaluate(() => window.face.settle(30_000));
  await expect.poll(fps, { timeout: 30_000, intervals: [500] }).toBe(0);
  // A slider change wakes the solver: the new skin is drawn while it moves.
  await page.evaluate(() => window.face.setActionUnit('AU12', 1));
  await expect.poll(fps, { timeout: 30_000, intervals: [250] }).toBeGreaterThan(0);
  // Settled again, it stops again.
  await page.evaluate(() => window.face.settle(30_000));
  await expect.poll(fps, { timeout: 30_000, intervals: [500] }).toBe(0);
});
