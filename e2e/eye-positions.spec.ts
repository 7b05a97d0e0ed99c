import { openFace } from './face';
import { expect, test } from './shared-app';

declare global {
  interface Window {
    /** Where the subject's left iris is in a picture of the face: the centre of its darkest pixels, in page pixels. */
    irisAt: () => Promise<{ x: number; y: number }>;
  }
}

test('the eye positions AU61 to AU64 turn both eyes in the picture, and a FACS code turns them too', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  await page.evaluate(() => {
    const face = window.face;
    const l = face.describeHead().landmarks;
    // A box round the left eye, from its corners as the camera shows them.
    const inner = face.locatePoint(l['eye-inner-l'])!;
    const outer = face.locatePoint(l['eye-outer-l'])!;
    window.irisAt = async () => {
      await face.settle(30_000);
      const picture = await createImageBitmap(await face.savePNG());
      const canvas = document.createElement('canvas');
      canvas.width = picture.width;
      canvas.height = picture.height;
      const g = canvas.getContext('2d')!;
      g.drawImage(picture, 0, 0);
      // savePNG has the canvas's pixels; the page's are smaller by the device pixel ratio.
      const scale = picture.width / document.querySelector('canvas')!.getBoundingClientRect().width;
      const x0 = Math.round(Math.min(inner.x, outer.x) * scale);
      const x1 = Math.round(Math.max(inner.x, outer.x) * scale);
      const half = Math.round(0.6 * (x1 - x0));
      const y0 = Math.round(((inner.y + outer.y) / 2) * scale) - half;
      const { data, width } = g.getImageData(x0, y0, x1 - x0, 2 * half);
      const luma = (i: number) => 0.3 * data[4 * i] + 0.59 * data[4 * i + 1] + 0.11 * data[4 * i + 2];
      const values = Array.from({ length: data.length / 4 }, (_, i) => luma(i)).sort((a, b) => a - b);
      // The darkest tenth of the box: pupil and iris (the lashes are thin and few at low resolution).
      const dark = values[Math.floor(0.1 * values.length)];
      let sx = 0;
      let sy = 0;
      let n = 0;
      for (let i = 0; i < data.length / 4; i++) {
        if (luma(i) > dark) continue;
        sx += i % width;
        sy += Math.floor(i / width);
        n++;
      }
      return { x: (x0 + sx / n) / scale, y: (y0 + sy / n) / scale };
    };
  });
  const at = async (code: string) => {
    await page.evaluate((code) => window.face.setFACS(code), code);
    return page.evaluate(() => window.irisAt());
  };
  const ahead = await at('');
  const left = await at('61');
  const right = await at('62');
  const up = await at('63');
  const down = await at('64');
  console.log(`iris centre (px): ahead ${JSON.stringify(ahead)}, 61 ${JSON.stringify(left)}, 62 ${JSON.stringify(right)}`);
  // The subject's left is the viewer's right: AU61 moves the iris right on screen, AU62 left; AU63 up, AU64 down.
  expect(left.x - ahead.x).toBeGreaterThan(2);
  expect(ahead.x - right.x).toBeGreaterThan(2);
  expect(ahead.y - up.y).toBeGreaterThan(1);
  expect(down.y - ahead.y).toBeGreaterThan(1);
  // The sideways turns move no skin; up and down move the upper lids with the eyes.
  const skin = await page.evaluate(async () => {
    const face = window.face;
    const moved = async (code: string) => {
      face.setFACS(code);
      await face.settle(30_000);
      const { rest, positions } = face.getSkin();
      let far = 0;
      for (let i = 0; i < rest.length; i++) far = Math.max(far, Math.abs(positions[i] - rest[i]));
      return 1000 * far;
    };
    return { sideways: await moved('61'), down: await moved('64') };
  });
  expect(skin.sideways).toBe(0);
  expect(skin.down).toBeGreaterThan(1);
  // Back to neutral, the eyes look ahead again.
  const back = await at('0');
  expect(Math.abs(back.x - ahead.x)).toBeLessThan(0.5);
  expect(Math.abs(back.y - ahead.y)).toBeLessThan(0.5);
});
