import { openFace } from './face';
import { expect, test } from './fixtures';

test('while the skin moves, slow draws go at half resolution, and the settled face is drawn again at full resolution', async ({ page }) => {
  await openFace(page, '/?resolution=medium');
  await page.evaluate(() => window.face.settle(60_000));
  const seen = await page.evaluate(async () => {
    const face = window.face;
    const canvas = document.querySelector('canvas')!;
    const frame = (): Promise<number> => new Promise((resolve) => requestAnimationFrame(resolve));
    const ratio = Math.min(devicePixelRatio, 2);
    const full = Math.floor(canvas.clientWidth * ratio);
    const half = Math.floor(canvas.clientWidth * ratio * 0.5);
    /** Waits until the canvas is at full width again (the first frame with nothing new redraws it), or gives up. */
    const untilFull = async (): Promise<boolean> => {
      const deadline = performance.now() + 10_000;
      while (canvas.width !== full && performance.now() < deadline) await frame();
      return canvas.width === full;
    };
    const fullAtStart = await untilFull();
    // How long a full draw takes here, GPU included: the view draws lower only where that is over 50 ms.
    const drawMs = face.measureRender(3).finishedMs;
    const widths = new Set<number>();
    let watching = true;
    const watch = (): void => {
      widths.add(canvas.width);
      if (watching) requestAnimationFrame(watch);
    };
    requestAnimationFrame(watch);
    face.setActionUnit('AU26', 1);
    await face.settle(60_000);
    const fullAtEnd = await untilFull();
    watching = false;
    return { full, half, fullAtStart, fullAtEnd, drawMs, widths: [...widths] };
  });
  expect(seen.fullAtStart).toBe(true);
  expect(seen.fullAtEnd).toBe(true);
  // Software WebGL (the test browser) takes far longer than 50 ms a draw; a GPU that keeps up never draws lower.
  if (seen.drawMs > 50) expect(seen.widths).toContain(seen.half);
  else expect(seen.widths).toEqual([seen.full]);
});
