import { addFaces, openEmbedPage } from './embed';
import { expect, test } from './fixtures';

/**
 * `antialias: "still"` (what `auto` picks in software WebGL, as here): a moving face is drawn without multisampling,
 * and a face at rest and `savePNG` show the very picture a multisampled canvas (`always`) shows. Two faces side by side
 * on one page, each with one of the two choices, smiling the same smile.
 */

/** Share of the pixels that may differ by more than 16 levels: the two pictures are the same (0 measured here). */
const DIFFERING = 0.001;
const SIZE = 360;

test('antialias "still" draws a moving face without multisampling, and a face at rest and savePNG as "always" does', async ({ page }) => {
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
      const pixels = async (source: HTMLCanvasElement | Blob): Promise<Uint8ClampedArray> => {
        const image = await createImageBitmap(source);
        const c = new OffscreenCanvas(image.width, image.height);
        const g = c.getContext('2d')!;
        g.drawImage(image, 0, 0);
        return g.getImageData(0, 0, image.width, image.height).data;
      };
      /** Share of the pixels whose colour differs by more than 16 levels in a channel. */
      const differing = (a: Uint8ClampedArray, b: Uint8ClampedArray): number => {
        let n = 0;
        for (let i = 0; i < a.length; i += 4) {
          if (Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2])) > 16) n++;
        }
        return n / (a.length / 4);
      };
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
