import { openFace } from './face';
import { expect, test, waitForHead } from './fixtures';
import { control, openFolder, setSlider, sliderValue } from './panels';

test('switching the mesh resolution reloads with the other head and keeps the expression', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  await setSlider(page, 'AU12L', 0.6);
  await page.evaluate(() => {
    window.face.setActionUnit('AU4R', 0.25);
    window.face.applyPreset('surprise', 0.5);
  });
  const before = await page.evaluate(() => ({ units: window.face.getActionUnits(), presets: window.face.listPresets() }));

  await openFolder(page, 'Rendering');
  await Promise.all([page.waitForURL(/resolution=medium/), control(page, 'resolution').locator('select').selectOption('medium')]);
  await waitForHead(page);
  await page.evaluate(() => window.face.ready);
  await expect(page.locator('#status-model')).toContainText('medium head: 17,091 vertices');

  const after = await page.evaluate(() => ({
    units: window.face.getActionUnits(),
    presets: window.face.listPresets(),
    url: location.href,
  }));
  expect(after.units).toEqual(before.units);
  expect(after.presets).toEqual(before.presets);
  // The hash stays, and keeps following the face: the address bar is a link to what is shown.
  expect(after.url).toContain('AU12L=0.6&AU12R=0.6');
  expect(after.url).toContain('preset%3Asurprise=0.5');
  expect(await sliderValue(page, 'AU12L')).toBe(0.6);
  expect(await sliderValue(page, 'AU12R')).toBe(0.6);
  expect(await sliderValue(page, 'AU4R')).toBe(0.25);
  await expect(control(page, 'resolution').locator('select')).toHaveValue('medium');
});
