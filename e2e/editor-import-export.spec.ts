import { readFileSync } from 'node:fs';
import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, openFolder } from './panels';

const DEFAULT_TEXT = readFileSync(new URL('../public/rigs/default.json', import.meta.url), 'utf8');

test(
  'a bad rig file is refused with its path-named message and changes nothing; ' +
    'a good one imports by picker and by drop; export downloads the rig',
  async ({ page }) => {
    await openFace(page, '/?resolution=low');
    await openFolder(page, 'Editor');
    const original = await page.evaluate(() => window.face.getRig());

    const bad = JSON.parse(DEFAULT_TEXT);
    const index = bad.muscles.findIndex((m: { name: string }) => m.name === 'zygomaticus-major-l');
    bad.muscles[index].insertion = [1e6, 0.66, 0.14];
    await control(page, 'import-file').setInputFiles({
      name: 'far.rig.json',
      mimeType: 'application/json',
      buffer: Buffer.from(JSON.stringify(bad)),
    });
    await expect(control(page, 'editor-message')).toHaveText(
      `far.rig.json: muscles[${index}].insertion[0]: expected a coordinate within ±10 m, got 1000000`,
    );
    await control(page, 'import-file').setInputFiles({
      name: 'broken.json',
      mimeType: 'application/json',
      buffer: Buffer.from('{ "format": "softface-rig", '),
    });
    await expect(control(page, 'editor-message')).toContainText('broken.json: invalid JSON at line 1');
    expect(await page.evaluate(() => window.face.getRig())).toEqual(original);
    await expect(control(page, 'rig-status')).toHaveText('default rig');

    const good = JSON.parse(DEFAULT_TEXT);
    good.muscles[index].strength = 0.3;
    await control(page, 'import-file').setInputFiles({
      name: 'strong.rig.json',
      mimeType: 'application/json',
      buffer: Buffer.from(JSON.stringify(good)),
    });
    await expect(control(page, 'editor-message')).toHaveText('imported strong.rig.json');
    await expect(control(page, 'rig-status')).toContainText('edited rig');
    expect(await page.evaluate((i) => (window.face.getRig().muscles[i] as { strength: number }).strength, index)).toBe(0.3);

    // Dropped on the face: the same import.
    good.muscles[index].strength = 0.4;
    await page.evaluate(
      async ({ text }) => {
        const data = new DataTransfer();
        data.items.add(new File([text], 'dropped.rig.json', { type: 'application/json' }));
        document.querySelector('.softface')!.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
      },
      { text: JSON.stringify(good) },
    );
    await expect(control(page, 'editor-message')).toHaveText('imported dropped.rig.json');
    expect(await page.evaluate((i) => (window.face.getRig().muscles[i] as { strength: number }).strength, index)).toBe(0.4);

    const download = page.waitForEvent('download');
    await control(page, 'export-rig').locator('button').click();
    const file = await download;
    expect(file.suggestedFilename()).toBe('default.rig.json');
    const exported = JSON.parse(readFileSync(await file.path(), 'utf8'));
    expect(exported).toEqual(await page.evaluate(() => window.face.getRig()));
  },
);
