import { openFace } from './face';
import { expect, test } from './fixtures';
import { control, sliderValue } from './panels';

test.beforeEach(async ({ page }) => {
  await openFace(page, '/?resolution=low');
});

test('handle calls move the panel controls that show what they changed', async ({ page }) => {
  await page.evaluate(() => window.face.setActionUnit('AU12L', 0.7));
  expect(await sliderValue(page, 'AU12L')).toBe(0.7);
  expect(await sliderValue(page, 'AU12R')).toBe(0); // a one-sided call leaves the other side's slider alone
  await expect(control(page, 'AU12L')).toContainText('left · D');

  await page.evaluate(() => window.face.setActionUnit('AU17', 0.3));
  expect(await sliderValue(page, 'AU17')).toBe(0.3);

  await page.evaluate(() => window.face.applyPreset('anger', 0.5));
  expect(await sliderValue(page, 'preset-anger')).toBe(0.5);

  await page.evaluate(() => window.face.setLight({ keyAzimuth: 200, keyIntensity: 1.5 }));
  expect(await sliderValue(page, 'light-keyAzimuth')).toBe(200);
  expect(await sliderValue(page, 'light-keyIntensity')).toBe(1.5);

  await page.evaluate(() => window.face.setRenderOptions({ wireframe: true, showTeeth: false }));
  await expect(control(page, 'wireframe').locator('input')).toBeChecked();
  await expect(control(page, 'show-teeth').locator('input')).not.toBeChecked();
  await expect(control(page, 'show-eyes').locator('input')).toBeChecked();

  await page.evaluate(() => window.face.setSkinParameters({ lengthIterations: 7 }));
  expect(await sliderValue(page, 'length-iterations')).toBe(7);

  await page.evaluate(() => window.face.reset());
  expect(await sliderValue(page, 'AU12L')).toBe(0);
  expect(await sliderValue(page, 'AU17')).toBe(0);
  expect(await sliderValue(page, 'preset-anger')).toBe(0);
  await expect(control(page, 'AU12L')).toContainText('left · –');
});

test('setLight and setRenderOptions reject bad input, naming it, and change nothing', async ({ page }) => {
  const result = await page.evaluate(() => {
    const face = window.face;
    const light = face.getLight();
    const render = face.getRenderOptions();
    const errors: string[] = [];
    const calls: (() => void)[] = [
      () => face.setLight({ keyAzimuth: 90, keyElevation: Number.NaN }),
      () => face.setLight({ keyIntensity: 2, spotAngle: 3 } as Parameters<typeof face.setLight>[0]),
      () => face.setLight({ keyElevation: 120 }),
      () => face.setLight({ keyColor: 'blue' }),
      () => face.setLight({ ambientIntensity: '1' } as unknown as Parameters<typeof face.setLight>[0]),
      () => face.setRenderOptions({ wireframe: 1 } as unknown as Parameters<typeof face.setRenderOptions>[0]),
      () => face.setRenderOptions({ showEyes: false, shadows: true } as Parameters<typeof face.setRenderOptions>[0]),
      () => face.setRenderOptions(null as unknown as Parameters<typeof face.setRenderOptions>[0]),
    ];
    for (const call of calls) {
      try {
        call();
        errors.push('no error');
      } catch (e) {
        errors.push((e as Error).message);
      }
    }
    return { errors, light, render, lightAfter: face.getLight(), renderAfter: face.getRenderOptions() };
  });
  expect(result.errors[0]).toMatch(/setLight: keyElevation .*NaN/);
  expect(result.errors[1]).toMatch(/setLight: unknown option "spotAngle"/);
  expect(result.errors[2]).toMatch(/setLight: keyElevation must be within -90\.\.90, got 120/);
  expect(result.errors[3]).toMatch(/setLight: keyColor .*"blue"/);
  expect(result.errors[4]).toMatch(/setLight: ambientIntensity needs a number/);
  expect(result.errors[5]).toMatch(/setRenderOptions: wireframe needs a boolean/);
  expect(result.errors[6]).toMatch(/setRenderOptions: unknown option "shadows"/);
  expect(result.errors[7]).toMatch(/setRenderOptions: needs an object/);
  expect(result.lightAfter).toEqual(result.light);
  expect(result.renderAfter).toEqual(result.render);
  expect(await sliderValue(page, 'light-keyAzimuth')).toBe(result.light.keyAzimuth);
});
