import { addElement, openEmbedPage, takeEvents } from './embed';
import { expect, test } from './fixtures';

test('<soft-face>: the attributes set the face and apply live, each change told by a change event', async ({ page }) => {
  await openEmbedPage(page);
  await addElement(page, 'f', { resolution: 'low', expression: 'AU12=0.8&AU6L=0.5', preset: 'happiness:0.4' });
  expect(await takeEvents(page, 'f')).toEqual([{ type: 'ready' }]);
  const face = () =>
    page.evaluate(() => {
      const f = document.querySelector('soft-face')!.face!;
      return {
        units: f.getActionUnits(),
        presets: Object.fromEntries(f.listPresets().map((p) => [p.name, p.weight])),
        eyes: f.getEyeSimulation(),
        vertices: f.stats().vertices,
      };
    });
  const start = await face();
  expect(start.vertices).toBe(4284);
  expect([start.units.AU12L, start.units.AU12R, start.units.AU6L, start.units.AU6R]).toEqual([0.8, 0.8, 0.5, 0]);
  expect(start.presets.happiness).toBe(0.4);

  const set = (name: string, value: string | null) =>
    page.evaluate(
      ([name, value]) => {
        const element = document.querySelector('soft-face')!;
        if (value === null) element.removeAttribute(name!);
        else element.setAttribute(name!, value);
      },
      [name, value],
    );

  // A new expression replaces the old one; the preset attribute still adds its weight.
  await set('expression', 'AU4R=0.3');
  const changed = await face();
  expect([changed.units.AU12L, changed.units.AU6L, changed.units.AU4R, changed.units.AU4L]).toEqual([0, 0, 0.3, 0]);
  expect(changed.presets.happiness).toBe(0.4);
  await set('preset', 'surprise:1, fear');
  const presets = (await face()).presets;
  expect([presets.happiness, presets.surprise, presets.fear]).toEqual([0, 1, 1]);
  expect(await takeEvents(page, 'f')).toEqual([
    { type: 'change', what: 'expression' },
    { type: 'change', what: 'expression' },
  ]);

  await set('eye-simulation', '');
  expect((await face()).eyes).toBe(true);
  await set('eye-simulation', null);
  expect((await face()).eyes).toBe(false);

  await expect(page.locator('soft-face .softface-panels')).toHaveCount(0);
  await set('panels', '');
  await expect(page.locator('soft-face .softface-panels')).toHaveCount(1);
  // The panels drive this face: a slider moved in them shows in its handle, and their inputs' own change events stay
  // inside the element.
  const slider = page.locator('soft-face .softface-panels [data-control="AU12L"] input');
  await slider.fill('0.7');
  await slider.press('Enter');
  expect((await face()).units.AU12L).toBe(0.7);
  await set('panels', 'false');
  await expect(page.locator('soft-face .softface-panels')).toHaveCount(0);

  await set('background', 'transparent');
  const alpha = await page.evaluate(async () => {
    // Two frames: the next one renders with the new background.
    await new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
    const canvas = document.querySelector('soft-face canvas') as HTMLCanvasElement;
    const gl = canvas.getContext('webgl2')!;
    const read = (x: number, y: number): number => {
      const out = new Uint8Array(4);
      gl.readPixels(x, y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
      return out[3];
    };
    return { corner: read(0, 0), centre: read(canvas.width >> 1, canvas.height >> 1) };
  });
  // The head is drawn opaque in the middle; around it, with a transparent background, nothing is.
  expect(alpha).toEqual({ corner: 0, centre: 255 });

  expect(await takeEvents(page, 'f')).toEqual([
    { type: 'change', what: 'eyes' },
    { type: 'change', what: 'eyes' },
    { type: 'change', what: 'panels' },
    { type: 'change', what: 'expression' },
    { type: 'change', what: 'panels' },
    { type: 'change', what: 'background' },
  ]);
});
