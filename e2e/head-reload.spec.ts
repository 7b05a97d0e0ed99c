import { readFileSync } from 'node:fs';
import { openFace } from './face';
import { expect, test } from './fixtures';

const OBJ = readFileSync(new URL('./assets/long-face.obj', import.meta.url), 'utf8');

test('a loaded head, its landmarks and its edited rig come back after a reload; "default head" goes back for good', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const original = await page.evaluate(() => window.face.describeHead());
  const loaded = await page.evaluate(async (text) => {
    const head = await window.face.loadHead(new File([text], 'long-face.obj'));
    // An edit on the loaded head's rig, kept by the autosave.
    window.face.updateMuscle('zygomaticus-major-l', { strength: 0.42 });
    return { head, rig: window.face.getRig() };
  }, OBJ);
  expect(loaded.head).toMatchObject({ source: 'loaded', name: 'long-face.obj', units: 'cm', up: '+z', forward: '-y' });
  expect(loaded.head.landmarks['chin'][1]).not.toBeCloseTo(original.landmarks['chin'][1], 3);
  await expect.poll(() => page.evaluate(() => window.face.describeEditor().autosave)).toBe('saved');

  await page.reload();
  await openFace(page, '/?resolution=low');
  const after = await page.evaluate(() => ({ head: window.face.describeHead(), rig: window.face.getRig(), edited: window.face.isRigEdited() }));
  expect(after.head).toMatchObject({ source: 'loaded', name: 'long-face.obj', vertices: loaded.head.vertices, landmarks: loaded.head.landmarks });
  expect(after.rig).toEqual(loaded.rig);
  expect(after.edited).toBe(true);

  await page.evaluate(() => window.face.revertHead());
  expect(await page.evaluate(() => window.face.describeHead())).toEqual(original);
  await page.reload();
  await openFace(page, '/?resolution=low');
  expect(await page.evaluate(() => window.face.describeHead())).toEqual(original);
});
