import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, openFolder } from './panels';

test("a name being typed into the muscle folder survives the face's other changes until Enter renames the muscle", async ({ page }) => {
  await openFace(page, '/?resolution=low');
  await openFolder(page, 'Editor');
  await control(page, 'editor').locator('input').check();
  await page.evaluate(() => window.face.selectMuscle('zygomaticus-major-l'));
  const name = control(page, 'muscle-name').locator('input');
  await expect(name).toHaveValue('zygomaticus-major-l');
  await name.fill('smile-l');
  // Changes the panel follows while the user types (the autosave's status after an edit is one such).
  await page.evaluate(() => {
    window.face.setMirrorEdits(!window.face.getMirrorEdits());
    window.face.updateMuscle('zygomaticus-major-r', { strength: 0.3 });
  });
  await expect(name).toHaveValue('smile-l');
  await name.press('Enter');
  const names = await page.evaluate(() => window.face.getRig().muscles.map((m) => m.name));
  expect(names).toContain('smile-l');
  expect(names).not.toContain('zygomaticus-major-l');
});
