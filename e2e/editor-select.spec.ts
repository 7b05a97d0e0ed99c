import { openFace } from './face';
import { expect, test } from './shared-app';
import { control } from './panels';

test('E switches the editor on, a click on a glyph selects it, the panels follow the handle, Escape clears it', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  await page.keyboard.press('e');
  await expect(control(page, 'editor').locator('input')).toBeChecked();
  expect(await page.evaluate(() => window.face.getEditor())).toBe(true);
  // Every muscle is drawn while the editor is on.
  expect(await page.evaluate(() => window.face.describeMuscleDisplay().length)).toBe(
    await page.evaluate(() => window.face.getRig().muscles.length),
  );

  const point = await page.evaluate(() => window.face.locateMuscle('zygomaticus-major-l'));
  await page.mouse.click(point!.x, point!.y);
  expect(await page.evaluate(() => window.face.getSelectedMuscle())).toBe('zygomaticus-major-l');
  await expect(control(page, 'muscle-name').locator('input')).toHaveValue('zygomaticus-major-l');
  await expect(control(page, 'muscle-action-unit').locator('select')).toHaveValue('AU12');
  const editor = await page.evaluate(() => window.face.describeEditor());
  expect(editor.part).toBe('insertion');
  expect(editor.gizmo).not.toBeNull();

  // With a muscle selected, E turns the gizmo to rotate instead of switching the editor off.
  await page.keyboard.press('e');
  expect(await page.evaluate(() => [window.face.getEditor(), window.face.describeEditor().mode])).toEqual([true, 'rotate']);
  await expect(control(page, 'gizmo-mode').locator('select')).toHaveValue('rotate');

  // A handle call moves the Muscle folder to another muscle, with its own fields.
  await page.evaluate(() => window.face.selectMuscle('orbicularis-oris-pucker'));
  await expect(control(page, 'muscle-name').locator('input')).toHaveValue('orbicularis-oris-pucker');
  await expect(control(page, 'muscle-radii-x')).toBeVisible();
  expect(await page.evaluate(() => window.face.describeEditor().part)).toBe('ellipsoid');

  await page.keyboard.press('Escape');
  expect(await page.evaluate(() => window.face.getSelectedMuscle())).toBeNull();
  await expect(control(page, 'muscle-name')).toHaveCount(0);
  // Nothing selected: E switches the editor off again.
  await page.keyboard.press('e');
  expect(await page.evaluate(() => window.face.getEditor())).toBe(false);
  expect(await page.evaluate(() => window.face.describeMuscleDisplay())).toEqual([]);
});
