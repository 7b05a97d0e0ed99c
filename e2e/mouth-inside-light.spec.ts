import type { Page } from '@playwright/test';
import { mouthBox, openFace, type Box } from './face';
import { measurePNG } from './fixtures';
import { expect, test } from './shared-app';
import { stillScreenshot } from './panels';

/**
 * Mean luminance (0..255) of the pixels of `shown` that the teeth and tongue make (they differ from `hidden`, the same
 * view with them hidden, by more than a trace), and of the skin in the box's top rows (above the upper lip's red).
 */
async function insideAndSkin(page: Page, shown: Buffer, hidden: Buffer): Promise<{ inside: number; skin: number; parts: number }> {
  const hiddenPixels = await measurePNG(page, hidden, ({ pixels }) => Array.from(pixels.data), {});
  return measurePNG(
    page,
    shown,
    ({ pixels, hiddenPixels }) => {
      const { data: d, width, height } = pixels;
      const luminance = (i: number) => 0.2126 * d[i] + 0.7152 * d[i + 1] + 0.0722 * d[i + 2];
      let inside = 0;
      let parts = 0;
      for (let i = 0; i < d.length; i += 4) {
        const change =
          Math.abs(d[i] - hiddenPixels[i]) + Math.abs(d[i + 1] - hiddenPixels[i + 1]) + Math.abs(d[i + 2] - hiddenPixels[i + 2]);
        if (change > 24) {
          inside += luminance(i);
          parts++;
        }
      }
      let skin = 0;
      let count = 0;
      for (let y = 0; y < Math.round(0.12 * height); y++) {
        for (let x = Math.round(0.3 * width); x < Math.round(0.7 * width); x++) {
          skin += luminance(4 * (y * width + x));
          count++;
        }
      }
      return { inside: parts ? inside / parts : 0, skin: skin / count, parts };
    },
    { hiddenPixels },
  );
}

async function shot(page: Page, box: Box, showTeeth: boolean): Promise<Buffer> {
  await page.evaluate((showTeeth) => window.face.setRenderOptions({ showTeeth }), showTeeth);
  return stillScreenshot(page, { clip: box });
}

test('the room lights the open mouth through the lips only: its teeth and tongue stay darker than the skin outside', async ({ page }) => {
  test.setTimeout(180_000);
  await openFace(page, '/?resolution=low');
  await page.evaluate(async () => {
    // Only the room's light (the hemisphere and the environment), which a part inside the mouth sees through the lips.
    window.face.setLight({ keyIntensity: 0 });
    window.face.setActionUnit('AU27', 1);
    await window.face.settle(120_000);
  });
  const box = await mouthBox(page);
  const hidden = await shot(page, box, false);
  const shown = await shot(page, box, true);
  const { inside, skin, parts } = await insideAndSkin(page, shown, hidden);
  console.log(
    `room light only, AU27: ${parts} pixels of teeth and tongue, mean luminance ${inside.toFixed(1)}; ` +
      `skin above the lip ${skin.toFixed(1)}`,
  );

  expect(parts).toBeGreaterThan(0.05 * box.width * box.height);
  // Measured: 0.24 of the skin's. Lit as the face is (before the opening was measured), 0.65: the teeth, paler than
  // skin, as bright as the lips, the tongue a pink floor.
  expect(inside).toBeLessThan(0.45 * skin);
});
