import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, faceCrop, openFolder, setSlider } from './panels';

test.beforeEach(async ({ page }) => {
  await openFace(page, '/?resolution=low');
  await openFolder(page, 'Light');
});

test("the key light's horizontal angle turns which side of the face is lit", async ({ page }) => {
  // Level, from the subject's left (+x, the right of the picture), then from the subject's right.
  await setSlider(page, 'light-keyElevation', 0);
  await setSlider(page, 'light-keyAzimuth', 90);
  const fromLeft = await faceCrop(page);
  await setSlider(page, 'light-keyAzimuth', 270);
  const fromRight = await faceCrop(page, fromLeft.rect);
  console.log(
    `azimuth 90: left ${fromLeft.left.toFixed(1)} right ${fromLeft.right.toFixed(1)}; ` +
      `azimuth 270: left ${fromRight.left.toFixed(1)} right ${fromRight.right.toFixed(1)}`,
  );
  expect(fromLeft.right).toBeGreaterThan(fromLeft.left * 1.3);
  expect(fromRight.left).toBeGreaterThan(fromRight.right * 1.3);
  expect(await page.evaluate(() => window.face.getLight())).toMatchObject({ keyAzimuth: 270, keyElevation: 0 });
});

test("the key light's vertical angle turns the light from above to below", async ({ page }) => {
  await setSlider(page, 'light-keyAzimuth', 0);
  await setSlider(page, 'light-keyElevation', 80);
  const above = await faceCrop(page);
  await setSlider(page, 'light-keyElevation', -80);
  const below = await faceCrop(page, above.rect);
  console.log(
    `elevation 80: top ${above.top.toFixed(1)} bottom ${above.bottom.toFixed(1)}; ` +
      `-80: top ${below.top.toFixed(1)} bottom ${below.bottom.toFixed(1)}`,
  );
  // Lit from above, the upper half of the face is brighter than the lower (measured: by about 20 grey levels); lit from
  // below, the lower half gains light (by about 20) while the upper half keeps its front-facing forehead lit.
  expect(above.top - above.bottom).toBeGreaterThan(below.top - below.bottom + 10);
  expect(below.bottom).toBeGreaterThan(above.bottom + 8);
  await expect(control(page, 'light-keyElevation')).toBeVisible();
});

test('the intensities and the colour reach the picture', async ({ page }) => {
  const normal = await faceCrop(page);
  await setSlider(page, 'light-keyIntensity', 0);
  await setSlider(page, 'light-ambientIntensity', 0);
  const dark = await faceCrop(page, normal.rect);
  // The room environment map still lights the face a little (measured: about 110 of 170 grey levels remain).
  console.log(`mean grey: default light ${normal.mean.toFixed(1)}, both lights off ${dark.mean.toFixed(1)}`);
  expect(dark.mean).toBeLessThan(0.8 * normal.mean);
  expect(await page.evaluate(() => window.face.getLight())).toMatchObject({ keyIntensity: 0, ambientIntensity: 0 });
  // A white key light, then a blue one of the same intensity: skin reflects little blue, so the face darkens.
  await setSlider(page, 'light-keyIntensity', 3);
  const white = await faceCrop(page, normal.rect);
  await page.evaluate(() => window.face.setLight({ keyColor: '#0000ff' }));
  expect(await page.evaluate(() => window.face.getLight().keyColor)).toBe('#0000ff');
  const blue = await faceCrop(page, normal.rect);
  console.log(`mean grey under the key light alone: white ${white.mean.toFixed(1)}, blue ${blue.mean.toFixed(1)}`);
  expect(blue.mean).toBeLessThan(0.8 * white.mean);
});
