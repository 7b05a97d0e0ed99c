import { openFace } from './face';
import { expect, test } from './shared-app';

test('setCamera turns the view about the head and moves it nearer; bad input throws naming it and changes nothing', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const r = await page.evaluate(async () => {
    const face = window.face;
    // Share of the canvas the head covers, and the mean x of its pixels (0 left .. 1 right), from a rendered PNG.
    const look = async (): Promise<{ cover: number; x: number }> => {
      const image = await createImageBitmap(await face.savePNG());
      const c = new OffscreenCanvas(image.width, image.height);
      const ctx = c.getContext('2d')!;
      ctx.drawImage(image, 0, 0);
      const d = ctx.getImageData(0, 0, image.width, image.height).data;
      let n = 0;
      let sx = 0;
      for (let i = 0; i < d.length; i += 4) {
        if (d[i] > 90) {
          n++;
          sx += ((i / 4) % image.width) / image.width;
        }
      }
      return { cover: n / (d.length / 4), x: sx / n };
    };
    // The nose tip: the skin's most forward vertex at rest; where it is on the page.
    const { rest } = face.getSkin();
    let tip = 0;
    for (let v = 0; v < rest.length / 3; v++) if (rest[3 * v + 2] > rest[3 * tip + 2]) tip = v;
    const nose = (): number => face.locatePoint([rest[3 * tip], rest[3 * tip + 1], rest[3 * tip + 2]])!.x;
    const width = document.querySelector('#viewport canvas')!.clientWidth;
    const changes: string[] = [];
    face.onChange((c) => changes.push(c));
    const start = face.getCamera();
    const front = await look();
    const noseFront = nose();
    face.setCamera({ distance: 0.6 });
    const near = await look();
    face.setCamera({ distance: 1, yaw: 90 });
    const side = face.getCamera();
    const noseLeft = nose();
    const errors: string[] = [];
    for (const bad of [{ yaw: 200 }, { pitch: Number.NaN }, { zoom: 2 }, { distance: '2' }]) {
      try {
        face.setCamera(bad as never);
      } catch (e) {
        errors.push((e as Error).message);
      }
    }
    const after = face.getCamera();
    face.setCamera({ yaw: 0 });
    const back = await look();
    return { start, front, near, side, noseFront, noseLeft, width, errors, after, back, changes };
  });
  expect(r.start).toEqual({ yaw: 0, pitch: 0, distance: 1 });
  // Nearer, the head covers more of the picture: by about 1 / 0.6 squared, less the parts that leave it.
  expect(r.near.cover).toBeGreaterThan(1.8 * r.front.cover);
  expect(r.side).toEqual({ yaw: 90, pitch: 0, distance: 1 });
  // From the front the nose tip is in the middle of the canvas; seen from the subject's left it is the profile's
  // front, toward the picture's left edge by about the head's depth.
  expect(Math.abs(r.noseFront - r.width / 2)).toBeLessThan(0.02 * r.width);
  expect(r.width / 2 - r.noseLeft).toBeGreaterThan(0.1 * r.width);
  expect(r.errors).toEqual([
    'setCamera: yaw: expected a number from -180 to 180, got 200',
    'setCamera: pitch: expected a number from -80 to 80, got NaN',
    'setCamera: expected one of the options yaw, pitch, distance, got "zoom"',
    'setCamera: distance: expected a number from 0.2 to 5, got "2"',
  ]);
  expect(r.after).toEqual(r.side);
  // Back to the front: the same picture as at the start.
  expect(Math.abs(r.back.cover - r.front.cover)).toBeLessThan(0.001);
  expect(r.changes.filter((c) => c === 'camera')).toHaveLength(3);
});
