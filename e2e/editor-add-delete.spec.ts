import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, openFolder } from './panels';

test('the panel adds a muscle in front of the view, duplicates, renames, assigns and deletes it, and undo steps back through it', async ({
  page,
}) => {
  await openFace(page, '/?resolution=low');
  // The default rig's muscles: the counts below are this plus what the test adds.
  const base = await page.evaluate(() => window.face.getRig().muscles.length);
  await openFolder(page, 'Editor');
  await control(page, 'editor').locator('input').check();
  await control(page, 'new-type').locator('select').selectOption('sphincter');
  await control(page, 'add-muscle').locator('button').click();
  // The view looks at the face's middle from the front: the muscle lands on the midline, on the skin.
  const added = await page.evaluate(() => {
    const name = window.face.getSelectedMuscle()!;
    return {
      name,
      muscle: window.face.getRig().muscles.find((m) => m.name === name) as { type: string; center: number[] },
      rest: window.face.getSkin().rest,
    };
  });
  expect(added.name).toBe('new-sphincter');
  expect(added.muscle.type).toBe('sphincter');
  let nearest = Infinity;
  for (let i = 0; i < added.rest.length; i += 3) {
    nearest = Math.min(
      nearest,
      Math.hypot(
        added.rest[i] - added.muscle.center[0],
        added.rest[i + 1] - added.muscle.center[1],
        added.rest[i + 2] - added.muscle.center[2],
      ),
    );
  }
  expect(nearest).toBeLessThan(0.01);
  expect(Math.abs(added.muscle.center[0])).toBeLessThan(0.005);
  expect(await page.evaluate(() => window.face.describeMuscleDisplay().length)).toBe(base + 1);

  await control(page, 'muscle-duplicate').locator('button').click();
  await expect(control(page, 'muscle-name').locator('input')).toHaveValue('new-sphincter-copy');
  const name = control(page, 'muscle-name').locator('input');
  await name.fill('ring');
  await name.press('Enter');
  await control(page, 'muscle-action-unit').locator('select').selectOption('AU18');
  let rig = await page.evaluate(() => window.face.getRig());
  expect(rig.muscles.map((m) => m.name).slice(-2)).toEqual(['new-sphincter', 'ring']);
  expect(rig.actionUnits.find((a) => a.id === 'AU18')!.muscles.map((l) => l.muscle)).toContain('ring');

  await control(page, 'muscle-delete').locator('button').click();
  expect(await page.evaluate(() => window.face.getSelectedMuscle())).toBeNull();
  rig = await page.evaluate(() => window.face.getRig());
  expect(rig.muscles.map((m) => m.name)).not.toContain('ring');
  expect(rig.actionUnits.find((a) => a.id === 'AU18')!.muscles.map((l) => l.muscle)).not.toContain('ring');
  expect(await page.evaluate(() => window.face.describeMuscleDisplay().length)).toBe(base + 1);

  // Undo: the delete, the link, the rename, the copy, the new muscle.
  for (const count of [base + 2, base + 2, base + 2, base + 1, base]) {
    await control(page, 'undo').locator('button').click();
    expect(await page.evaluate(() => window.face.getRig().muscles.length)).toBe(count);
  }
  await expect(control(page, 'undo').locator('button')).toBeDisabled();
  // The skin still solves with the rig back as it was.
  expect(
    await page.evaluate(async () => {
      await window.face.settle(45_000);
      return window.face.stats().sleeping;
    }),
  ).toBe(true);
});
