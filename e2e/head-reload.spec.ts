import { readFileSync } from 'node:fs';
import { openFace } from './face';
import { expect, test } from './fixtures';

const OBJ = readFileSync(new URL('./assets/long-face.obj', import.meta.url), 'utf8');

test.describe.configure({ timeout: 180_000 });

test(
  'a loaded head, its landmarks and its edited rig come back when the page ' +
    'is reopened, at the resolution asked; "default head" goes back for good',
  async ({ page }) => {
    await openFace(page, '/?resolution=low');
    const original = await page.evaluate(() => window.face.describeHead());
    const loaded = await page.evaluate(async (text) => {
      const head = await window.face.loadHead(new File([text], 'long-face.obj'));
      // An edit on the loaded head's rig, kept by the autosave.
      window.face.updateMuscle('zygomaticus-major-l', { strength: 0.42 });
      return { head, rig: window.face.getRig() };
    }, OBJ);
    expect(loaded.head).toMatchObject({ source: 'loaded', name: 'long-face.obj', units: 'cm', up: '+z', forward: '-y' });
    expect(loaded.head.landmarks.chin[1]).not.toBeCloseTo(original.landmarks.chin[1], 3);
    await expect.poll(() => page.evaluate(() => window.face.describeEditor().autosave)).toBe('saved');

    // Reopened, here at another resolution: the same head, subdivided (each of its 8,524 triangles into six), with the
    // same landmarks and the same edited rig.
    await openFace(page, '/?resolution=medium');
    const after = await page.evaluate(() => ({
      head: window.face.describeHead(),
      rig: window.face.getRig(),
      edited: window.face.isRigEdited(),
    }));
    expect(after.head).toMatchObject({
      source: 'loaded',
      name: 'long-face.obj',
      level: 'medium',
      triangles: 6 * loaded.head.triangles,
      landmarks: loaded.head.landmarks,
    });
    expect(after.rig).toEqual(loaded.rig);
    expect(after.edited).toBe(true);
    // Exported, the rig is that head's: long-face.rig.json.
    expect(await page.evaluate(() => window.face.describeEditor().rigName)).toBe('long-face');

    await page.evaluate(() => window.face.revertHead());
    expect(await page.evaluate(() => window.face.describeHead())).toMatchObject({
      source: 'default',
      level: 'medium',
      landmarks: original.landmarks,
    });
    await openFace(page, '/?resolution=low');
    expect(await page.evaluate(() => window.face.describeHead())).toEqual(original);
  },
);
