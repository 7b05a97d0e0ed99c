import { addElement, openEmbedPage } from './embed';
import { expect, test } from './fixtures';

test('<soft-face>: removing the element disposes its face: worker, canvas and handle', async ({ page }) => {
  await openEmbedPage(page);
  await addElement(page, 'f', { resolution: 'low', panels: '' }, { inView: false });
  expect(page.workers()).toHaveLength(1);
  const r = await page.evaluate(async () => {
    const element = document.querySelector('soft-face')!;
    const face = element.face!;
    const canvas = element.querySelector('canvas')!;
    const gl = canvas.getContext('webgl2')!;
    element.remove();
    // Disposal waits a microtask, as an element moved elsewhere is removed and inserted again at once.
    await Promise.resolve();
    let after = '';
    try {
      face.setActionUnit('AU12', 1);
    } catch (error) {
      after = (error as Error).message;
    }
    return { after, children: element.childElementCount, face: element.face === undefined, lost: gl.isContextLost() };
  });
  expect(r).toEqual({ after: 'the face was disposed', children: 0, face: true, lost: true });
  await expect.poll(() => page.workers().length).toBe(0);
});

test('<soft-face>: moving the element keeps its face', async ({ page }) => {
  await openEmbedPage(page);
  await addElement(page, 'f', { resolution: 'low', expression: 'AU12=0.5' }, { inView: false });
  const r = await page.evaluate(async () => {
    const element = document.querySelector('soft-face')!;
    const face = element.face!;
    const box = document.createElement('div');
    document.body.append(box);
    box.append(element);
    await Promise.resolve();
    await Promise.resolve();
    return { same: element.face === face, units: face.getActionUnits().AU12L, canvases: element.querySelectorAll('canvas').length };
  });
  expect(r).toEqual({ same: true, units: 0.5, canvases: 1 });
  expect(page.workers()).toHaveLength(1);
});
