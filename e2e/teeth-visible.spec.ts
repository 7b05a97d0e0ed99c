import type { Page } from '@playwright/test';
import { openFace } from './face';
import { expect, measurePNG, test } from './fixtures';
import { stillScreenshot } from './panels';

interface Box {
  x: number;
  y: number;
  width: number;
  height: number;
}

/**
 * The mouth's box on the page (client pixels), from points of the rig projected to the screen: centred across on the
 * lips' sphincter, from a little above the lips' parting line to well below it (the jaw opens downward), sized from
 * the distance between the eye sphincters' centres.
 */
async function mouthBox(page: Page): Promise<Box> {
  return page.evaluate(() => {
    const face = window.face;
    const rig = face.getRig();
    const centre = (name: string): number[] => {
      const m = rig.muscles.find((x) => x.name === name);
      if (!m || m.type === 'linear') throw new Error(`mouthBox: the rig has no sphincter named ${name}`);
      return m.center;
    };
    const at = (name: string) => {
      const p = face.locateMuscle(name);
      if (!p) throw new Error(`mouthBox: ${name} is not on the page`);
      return p;
    };
    const mouth = at('orbicularis-oris-tightener');
    const left = at('orbicularis-oculi-orbital-l');
    const right = at('orbicularis-oculi-orbital-r');
    const perMetre =
      Math.hypot(left.x - right.x, left.y - right.y) /
      Math.abs(centre('orbicularis-oculi-orbital-l')[0] - centre('orbicularis-oculi-orbital-r')[0]);
    return { x: mouth.x - 0.028 * perMetre, y: mouth.y - 0.012 * perMetre, width: 0.056 * perMetre, height: 0.04 * perMetre };
  });
}

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
