import { addElement, openEmbedPage } from './embed';
import { openFace } from './face';
import { expect, test } from './fixtures';
import { control } from './panels';

test('a FACS code sets the face from a link, the handle and the panel, and a bad one names its place and changes nothing', async ({
  page,
}) => {
  test.setTimeout(90_000);
  // A link's plus signs arrive as spaces (the query form): the code still reads.
  await openFace(page, '/?resolution=low#facs=1+2+5B+26');
  const opened = await page.evaluate(() => ({ units: window.face.getActionUnits(), code: window.face.getFACS() }));
  expect([opened.units.AU1L, opened.units.AU2R, opened.units.AU5L, opened.units.AU26]).toEqual([1, 1, 0.2, 1]);
  expect(opened.code).toBe('1E+2E+5B+26E');
  // The hash keeps the expression as sliders from then on.
  await expect.poll(() => page.evaluate(() => location.hash)).toContain('AU5L=0.2');

  // The handle: every preset's code, set again, writes the same code; a bad code throws with its place and leaves
  // the face as it was.
  const handle = await page.evaluate(() => {
    const face = window.face;
    const codes: Record<string, [string, string]> = {};
    for (const { name } of face.listPresets()) {
      face.reset();
      face.applyPreset(name, 1);
      const code = face.getFACS();
      face.setFACS(code);
      codes[name] = [code, face.getFACS()];
    }
    face.setFACS('L12C+R14A');
    const before = face.getActionUnits();
    let refused = '';
    try {
      face.setFACS('1+2+99');
    } catch (e) {
      refused = (e as Error).message;
    }
    return { codes, before, after: face.getActionUnits(), refused };
  });
  for (const [name, [code, again]] of Object.entries(handle.codes)) expect(again, name).toBe(code);
  expect(handle.codes.surprise[0]).toBe('1E+2E+5B+26E');
  expect(handle.refused).toMatch(/^setFACS: at 5 of "1\+2\+99": expected an Action Unit the face has \(.*\), got "99"$/);
  expect(handle.after).toEqual(handle.before);
  expect([handle.after.AU12L, handle.after.AU12R, handle.after.AU14R]).toEqual([0.4, 0, 0.1]);

  // The panel's field shows the code of what the sliders set, and sets the face from what is typed.
  const field = control(page, 'facs').locator('input');
  await expect(field).toHaveValue('L12C+R14A');
  await field.fill('6D+12D');
  await field.press('Enter');
  await expect(control(page, 'AU12L').locator('input')).toHaveValue('0.7');
  await field.fill('6+12+L17');
  await field.press('Enter');
  await expect(control(page, 'facs-message')).toContainText('at 6 of "6+12+L17": expected 17 without a side');
  // Refused: the face kept its expression, and the field the text to mend.
  expect(await page.evaluate(() => window.face.getFACS())).toBe('6D+12D');
  await expect(field).toHaveValue('6+12+L17');
});

test('<soft-face facs="..."> sets the face, under the expression attribute; a bad code is an error event', async ({ page }) => {
  await openEmbedPage(page);
  await addElement(page, 'f', { resolution: 'low', facs: '4+5+7+23', expression: 'AU7=0.5' });
  const units = await page.evaluate(() => document.querySelector('soft-face')!.face!.getActionUnits());
  expect([units.AU4L, units.AU5R, units.AU7L, units.AU23]).toEqual([1, 1, 0.5, 1]);
  const refused = await page.evaluate(
    () =>
      new Promise<string>((resolve) => {
        const element = document.querySelector('soft-face')!;
        element.addEventListener('error', (e) => resolve((e as ErrorEvent).message), { once: true });
        element.setAttribute('facs', '4+5++7');
      }),
  );
  expect(refused).toMatch(/^<soft-face> facs: at 5 of "4\+5\+\+7": expected a unit on each side of every plus sign/);
  expect(await page.evaluate(() => document.querySelector('soft-face')!.face!.getFACS())).toBe('4E+5E+7C+23E');
});
