import { openFace } from './face';
import { expect, test } from './fixtures';
import { control, openFolder } from './panels';

test('an edited rig is autosaved, a reload restores it and says so, and "revert to default" brings the default back', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const original = await page.evaluate(() => window.face.getRig());
  await page.evaluate(() => {
    window.face.updateMuscle('zygomaticus-major-l', { insertion: [0.031, 0.662, 0.141] });
    window.face.renameMuscle('risorius-l', 'risorius-edited-l');
  });
  const edited = await page.evaluate(() => window.face.getRig());
  await openFolder(page, 'Editor');
  // Written within a second of the edit (the expect polls until it says so).
  await expect(control(page, 'rig-status')).toHaveText('edited rig · saved in this browser');

  await page.reload();
  await openFace(page, '/?resolution=low');
  expect(await page.evaluate(() => window.face.getRig())).toEqual(edited);
  expect(await page.evaluate(() => window.face.describeEditor().edited)).toBe(true);
  await openFolder(page, 'Editor');
  await expect(control(page, 'rig-status')).toContainText('edited rig');

  await control(page, 'revert-rig').locator('button').click();
  expect(await page.evaluate(() => window.face.getRig())).toEqual(original);
  await expect(control(page, 'rig-status')).toHaveText('default rig');
  await expect(control(page, 'revert-rig')).toBeHidden();
});
