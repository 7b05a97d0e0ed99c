import { maxDifference, openFace, pullForehead, type PulledSkin } from './face';
import { expect, test } from './fixtures';

test('shared, transfer and main solver modes give the same skin for the same input', async ({ page }) => {
  test.setTimeout(150_000);
  const results: PulledSkin[] = [];
  // The low head keeps three solves within the time limit; the modes share every line of solver code.
  for (const mode of ['shared', 'transfer', 'main']) {
    await openFace(page, `/?resolution=low&solver=${mode}`);
    expect(await page.evaluate(() => window.face.stats().mode)).toBe(mode);
    const skin = await pullForehead(page);
    expect(skin.mode).toBe(mode);
    // The pull moved the skin (about 4 mm), so equal results cannot come from a skin that stayed at rest.
    expect(skin.moved).toBeGreaterThan(0.003);
    results.push(skin);
  }
  const [shared, transfer, main] = results;
  expect(maxDifference(shared.rest, transfer.rest)).toBe(0);
  expect(maxDifference(shared.positions, transfer.positions)).toBeLessThan(1e-6 * shared.size);
  expect(maxDifference(shared.positions, main.positions)).toBeLessThan(1e-6 * shared.size);
});
