import { addFaces, openEmbedPage } from './embed';
import { expect, installPixelReader, test } from './fixtures';

/**
 * `antialias: "still"` (what `auto` picks in software WebGL, as here): a moving face is drawn without multisampling,
 * and a face at rest and `savePNG` show the very picture a multisampled canvas (`always`) shows. Two faces side by side
 * on one page, each with one of the two choices, smiling the same smile.
 */

/** Share of the pixels that may differ by more than 16 levels: the two pictures are the same (0 measured here). */
const DIFFERING = 0.001;
const SIZE = 360;

test('antialias "still" draws a moving face without multisampling, and a face at rest and savePNG as "always" does', async ({ page }) => {
  await page.addInitScript(installPixelReader);
  await openEmbedPage(page);
  await addFaces(
    page,
    {
      always: { resolution: 'low', antialias: 'always' },
      still: { resolution: 'low', antialias: 'still' },
      auto: { resolution: 'low' },
    },
    { width: SIZE, height: SIZE },
  );
  const result = await page.evaluate(
    async ({ DIFFERING }) => {
      const faces = window.faces;
      const canvas = (name: string) => document.querySelector(`#${name} canvas`) as HTMLCanvasElement;
      const multisampled = (name: string) => canvas(name).getContext('webgl2')!.getContextAttributes()!.antialias;
      const pixels = window.readPixels;
      const differing = window.differingShare;
      const frame = () => new Promise((resolve) => requestAnimationFrame(resolve));
      for (const name of ['always', 'still']) faces[name].applyPreset('happiness', 1);
      await Promise.all([faces.always.settle(), faces.still.settle()]);
      // At rest the view draws the still (within a few frames of the motion's end): the canvases come to agree. Until
      // then the canvas of `still` shows the motion's last picture, drawn without multisampling (at half resolution).
      const deadline = performance.now() + 10_000;
      let atRest = 1;
      while (performance.now() < deadline) {
        await frame();
        atRest = differing(await pixels(canvas('always')), await pixels(canvas('still')));
        if (atRest <= DIFFERING) break;
      }
      const png = differing(await pixels(await faces.always.savePNG()), await pixels(await faces.still.savePNG()));
      return {
        multisampled: { always: multisampled('always'), still: multisampled('still'), auto: multisampled('auto') },
        atRest,
        quality: canvas('still').dataset.quality,
        png,
      };
    },
    { DIFFERING },
  );
  console.log(`antialias: ${JSON.stringify(result)}`);
  // Headless Chromium's WebGL is SwiftShader: `auto` picks `still` there.
  expect(result.multisampled).toEqual({ always: true, still: false, auto: false });
  expect(result.atRest).toBeLessThanOrEqual(DIFFERING);
  // The canvas says it shows the finished picture.
  expect(result.quality).toBe('full');
  expect(result.png).toBeLessThanOrEqual(DIFFERING);
});
