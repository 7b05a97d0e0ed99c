import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, test } from './fixtures';
import { failedRequests, serveFiles } from './packed-app';

/**
 * `examples/live-blendshapes`: the sender page streams ARKit blendshape frames over a BroadcastChannel and the face
 * page's `<soft-face>` takes them through `setBlendshapes`: the smile's Action Units rise on the face, its sliders stay.
 */
const ORIGIN = 'http://localhost:4398';
const root = (p: string): string => fileURLToPath(new URL(`../${p}`, import.meta.url));

test('a blendshape stream from another page drives the face through the overlay, the sliders untouched', async ({ page, context }) => {
  test.setTimeout(120_000);
  const failed = failedRequests(page);
  const files = (path: string): string =>
    path.startsWith('/softface/') ? join(root('dist-lib'), path.slice('/softface/'.length)) : join(root('examples/live-blendshapes'), path);
  await serveFiles(page, ORIGIN, files);
  await page.goto(`${ORIGIN}/index.html`);
  await expect.poll(() => page.evaluate(() => document.querySelector('soft-face')?.face !== undefined), { timeout: 90_000 }).toBe(true);
  await page.evaluate(() => document.querySelector('soft-face')!.face!.ready);
  const sender = await context.newPage();
  await serveFiles(sender, ORIGIN, files);
  await sender.goto(`${ORIGIN}/sender.html`);
  await expect(page.locator('#status')).toHaveText(/^\d+ frames$/, { timeout: 30_000 });
  const seen = await page.evaluate(async () => {
    const face = document.querySelector('soft-face')!.face!;
    // The smile comes and goes: its largest value over a second of frames.
    let most = 0;
    for (let i = 0; i < 20; i++) {
      most = Math.max(most, face.getEffectiveActionUnits().AU12L);
      await new Promise((r) => setTimeout(r, 60));
    }
    return { most, sliders: Object.values(face.getActionUnits()).every((v) => v === 0), shapes: face.getBlendshapes() };
  });
  expect(seen.most).toBeGreaterThan(0.5);
  expect(seen.sliders).toBe(true);
  expect(seen.shapes.mouthSmileLeft).toBeGreaterThanOrEqual(0);
  await sender.close();
  // The handle refuses an unknown name, and clearing takes the stream's units back out.
  const after = await page.evaluate(() => {
    const face = document.querySelector('soft-face')!.face!;
    let refused = '';
    try {
      face.setBlendshapes({ mouthSmile_L: 1 } as never);
    } catch (e) {
      refused = (e as Error).message;
    }
    face.clearBlendshapes();
    return { refused, smile: face.getEffectiveActionUnits().AU12L };
  });
  expect(after.refused).toBe(
    'setBlendshapes: expected one of the 52 ARKit blendshape names (eyeBlinkLeft, jawOpen, ...), got "mouthSmile_L"',
  );
  expect(after.smile).toBe(0);
  expect(failed).toEqual([]);
});
