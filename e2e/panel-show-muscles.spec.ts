import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, faceCrop, openFolder, pictureDifference } from './panels';

const shown = (page: import('@playwright/test').Page): Promise<string[]> => page.evaluate(() => window.face.describeMuscleDisplay());

test("an Action Unit's 'show muscles' checkbox draws exactly its muscles over the face, and 'show all muscles' all of them", async ({
  page,
}) => {
  // Five screenshots of the whole page on a software renderer: more than the default minute on a busy machine.
  test.setTimeout(150_000);
  await openFace(page, '/?resolution=low');
  await page.evaluate(() => window.face.settle(45_000));
  expect(await shown(page)).toEqual([]);
  const before = await faceCrop(page);

  const box = control(page, 'AU12-muscles').locator('input');
  await box.check();
  expect(await shown(page)).toEqual(['zygomaticus-major-l', 'zygomaticus-major-r']);
  expect(await page.evaluate(() => window.face.getMuscleDisplay())).toEqual({ all: false, actionUnits: ['AU12'] });
  const zygomaticus = await faceCrop(page, before.rect);
  const drawn = pictureDifference(before, zygomaticus);

  await box.uncheck();
  expect(await shown(page)).toEqual([]);
  const back = await faceCrop(page, before.rect);
  const restored = pictureDifference(before, back);

  await openFolder(page, 'Rendering');
  await control(page, 'show-all-muscles').locator('input').check();
  const all = await shown(page);
  const muscles = await page.evaluate(() => window.face.getRig().muscles.map((m) => m.name));
  expect(all).toHaveLength(muscles.length);
  expect(new Set(all)).toEqual(new Set(muscles));
  const everything = pictureDifference(before, await faceCrop(page, before.rect));
  console.log(
    `picture difference from no muscles: AU12 ${drawn.toFixed(2)}, unticked ${restored.toFixed(2)}, all ${everything.toFixed(2)}`,
  );
  // Two thin rods move few pixels; every muscle moves many more; unticking gives the same picture back.
  expect(drawn).toBeGreaterThan(0.1);
  expect(restored).toBeLessThan(0.05);
  expect(everything).toBeGreaterThan(4 * drawn);

  // "all" keeps the per-unit choice: switching it off shows the ticked units again.
  await box.check();
  await control(page, 'show-all-muscles').locator('input').uncheck();
  expect(await shown(page)).toEqual(['zygomaticus-major-l', 'zygomaticus-major-r']);
});

test('a handle call ticks the checkboxes, and a bad one throws naming the id and changes nothing', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  await openFolder(page, 'Rendering');
  await page.evaluate(() => window.face.setMuscleDisplay({ actionUnits: ['AU26', 'AU6'] }));
  await expect(control(page, 'AU26-muscles').locator('input')).toBeChecked();
  await expect(control(page, 'AU6-muscles').locator('input')).toBeChecked();
  await expect(control(page, 'AU12-muscles').locator('input')).not.toBeChecked();
  expect(await shown(page)).toEqual(['orbicularis-oculi-orbital-l', 'orbicularis-oculi-orbital-r', 'jaw']);

  const error = await page.evaluate(() => {
    try {
      window.face.setMuscleDisplay({ all: true, actionUnits: ['AU12', 'AU99'] });
      return '';
    } catch (e) {
      return (e as Error).message;
    }
  });
  expect(error).toContain('"AU99"');
  expect(await page.evaluate(() => window.face.getMuscleDisplay())).toEqual({ all: false, actionUnits: ['AU6', 'AU26'] });

  await page.evaluate(() => window.face.setMuscleDisplay({ all: true }));
  await expect(control(page, 'show-all-muscles').locator('input')).toBeChecked();
  expect(await shown(page)).toHaveLength(await page.evaluate(() => window.face.getRig().muscles.length));
  await page.evaluate(() => window.face.setMuscleDisplay({ all: false, actionUnits: [] }));
  await expect(control(page, 'show-all-muscles').locator('input')).not.toBeChecked();
  await expect(control(page, 'AU26-muscles').locator('input')).not.toBeChecked();
  expect(await shown(page)).toEqual([]);
});
