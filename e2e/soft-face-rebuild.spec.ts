import { addElement, openEmbedPage, takeEvents } from './embed';
import { expect, test } from './fixtures';

test('<soft-face>: a new solver rebuilds the face, fires ready again and keeps what the face had', async ({ page }) => {
  await openEmbedPage(page);
  await addElement(page, 'f', { resolution: 'low', solver: 'transfer', expression: 'AU12=0.8' }, { inView: false });
  await takeEvents(page, 'f');
  const old = await page.evaluate(() => {
    const f = document.querySelector('soft-face')!.face!;
    // What only the handle knows: the rebuilt face must carry it over.
    f.setActionUnit('AU4L', 0.3);
    f.setLight({ keyAzimuth: 120 });
    f.setRenderOptions({ wireframe: true });
    f.setMuscleDisplay({ actionUnits: ['AU12'] });
    f.setSkinParameters({ lengthIterations: 5 });
    return f.stats().mode;
  });
  expect(old).toBe('transfer');
  await takeEvents(page, 'f');

  await page.evaluate(async () => {
    const element = document.querySelector('soft-face')!;
    const ready = new Promise((resolve) => element.addEventListener('ready', resolve, { once: true }));
    (window as unknown as { oldFace: unknown }).oldFace = element.face;
    element.setAttribute('solver', 'main');
    await ready;
  });
  const r = await page.evaluate(() => {
    const element = document.querySelector('soft-face')!;
    const f = element.face!;
    const oldFace = (window as unknown as { oldFace: typeof f }).oldFace;
    return {
      replaced: f !== oldFace,
      oldDisposed: oldFace.isDisposed(),
      mode: f.stats().mode,
      units: [f.getActionUnits().AU12L, f.getActionUnits().AU12R, f.getActionUnits().AU4L, f.getActionUnits().AU4R],
      azimuth: f.getLight().keyAzimuth,
      wireframe: f.getRenderOptions().wireframe,
      muscles: f.getMuscleDisplay(),
      lengthIterations: f.getSkinParameters().lengthIterations,
      canvases: element.querySelectorAll('canvas').length,
    };
  });
  expect(r).toEqual({
    replaced: true,
    oldDisposed: true,
    mode: 'main',
    units: [0.8, 0.8, 0.3, 0],
    azimuth: 120,
    wireframe: true,
    muscles: { all: false, actionUnits: ['AU12'] },
    lengthIterations: 5,
    canvases: 1,
  });
  // The main-thread solver runs no worker; the old face's worker is gone.
  await expect.poll(() => page.workers().length).toBe(0);
  expect(await takeEvents(page, 'f')).toEqual([{ type: 'ready' }]);
});
