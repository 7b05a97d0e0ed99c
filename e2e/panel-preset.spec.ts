import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, openFolder, setSlider, settledSkin, sliderValue } from './panels';

test('a preset slider sets the Action Units it names (presets add to the sliders), and reset zeroes everything', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  await openFolder(page, 'Presets');
  await setSlider(page, 'preset-happiness', 1);

  const state = await page.evaluate(() => ({
    sliders: window.face.getActionUnits(),
    effective: window.face.getEffectiveActionUnits(),
    presets: window.face.listPresets(),
  }));
  // The sliders stay at 0; the preset's units (happiness: AU6 0.8, AU12 0.9) take effect on both sides.
  expect(Object.values(state.sliders).every((v) => v === 0)).toBe(true);
  expect(state.effective.AU6L).toBeCloseTo(0.8, 6);
  expect(state.effective.AU6R).toBeCloseTo(0.8, 6);
  expect(state.effective.AU12L).toBeCloseTo(0.9, 6);
  expect(state.effective.AU12R).toBeCloseTo(0.9, 6);
  expect(state.effective.AU4L).toBe(0);
  expect(state.presets.find((p) => p.name === 'happiness')?.weight).toBe(1);
  expect((await settledSkin(page)).moved).toBeGreaterThan(0.002);

  // Presets combine: a second one adds its own units.
  await setSlider(page, 'preset-surprise', 0.5);
  const combined = await page.evaluate(() => window.face.getEffectiveActionUnits());
  expect(combined.AU12L).toBeCloseTo(0.9, 6);
  expect(combined.AU1L).toBeCloseTo(0.5, 6); // surprise's AU1 1 at half weight

  // Reset: every preset and slider back to 0, and the panel's sliders with them.
  await setSlider(page, 'AU4L', 0.5);
  await control(page, 'reset').locator('button').click();
  const after = await page.evaluate(() => ({ effective: window.face.getEffectiveActionUnits(), presets: window.face.listPresets() }));
  expect(Object.values(after.effective).every((v) => v === 0)).toBe(true);
  expect(after.presets.every((p) => p.weight === 0)).toBe(true);
  expect(await sliderValue(page, 'preset-happiness')).toBe(0);
  expect(await sliderValue(page, 'preset-surprise')).toBe(0);
  expect(await sliderValue(page, 'AU4L')).toBe(0);
  expect((await settledSkin(page)).moved).toBeLessThan(1e-4);
});
