import { openFace } from './face';
import { expect, test } from './fixtures';

test("after an input the view's first draw shows the skin's answer, not the skin as it was", async ({ page }) => {
  // The medium head: its first frame of a new input comes a frame or more after the input, so a view that draws at
  // the next animation frame regardless draws the old skin (with the jaw and teeth already turned).
  await openFace(page, '/?resolution=medium');
  await page.evaluate(() => window.face.settle(60_000));
  const seen = await page.evaluate(async () => {
    const face = window.face;
    // Until animation frames come at their pace again: the first pictures (the environment map, shader compiles) keep
    // software WebGL busy for a while after the skin is ready.
    const frame = (): Promise<number> => new Promise((resolve) => requestAnimationFrame(resolve));
    for (let last = await frame(), now = await frame(); now - last > 50; last = now, now = await frame());
    const before = face.stats().frames;
    const prototype = WebGL2RenderingContext.prototype;
    const drawElements = prototype.drawElements;
    /** The solver frames solved when the view next issued a draw call. */
    let atFirstDraw: number | null = null;
    prototype.drawElements = function (this: WebGL2RenderingContext, ...args: Parameters<WebGL2RenderingContext['drawElements']>) {
      atFirstDraw ??= face.stats().frames;
      return drawElements.apply(this, args);
    };
    try {
      face.setActionUnit('AU26', 1);
      // The view draws (and so calls drawElements) while the skin moves.
      const deadline = performance.now() + 10_000;
      while (atFirstDraw === null && performance.now() < deadline) await frame();
    } finally {
      prototype.drawElements = drawElements;
    }
    return { before, atFirstDraw: atFirstDraw as number | null };
  });
  expect(seen.atFirstDraw).not.toBeNull();
  expect(seen.atFirstDraw!).toBeGreaterThan(seen.before);
});
