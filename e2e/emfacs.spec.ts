import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, openFolder, setSlider } from './panels';

test('an EMFACS face is set by name from the handle and from the Presets folder, and a bad name changes nothing', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const byHandle = await page.evaluate(() => {
    const face = window.face;
    const fear = face.listEmotionVariants('fear');
    face.setEmotion('fear-prototype-2');
    const code = face.getFACS();
    let refused = '';
    try {
      face.setEmotion('joy');
    } catch (e) {
      refused = (e as Error).message;
    }
    return { fear: fear.map((v) => v.name), code, after: face.getFACS(), refused, all: face.listEmotionVariants().length };
  });
  expect(byHandle.fear.slice(0, 2)).toEqual(['fear-prototype-1', 'fear-prototype-2']);
  // getFACS writes every unit with its grade's letter (no letter in the table's code is E).
  expect(byHandle.code).toBe('1E+2E+4E+5E+20E+26E');
  expect(byHandle.after).toBe('1E+2E+4E+5E+20E+26E');
  expect(byHandle.refused).toMatch(/^setEmotion: expected an emotion \(surprise, fear, \.\.\.\), .*, got "joy"$/);
  expect(byHandle.all).toBeGreaterThan(60);

  // The folder's list: picking a face sets its code; moving a slider after that leaves the list at none.
  await openFolder(page, 'Presets');
  const list = control(page, 'emfacs').locator('select');
  await list.selectOption({ label: 'surprise prototype 2: 1+2+5B+27' });
  expect(await page.evaluate(() => window.face.getFACS())).toBe('1E+2E+5B+27E');
  expect(await list.inputValue()).toBe('surprise prototype 2: 1+2+5B+27');
  await openFolder(page, 'Action Units');
  await page.evaluate(() => window.face.setActionUnit('AU12', 0.5));
  await expect(list).toHaveValue('–');
  expect(await page.evaluate(() => window.face.getFACS())).toBe('1E+2E+5B+12C+27E');
  await setSlider(page, 'AU12L', 0);
});
