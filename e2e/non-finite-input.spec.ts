import { openFace, pullForehead } from './face';
import { expect, test } from './shared-app';

test('a non-finite input throws a clear error and the skin keeps its last good state', async ({ page }) => {
  test.setTimeout(90_000);
  await openFace(page, '/?resolution=low');
  const good = await pullForehead(page);
  expect(good.moved).toBeGreaterThan(0.003);
  const before = await page.evaluate(() => window.face.stats());

  const errors = await page.evaluate(() => {
    const face = window.face;
    const attempt = (f: () => void): string => {
      try {
        f();
        return 'no error';
      } catch (error) {
        return (error as Error).message;
      }
    };
    return {
      // The first entry is fine; the second's NaN must keep the first from being applied too.
      nanTarget: attempt(() => face.setMuscleTargets([0, 1], [0, 0.7, 0.1, NaN, 0.7, 0.1], 1)),
      infiniteWeight: attempt(() => face.setMuscleTargets([0], [0, 0.7, 0.1], Infinity)),
      nanParameter: attempt(() => face.setSkinParameters({ positionStiffness: NaN })),
      unknownParameter: attempt(() => face.setSkinParameters({ stiffness: 1 } as never)),
    };
  });
  expect(errors.nanTarget).toMatch(/target of vertex 1 \(entry 1\) has a non-finite x coordinate: NaN/);
  expect(errors.infiniteWeight).toMatch(/weight must be a finite number from 0 to 1, got Infinity/);
  expect(errors.nanParameter).toBe('skin parameters: positionStiffness: expected a number from 0 to 1, got NaN');
  expect(errors.unknownParameter).toMatch(
    /^skin parameters: expected one of the options positionIterations, .*, foldMomentum, pretension, got "stiffness"$/,
  );

  const after = await page.evaluate(async () => {
    await window.face.settle(20_000);
    return { positions: Array.from(window.face.getSkin().positions), stats: window.face.stats() };
  });
  expect(after.positions).toEqual(good.positions);
  expect(after.stats.frames).toBe(before.frames);
  expect(after.stats.constraints.muscle).toBe(50);
  expect(after.stats.sleeping).toBe(true);
});
