import { openFace } from './face';
import { expect, test } from './fixtures';

test('between saccades and blinks the eyes hold still, and the view draws nothing for them', async ({ page }) => {
  test.setTimeout(60_000);
  await openFace(page, '/?resolution=low');
  await page.evaluate(() => window.face.settle(30_000));
  const seen = await page.evaluate(async () => {
    const face = window.face;
    const prototype = WebGL2RenderingContext.prototype;
    const drawElements = prototype.drawElements;
    let draws = 0;
    prototype.drawElements = function (this: WebGL2RenderingContext, ...args: Parameters<WebGL2RenderingContext['drawElements']>) {
      draws++;
      return drawElements.apply(this, args);
    };
    const frame = (): Promise<number> => new Promise((resolve) => requestAnimationFrame(resolve));
    const canvas = document.querySelector('canvas')!;
    /** Stretches of animation frames with the same gaze, no blink and the skin asleep: [frames, draws]. */
    const still: [number, number][] = [];
    let drawsWhileMoving = 0;
    let key = '';
    let frames = 0;
    /**
     * The stretch's frame from which draws are counted (-1: not yet), the draws before it and at its last frame (the
     * frame that ends a stretch has drawn the change that ended it).
     */
    let from = -1;
    let drawsBefore = 0;
    let drawsAtLast = 0;
    face.setEyeSimulation(true, { seed: 7 });
    try {
      const t0 = performance.now();
      while (performance.now() - t0 < 10_000) {
        await frame();
        const eyes = face.eyeStats();
        const now = eyes.blink === 0 && face.stats().sleeping ? `${eyes.gaze.yaw},${eyes.gaze.pitch}` : '';
        if (now !== '' && now === key) {
          frames++;
          // A face drawn at half resolution or without multisampling while it moved is drawn once more at full
          // quality when it stands still (software WebGL, see HeadViewOptions.motionResolution and antialias; the
          // canvas's data-quality says which it shows): draws are counted from the frame after that.
          if (from < 0 && canvas.dataset.quality === 'full') from = frames + 1;
          if (frames === from) drawsBefore = draws;
          drawsAtLast = draws;
        } else {
          if (from > 0 && frames > from) still.push([frames - from, drawsAtLast - drawsBefore]);
          if (now === '') drawsWhileMoving = draws;
          key = now;
          frames = 1;
          from = -1;
        }
      }
    } finally {
      prototype.drawElements = drawElements;
      face.setEyeSimulation(false);
    }
    return { still, drawsWhileMoving };
  });
  // The gaze held still for some frames (a fixation lasts 0.5 to 3 s), and the view drew nothing in them.
  const stillFrames = seen.still.reduce((n, [frames]) => n + frames, 0);
  expect(stillFrames).toBeGreaterThan(10);
  expect(seen.still.map(([, draws]) => draws)).toEqual(seen.still.map(() => 0));
  // It drew while the eyes and lids moved.
  expect(seen.drawsWhileMoving).toBeGreaterThan(0);
});
