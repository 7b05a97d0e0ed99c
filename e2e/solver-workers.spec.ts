import { maxDifference, openFace } from './face';
import { expect, test } from './fixtures';

/** Sets a smile with the jaw open (muscles, lips against the teeth colliders), settles and returns the skin. */
async function smileOpen(page: import('@playwright/test').Page) {
  return page.evaluate(async () => {
    const face = window.face;
    face.setActionUnit('AU12', 1);
    face.setActionUnit('AU26', 1);
    await face.settle(60_000);
    const { rest, positions } = face.getSkin();
    let moved = 0;
    for (let i = 0; i < rest.length; i += 3)
      moved = Math.max(moved, Math.hypot(positions[i] - rest[i], positions[i + 1] - rest[i + 1], positions[i + 2] - rest[i + 2]));
    let size = 0;
    for (let k = 0; k < 3; k++) {
      const axis = Array.from(rest).filter((_, i) => i % 3 === k);
      size = Math.hypot(size, Math.max(...axis) - Math.min(...axis));
    }
    return { positions: Array.from(positions), moved, size, workers: face.stats().workers, mode: face.stats().mode };
  });
}

test('two solver workers give the shape one worker gives', async ({ page }) => {
  test.setTimeout(150_000);
  await openFace(page, '/?resolution=low&workers=1');
  const one = await smileOpen(page);
  await openFace(page, '/?resolution=low&workers=2');
  const two = await smileOpen(page);
  expect(one.mode).toBe('shared');
  expect(one.workers).toBe(1);
  // The partner worker solved the frames, not only the one the page started with.
  expect(two.workers).toBe(2);
  // A smile with the jaw open moves the skin by centimetres, so equal shapes cannot come from skin left at rest.
  expect(one.moved).toBeGreaterThan(0.01);
  expect(maxDifference(one.positions, two.positions)).toBeLessThan(1e-6 * one.size);
  await expect(page.locator('#status-solver')).toContainText('2 workers');
});
