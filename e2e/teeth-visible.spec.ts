import type { Page } from '@playwright/test';
import { mouthBox, openFace, type Box } from './face';
import { measurePNG } from './fixtures';
import { expect, test } from './shared-app';
import { stillScreenshot } from './panels';

/**
 * Pixels of tooth colour in a box of the page: light and nearly grey (enamel is off-white; skin, lips, gums and
 * tongue are far redder).
 */
async function toothPixels(page: Page, box: Box): Promise<{ count: number; total: number }> {
  const png = await stillScreenshot(page, { clip: box });
  return measurePNG(
    page,
    png,
    ({ pixels }) => {
      const d = pixels.data;
      let count = 0;
      for (let i = 0; i < d.length; i += 4) {
        const [r, g, b] = [d[i], d[i + 1], d[i + 2]];
        // Measured: enamel about (215, 209, 198); lit skin and lips (215, 187, 168) and redder.
        if (g > 150 && r - g < 14 && r - b < 30) count++;
      }
      return { count, total: d.length / 4 };
    },
    {},
  );
}

test('with the jaw open (AU26) the teeth show between the lips; closed at rest, none shows through the parting line', async ({ page }) => {
  test.setTimeout(180_000);
  await openFace(page, '/?resolution=low');
  await page.evaluate(() => window.face.settle(60_000));
  const box = await mouthBox(page);
  const rest = await toothPixels(page, box);

  await page.evaluate(async () => {
    window.face.setActionUnit('AU26', 1);
    await window.face.settle(120_000);
  });
  const open = await toothPixels(page, box);
  // The same open mouth with the teeth hidden: what is left of tooth colour is not the teeth.
  await page.evaluate(() => window.face.setRenderOptions({ showTeeth: false }));
  const hidden = await toothPixels(page, box);
  console.log(
    `tooth-coloured pixels of ${open.total} in the mouth: rest ${rest.count}, ` +
      `AU26 ${open.count}, AU26 with the teeth hidden ${hidden.count}`,
  );

  expect(hidden.count).toBe(0);
  // Closed, the lips meet along a parting line a millimetre or so wide, and the teeth behind it lie in the lips' shadow
  // (src/render/mouth-shade.ts): no enamel shows through it (lit as in a smile, 10 pixels, 0.08 % of the box, did).
  expect(rest.count).toBe(0);
  // Open (measured: about 620 pixels, 5 % of the box: the upper incisors and canines, the back teeth of both rows).
  expect(open.count).toBeGreaterThan(0.03 * open.total);
  expect(open.count).toBeGreaterThan(20 * rest.count);
});
