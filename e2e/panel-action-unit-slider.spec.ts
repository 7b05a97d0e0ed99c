import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, faceCrop, pictureDifference, setSlider, settledSkin, sliderValue } from './panels';

test('moving an Action Unit slider in the panel changes the skin and the picture, and its label shows the grade', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const before = await settledSkin(page);
  expect(before.moved).toBeLessThan(1e-4); // neutral: at rest
  const neutral = await faceCrop(page);

  await expect(control(page, 'AU12L')).toContainText('left · –');
  await setSlider(page, 'AU12L', 1);
  expect(await page.evaluate(() => window.face.getActionUnits())).toMatchObject({ AU12L: 1 });
  await expect(control(page, 'AU12L')).toContainText('left · E');

  const after = await settledSkin(page);
  expect(after.moved).toBeGreaterThan(0.002); // the lip corner moves millimetres
  const smiling = await faceCrop(page, neutral.rect);
  const difference = pictureDifference(neutral, smiling);
  console.log(`skin moved ${(after.moved * 1000).toFixed(1)} mm; picture differs by ${difference.toFixed(2)} grey levels on average`);
  expect(difference).toBeGreaterThan(0.3);

  // A small value shows its grade: 0.15 is B.
  await setSlider(page, 'AU12L', 0.15);
  await expect(control(page, 'AU12L')).toContainText('left · B');
  expect(await sliderValue(page, 'AU12L')).toBe(0.15);
});
