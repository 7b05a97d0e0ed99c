import type { Page } from '@playwright/test';
import { addFaces, openEmbedPage } from './embed';
import { openFace } from './face';
import { expect, test } from './fixtures';

/** What the canvas of a face went through while AU26 opened the jaw and the skin settled. */
interface Watched {
  full: number;
  half: number;
  fullAtStart: boolean;
  fullAtEnd: boolean;
  /** Whether an animation frame showed the canvas back at full width, after a half-width one, while the skin still moved. */
  fullWhileMoving: boolean;
  /** Wall ms a full draw takes here, GPU included (`measureRender`). */
  drawMs: number;
  widths: number[];
}

/** Opens the jaw of the face `name` in `window.faces` (the app's `window.face` for null) and watches its canvas. */
function watchJaw(page: Page, name: string | null): Promise<Watched> {
  return page.evaluate(async (name) => {
    const face = name === null ? window.face : window.faces[name];
    const canvas = document.querySelector(name === null ? 'canvas' : `#${name} canvas`) as HTMLCanvasElement;
    await face.settle(60_000);
    const frame = (): Promise<number> => new Promise((resolve) => requestAnimationFrame(resolve));
    const ratio = Math.min(devicePixelRatio, 2);
    const full = Math.floor(canvas.clientWidth * ratio);
    const half = Math.floor(canvas.clientWidth * ratio * 0.5);
    /** Waits until the canvas is at full width again (redrawn once nothing new has come for a while), or gives up. */
    const untilFull = async (): Promise<boolean> => {
      const deadline = performance.now() + 10_000;
      while (canvas.width !== full && performance.now() < deadline) await frame();
      return canvas.width === full;
    };
    const fullAtStart = await untilFull();
    const drawMs = face.measureRender(3).finishedMs;
    const widths = new Set<number>();
    let watching = true;
    let wasHalf = false;
    let fullWhileMoving = false;
    const watch = (): void => {
      widths.add(canvas.width);
      if (canvas.width === half) wasHalf = true;
      else if (wasHalf && canvas.width === full && !face.stats().sleeping) fullWhileMoving = true;
      if (watching) requestAnimationFrame(watch);
    };
    requestAnimationFrame(watch);
    face.setActionUnit('AU26', 1);
    await face.settle(60_000);
    const fullAtEnd = await untilFull();
    watching = false;
    return { full, half, fullAtStart, fullAtEnd, fullWhileMoving, drawMs, widths: [...widths] };
  }, name);
}

test('while the skin moves, slow draws go at half resolution, and the settled face is drawn again at full resolution', async ({ page }) => {
  await openFace(page, '/?resolution=medium');
  const seen = await watchJaw(page, null);
  expect(seen.fullAtStart).toBe(true);
  expect(seen.fullAtEnd).toBe(true);
  // The view draws lower only where a full draw takes over 50 ms: software WebGL (the test browser) takes far longer;
  // a GPU that keeps up never draws lower.
  if (seen.drawMs > 50) expect(seen.widths).toContain(seen.half);
  else expect(seen.widths).toEqual([seen.full]);
  // Full resolution comes back once the motion has ended, not at an animation frame that merely came before the
  // solver's next frame (see motion-draw.ts).
  expect(seen.fullWhileMoving).toBe(false);
});

test('a face made with motionResolution 1 draws a moving face at full resolution, however slow its draws', async ({ page }) => {
  test.setTimeout(120_000);
  await openEmbedPage(page);
  // Two faces alike but for the option: where draws are slow, the one with the default draws lower while it moves.
  await addFaces(
    page,
    { steady: { resolution: 'medium', motionResolution: 1 }, usual: { resolution: 'medium' } },
    { width: 560, height: 420 },
  );
  const usual = await watchJaw(page, 'usual');
  const steady = await watchJaw(page, 'steady');
  console.log(`a full draw: ${steady.drawMs.toFixed(0)} and ${usual.drawMs.toFixed(0)} ms; widths ${steady.widths} and ${usual.widths}`);
  expect(steady.fullAtEnd && usual.fullAtEnd).toBe(true);
  expect(steady.widths).toEqual([steady.full]);
  if (usual.drawMs > 50) expect(usual.widths).toContain(usual.half);
});
