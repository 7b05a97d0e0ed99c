import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, faceCrop, openFolder, pictureDifference } from './panels';

test('the wireframe checkbox draws the head as edges: the background shows through the face', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const solid = await faceCrop(page);
  await openFolder(page, 'Rendering');
  await control(page, 'wireframe').locator('input').check();
  expect(await page.evaluate(() => window.face.getRenderOptions())).toEqual({ wireframe: true, showEyes: true, showTeeth: true });
  const wire = await faceCrop(page, solid.rect);
  console.log(
    `distance from the background: solid ${solid.fromBackground.toFixed(1)}, wireframe ` +
      `${wire.fromBackground.toFixed(1)}; difference ${pictureDifference(solid, wire).toFixed(1)}`,
  );
  expect(wire.fromBackground).toBeLessThan(0.8 * solid.fromBackground);
  expect(pictureDifference(solid, wire)).toBeGreaterThan(10);

  await control(page, 'wireframe').locator('input').uncheck();
  const back = await faceCrop(page, solid.rect);
  expect(pictureDifference(solid, back)).toBeLessThan(1);
});
