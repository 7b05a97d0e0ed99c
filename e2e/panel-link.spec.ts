import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, setSlider, sliderValue } from './panels';

test('linked sides move together; unlinked, a slider drives its own side only', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const units = (): Promise<Record<string, number>> => page.evaluate(() => window.face.getActionUnits());

  await expect(control(page, 'AU2-link').locator('input')).toBeChecked(); // linked by default
  await setSlider(page, 'AU2L', 0.4);
  expect(await units()).toMatchObject({ AU2L: 0.4, AU2R: 0.4 });
  expect(await sliderValue(page, 'AU2R')).toBe(0.4); // the other slider moved too

  await control(page, 'AU2-link').locator('input').uncheck();
  await setSlider(page, 'AU2R', 0.9);
  expect(await units()).toMatchObject({ AU2L: 0.4, AU2R: 0.9 });
  expect(await sliderValue(page, 'AU2L')).toBe(0.4);
  await setSlider(page, 'AU2L', 0);
  expect(await units()).toMatchObject({ AU2L: 0, AU2R: 0.9 });

  // Another unit's link is its own: AU12 is still linked.
  await setSlider(page, 'AU12R', 0.3);
  expect(await units()).toMatchObject({ AU12L: 0.3, AU12R: 0.3, AU2L: 0, AU2R: 0.9 });
  // The solver was driven, not just the sliders: the skin settles somewhere other than rest.
  const moved = await page.evaluate(async () => {
    await window.face.settle(45_000);
    const { rest, positions } = window.face.getSkin();
    let m = 0;
    for (let i = 0; i < rest.length; i++) m = Math.max(m, Math.abs(positions[i] - rest[i]));
    return m;
  });
  expect(moved).toBeGreaterThan(0.001);
});
