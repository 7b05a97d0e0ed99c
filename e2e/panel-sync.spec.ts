import { openFace } from './face';
import { expect, test } from './shared-app';
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
  expect(result.errors[0]).toMatch(/setLight: keyElevation: expected a number from -90 to 90, got NaN/);
  expect(result.errors[1]).toMatch(/setLight: expected one of the options .*, got "spotAngle"/);
  expect(result.errors[2]).toMatch(/setLight: keyElevation: expected a number from -90 to 90, got 120/);
  expect(result.errors[3]).toMatch(/setLight: keyColor: expected a colour "#rrggbb", got "blue"/);
  expect(result.errors[4]).toMatch(/setLight: ambientIntensity: expected a number from 0 to 3, got/);
  expect(result.errors[5]).toMatch(/setRenderOptions: wireframe: expected true or false/);
  expect(result.errors[6]).toMatch(/setRenderOptions: expected one of the options wireframe, showEyes, showTeeth, got "shadows"/);
  expect(result.errors[7]).toMatch(/setRenderOptions: expected an object of options/);
  expect(result.lightAfter).toEqual(result.light);
  expect(result.renderAfter).toEqual(result.render);
  expect(await sliderValue(page, 'light-keyAzimuth')).toBe(result.light.keyAzimuth);
});
