import type { Page } from '@playwright/test';
import { addFaces, openEmbedPage } from './embed';
import { expect, test } from './fixtures';

/** What the canvas of a face went through while AU26 opened the jaw and the skin settled. */
interface Watched {
  full: number;
  half: number;
  fullAtStart: boolean;
  fullAtEnd: boolean;
  /** Whether an animation frame showed the canvas back at full width, after a half-width one, while the skin still moved. */
  fullWhileMoving: boolean;
  /** Every width the canvas took, in order (a MutationObserver on its width attribute: none is missed). */
  widths: number[];
}

/** Animation frames after `settle` by which the view has drawn the settled skin. */
const DRAWN_WITHIN_FRAMES = 10;

/** Opens the jaw of the face `name` in `window.faces` and watches its canvas. */
function watchJaw(page: Page, name: string): Promise<Watched> {
  return page.evaluate(
    async ({ name, DRAWN_WITHIN_FRAMES }) => {
      const face = window.faces[name];
      const canvas = document.querySelector(`#${name} canvas`) as HTMLCanvasElement;
      await face.settle(60_000);
      const frame = (): Promise<number> => new Promise((resolve) => requestAnimationFrame(resolve));
      const ratio = Math.min(devicePixelRatio, 2);
      const full = Math.floor(canvas.clientWidth * ratio);
      const half = Math.floor(canvas.clientWidth * ratio * 0.5);
      // A face is ready before its first picture is drawn (in software WebGL that draw, which makes the environment
      // map, takes seconds): the jaw must open after it, or the skin may settle before anything is drawn, and the
      // first picture is then a still of the open jaw. The canvas's data-quality is set by each draw.
      const shownFull = (): boolean => canvas.width === full && canvas.dataset.quality === 'full';
      /** Waits until the canvas shows a finished picture at full width (again, once nothing new has come), or gives up. */
      const untilFull = async (): Promise<boolean> => {
        const deadline = performance.now() + 20_000;
        while (!shownFull() && performance.now() < deadline) await frame();
        return shownFull();
      };
      const fullAtStart = await untilFull();
      const widths = [canvas.width];
      const observer = new MutationObserver(() => {
        if (canvas.width !== widths[widths.length - 1]) widths.push(canvas.width);
      });
      observer.observe(canvas, { attributes: true, attributeFilter: ['width'] });
      let watching = true;
      let wasHalf = false;
      let fullWhileMoving = false;
      const watch = (): void => {
        if (canvas.width === half) wasHalf = true;
        else if (wasHalf && canvas.width === full && !face.stats().sleeping) fullWhileMoving = true;
        if (watching) requestAnimationFrame(watch);
      };
      requestAnimationFrame(watch);
      face.setActionUnit('AU26', 1);
      await face.settle(60_000);
      // The solver may settle before the view has drawn its motion (a cold page draws slowly): the view takes the
      // newest skin at each animation frame, so a few frames after `settle` it has drawn it (at half width where draws
      // are slow, which ends the wait at once).
      for (let i = 0; i < DRAWN_WITHIN_FRAMES && !widths.includes(half); i++) await frame();
      const fullAtEnd = await untilFull();
      watching = false;
      // Records of the last change are delivered before this.
      await Promise.resolve();
      observer.disconnect();
      return { full, half, fullAtStart, fullAtEnd, fullWhileMoving, widths };
    },
    { name, DRAWN_WITHIN_FRAMES },
  );
}

// Whether a draw is slow is the `slowDrawMs` option's call: 0 counts every draw as slow (as software WebGL's are), a
// large number none (as a GPU that keeps up), so each face's behaviour does not hang on this machine's speed.
const ALWAYS_SLOW = 0;
const NEVER_SLOW = 600_000;

test('while the skin moves, slow draws go at half resolution and the settled face is drawn at full; draws that keep up stay full', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await openEmbedPage(page);
  await addFaces(
    page,
    { slow: { resolution: 'low', slowDrawMs: ALWAYS_SLOW }, fast: { resolution: 'low', slowDrawMs: NEVER_SLOW } },
    { width: 560, height: 420 },
  );
  const slow = await watchJaw(page, 'slow');
  const fast = await watchJaw(page, 'fast');
  console.log(`widths: slow ${slow.widths}, fast ${fast.widths}`);
  expect(slow.fullAtStart && slow.fullAtEnd && fast.fullAtStart && fast.fullAtEnd).toBe(true);
  expect(slow.widths).toContain(slow.half);
  expect(slow.widths[slow.widths.length - 1]).toBe(slow.full);
  expect(fast.widths).toEqual([fast.full]);
  // Full resolution comes back once the motion has ended, not at an animation frame that merely came before the
  // solver's next frame (see motion-draw.ts).
  expect(slow.fullWhileMoving).toBe(false);
});

test('a face made with motionResolution 1 draws a moving face at full resolution, however slow its draws', async ({ page }) => {
  test.setTimeout(120_000);
  await openEmbedPage(page);
  // Two faces alike but for the option, both with every draw slow: the one with the default draws lower while it moves.
  await addFaces(
    page,
    {
      steady: { resolution: 'low', motionResolution: 1, slowDrawMs: ALWAYS_SLOW },
      usual: { resolution: 'low', slowDrawMs: ALWAYS_SLOW },
    },
    { width: 560, height: 420 },
  );
  const usual = await watchJaw(page, 'usual');
  const steady = await watchJaw(page, 'steady');
  console.log(`widths: steady ${steady.widths}, usual ${usual.widths}`);
  expect(steady.fullAtEnd && usual.fullAtEnd).toBe(true);
  expect(steady.widths).toEqual([steady.full]);
  expect(usual.widths).toContain(usual.half);
});
