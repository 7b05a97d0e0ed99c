import { readFile } from 'node:fs/promises';
import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, openFolder } from './panels';

const PNG_MAGIC = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];

test('save PNG: face.savePNG() gives the canvas as a PNG, and the button downloads it', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const png = await page.evaluate(async () => {
    const blob = await window.face.savePNG();
    const bytes = Array.from(new Uint8Array(await blob.slice(0, 8).arrayBuffer()));
    const image = await createImageBitmap(blob);
    // The middle of the picture is the face, not the background.
    const c = new OffscreenCanvas(image.width, image.height);
    const ctx = c.getContext('2d')!;
    ctx.drawImage(image, 0, 0);
    const [r, g, b] = ctx.getImageData(image.width >> 1, image.height >> 1, 1, 1).data;
    const canvas = document.querySelector('#viewport canvas') as HTMLCanvasElement;
    return {
      type: blob.type,
      size: blob.size,
      bytes,
      width: image.width,
      height: image.height,
      canvas: [canvas.width, canvas.height],
      centre: [r, g, b],
    };
  });
  console.log(`PNG: ${png.width} x ${png.height}, ${png.size} bytes, centre pixel ${png.centre}`);
  expect(png.type).toBe('image/png');
  expect(png.bytes).toEqual(PNG_MAGIC);
  expect(png.size).toBeGreaterThan(10_000);
  expect([png.width, png.height]).toEqual(png.canvas);
  expect(Math.abs(png.centre[0] - 0x1d) + Math.abs(png.centre[1] - 0x20) + Math.abs(png.centre[2] - 0x24)).toBeGreaterThan(60);

  await openFolder(page, 'Rendering');
  const [download] = await Promise.all([page.waitForEvent('download'), control(page, 'save-png').locator('button').click()]);
  expect(download.suggestedFilename()).toMatch(/^softface-\d{4}-\d\d-\d\dT\d\d-\d\d-\d\d\.png$/);
  const file = await readFile(await download.path());
  expect(Array.from(file.subarray(0, 8))).toEqual(PNG_MAGIC);
  expect(file.length).toBeGreaterThan(10_000);
});

test('face.savePNG() taken as soon as settle() resolves shows the settled skin, not the frame drawn before it', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const differences = await page.evaluate(async () => {
    const face = window.face;
    const pixels = async (): Promise<Uint8ClampedArray> => {
      const image = await createImageBitmap(await face.savePNG());
      const c = new OffscreenCanvas(image.width, image.height);
      const ctx = c.getContext('2d')!;
      ctx.drawImage(image, 0, 0);
      return ctx.getImageData(0, 0, image.width, image.height).data;
    };
    const changed = (a: Uint8ClampedArray, b: Uint8ClampedArray): number => {
      let n = 0;
      for (let i = 0; i < a.length; i += 4) if (a[i] !== b[i] || a[i + 1] !== b[i + 1] || a[i + 2] !== b[i + 2]) n++;
      return n;
    };
    const neutral = await pixels();
    const out: { item: string; smiling: number; back: number }[] = [];
    // A one-sided expression and a full preset; after each, back to neutral and a picture at once.
    for (const item of ['AU14R=0.7&AU12R=0.3', 'preset:happiness=1']) {
      face.setExpression(item);
      await face.settle(60_000);
      const smiling = changed(await pixels(), neutral);
      face.setExpression('');
      await face.settle(60_000);
      out.push({ item, smiling, back: changed(await pixels(), neutral) });
    }
    return out;
  });
  for (const d of differences) {
    // The expression shows in its picture, and the neutral picture after it is the first one, pixel for pixel.
    expect(d.smiling, d.item).toBeGreaterThan(200);
    expect(d.back, d.item).toBe(0);
  }
});
