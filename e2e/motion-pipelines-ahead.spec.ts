import { addFaces, openEmbedPage } from './embed';
import { expect, installPixelReader, test } from './fixtures';

/**
 * Where the canvas does not multisample (software WebGL, as here), a face at rest is drawn into an offscreen target,
 * and its first motion would make the canvas's pipelines: the view draws the head once into one pixel of the canvas
 * after its first picture instead (PictureDrawer.warmMotion), which must leave that picture as it was.
 */

/** Share of the pixels that may differ by more than 16 levels between the canvas and `savePNG` (0 measured). */
const DIFFERING = 0.001;

test('a face whose canvas does not multisample draws once into one pixel of it after its first picture, which stays the same', async ({
  page,
}) => {
  await page.addInitScript(installPixelReader);
  await openEmbedPage(page);
  await page.evaluate(() => {
    const log: { scissored: boolean; canvas: boolean; box: number[] }[] = [];
    (window as unknown as { drawLog: typeof log }).drawLog = log;
    const prototype = WebGL2RenderingContext.prototype;
    const drawElements = prototype.drawElements;
    prototype.drawElements = function (this: WebGL2RenderingContext, ...args: Parameters<WebGL2RenderingContext['drawElements']>) {
      log.push({
        scissored: this.isEnabled(this.SCISSOR_TEST),
        canvas: this.getParameter(this.FRAMEBUFFER_BINDING) === null,
        box: [...(this.getParameter(this.SCISSOR_BOX) as Int32Array)],
      });
      return drawElements.apply(this, args);
    };
  });
  await addFaces(page, { face: { resolution: 'low' } });
  const seen = await page.evaluate(
    async ({ DIFFERING }) => {
      const face = window.faces.face;
      const canvas = document.querySelector('#face canvas') as HTMLCanvasElement;
      const log = (window as unknown as { drawLog: { scissored: boolean; canvas: boolean; box: number[] }[] }).drawLog;
      const frame = (): Promise<number> => new Promise((resolve) => requestAnimationFrame(resolve));
      await face.settle();
      // The one-pixel draw comes at an animation frame with nothing to draw, once the GPU has done the first picture.
      const warm = () => log.filter((d) => d.scissored && d.canvas && d.box[2] <= 2 && d.box[3] <= 2).length;
      const deadline = performance.now() + 20_000;
      while (warm() === 0 && performance.now() < deadline) await frame();
      const warmDraws = warm();
      // Nothing changes from here: no draw of any kind for a second.
      const drawsBefore = log.length;
      const quietUntil = performance.now() + 1_000;
      while (performance.now() < quietUntil) await frame();
      const drawsWhileAtRest = log.length - drawsBefore;
      const shown = await window.readPixels(canvas);
      const still = await window.readPixels(await face.savePNG());
      // The pixel the view drew into (the canvas's bottom left corner), against the picture a still gives.
      const corner = (shown.length / 4 - canvas.width) * 4;
      return {
        multisampled: canvas.getContext('webgl2')!.getContextAttributes()!.antialias,
        warmDraws,
        drawsWhileAtRest,
        differing: window.differingShare(shown, still),
        sameSize: shown.length === still.length,
        corner: [...shown.slice(corner, corner + 4)],
        stillCorner: [...still.slice(corner, corner + 4)],
        quality: canvas.dataset.quality,
        DIFFERING,
      };
    },
    { DIFFERING },
  );
  console.log(`pipelines ahead: ${JSON.stringify(seen)}`);
  expect(seen.multisampled).toBe(false);
  // Each of the head's meshes drawn once into the pixel.
  expect(seen.warmDraws).toBeGreaterThan(0);
  expect(seen.drawsWhileAtRest).toBe(0);
  expect(seen.quality).toBe('full');
  expect(seen.sameSize).toBe(true);
  expect(seen.differing).toBeLessThanOrEqual(DIFFERING);
  expect(seen.corner).toEqual(seen.stillCorner);
});
