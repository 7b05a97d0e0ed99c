import { openFace } from './face';
import { expect, test } from './shared-app';

declare global {
  interface Window {
    /** Pixels of a box of the face's picture (page pixels), with a luma function, after the skin settled. */
    pictureBox: (box: {
      x0: number;
      y0: number;
      x1: number;
      y1: number;
    }) => Promise<{ luma: number[]; width: number; scale: number; white: number }>;
  }
}

test('AU51 at E turns the face 40 to 50 degrees with the eyes and teeth, and the neck skin bunches on the near side', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  await page.evaluate(() => {
    window.pictureBox = async ({ x0, y0, x1, y1 }) => {
      await window.face.settle(30_000);
      const picture = await createImageBitmap(await window.face.savePNG());
      const canvas = document.createElement('canvas');
      canvas.width = picture.width;
      canvas.height = picture.height;
      const g = canvas.getContext('2d')!;
      g.drawImage(picture, 0, 0);
      // savePNG has the canvas's pixels; the page's are smaller by the device pixel ratio.
      const scale = picture.width / document.querySelector('canvas')!.getBoundingClientRect().width;
      const [a, b] = [Math.round(x0 * scale), Math.round(y0 * scale)];
      const { data, width } = g.getImageData(a, b, Math.max(1, Math.round((x1 - x0) * scale)), Math.max(1, Math.round((y1 - y0) * scale)));
      const luma: number[] = [];
      let white = 0;
      for (let i = 0; i < data.length; i += 4) {
        luma.push(0.3 * data[i] + 0.59 * data[i + 1] + 0.11 * data[i + 2]);
        // Teeth: bright and nearly grey (skin is as bright at its highlights, but red).
        if (Math.min(data[i], data[i + 1], data[i + 2]) > 150 && data[i] - data[i + 2] < 40) white++;
      }
      return { luma, width, scale, white };
    };
  });

  // Where the ears and nose are on screen at rest and turned: the view turns the head's frame, so the projected
  // landmarks show the turn the viewer sees.
  const where = () =>
    page.evaluate(() => {
      const l = window.face.describeHead().landmarks;
      return {
        earL: window.face.locatePoint(l['ear-l'])!,
        earR: window.face.locatePoint(l['ear-r'])!,
        nose: window.face.locatePoint(l['nose-tip'])!,
      };
    });
  const before = await where();
  await page.evaluate(async () => {
    window.face.setFACS('51');
    await window.face.settle(30_000);
  });
  const after = await where();
  expect(await page.evaluate(() => window.face.getHeadPose())).toEqual({ yaw: 45, pitch: 0, roll: 0, forward: 0 });
  // Turned by a about the vertical, the ears' span seen from the front shrinks to cos(a) of itself.
  const span = (p: typeof before) => p.earL.x - p.earR.x;
  const degrees = (Math.acos(span(after) / span(before)) * 180) / Math.PI;
  console.log(`ear span ${span(before).toFixed(1)} px at rest, ${span(after).toFixed(1)} px turned: ${degrees.toFixed(1)} degrees`);
  expect(degrees).toBeGreaterThanOrEqual(40);
  expect(degrees).toBeLessThanOrEqual(50);
  // Toward the subject's left, the viewer's right.
  expect(after.nose.x - before.nose.x).toBeGreaterThan(10);

  // The skin: finite, no triangle turned over, the neck's left side (near) bunched more than its right.
  const skin = await page.evaluate(() => {
    const { rest, positions, triangles } = window.face.getSkin();
    let nonFinite = 0;
    for (const v of positions) if (!Number.isFinite(v)) nonFinite++;
    let inverted = 0;
    const areas = { left: [0, 0], right: [0, 0] };
    const lowest = Math.min(...Array.from({ length: rest.length / 3 }, (_, i) => rest[3 * i + 1]));
    const normal = (p: Float32Array, a: number, b: number, c: number) => {
      const u = [0, 1, 2].map((k) => p[3 * b + k] - p[3 * a + k]);
      const w = [0, 1, 2].map((k) => p[3 * c + k] - p[3 * a + k]);
      return [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
    };
    for (let t = 0; t < triangles.length; t += 3) {
      const [a, b, c] = [triangles[t], triangles[t + 1], triangles[t + 2]];
      const n0 = normal(rest, a, b, c);
      const n1 = normal(positions, a, b, c);
      if (n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2] < 0) inverted++;
      // The neck's sides: the 3 cm above its lowest point, 2 cm or more off the midline.
      const x = (rest[3 * a] + rest[3 * b] + rest[3 * c]) / 3;
      const y = (rest[3 * a + 1] + rest[3 * b + 1] + rest[3 * c + 1]) / 3;
      if (y > lowest + 0.03 || Math.abs(x) < 0.02) continue;
      const side = areas[x > 0 ? 'left' : 'right'];
      side[0] += Math.hypot(...n1);
      side[1] += Math.hypot(...n0);
    }
    return { nonFinite, inverted, left: areas.left[0] / areas.left[1], right: areas.right[0] / areas.right[1] };
  });
  console.log(`neck side area over rest: left ${skin.left.toFixed(3)}, right ${skin.right.toFixed(3)}`);
  expect(skin).toMatchObject({ nonFinite: 0, inverted: 0 });
  expect(skin.left).toBeLessThan(skin.right - 0.02);

  // The eyes turned with the head: the near eye's iris (the darkest pixels) lies between its corners as the turned head
  // shows them. (The far eye is seen edge-on, against the dark background beside the head.)
  const irises = await page.evaluate(async () => {
    const l = window.face.describeHead().landmarks;
    const out: { inner: number; outer: number; iris: number }[] = [];
    for (const side of ['r'] as const) {
      const inner = window.face.locatePoint(l[`eye-inner-${side}`])!;
      const outer = window.face.locatePoint(l[`eye-outer-${side}`])!;
      const x0 = Math.min(inner.x, outer.x);
      const x1 = Math.max(inner.x, outer.x);
      const half = Math.max(3, 0.5 * (x1 - x0));
      const y = (inner.y + outer.y) / 2;
      const pad = 0.5 * (x1 - x0);
      const box = { x0: x0 - pad, y0: y - half, x1: x1 + pad, y1: y + half };
      const { luma, width, scale } = await window.pictureBox(box);
      const sorted = [...luma].sort((a, b) => a - b);
      const dark = sorted[Math.floor(0.05 * sorted.length)];
      let sx = 0;
      let n = 0;
      luma.forEach((v, i) => {
        if (v > dark) return;
        sx += i % width;
        n++;
      });
      out.push({ inner: inner.x, outer: outer.x, iris: box.x0 + sx / n / scale });
    }
    return out;
  });
  console.log(`near iris between the corners (px): ${JSON.stringify(irises)}`);
  for (const e of irises) {
    expect(e.iris).toBeGreaterThan(Math.min(e.inner, e.outer));
    expect(e.iris).toBeLessThan(Math.max(e.inner, e.outer));
  }

  // The teeth turned with the head: with the mouth open, the turned mouth shows them (and not with teeth hidden).
  const teeth = await page.evaluate(async () => {
    const face = window.face;
    face.setFACS('51+26+25');
    await face.settle(30_000);
    const l = face.describeHead().landmarks;
    const a = face.locatePoint(l['mouth-l'])!;
    const b = face.locatePoint(l['mouth-r'])!;
    const chin = face.locatePoint(l.chin)!;
    const box = { x0: Math.min(a.x, b.x), x1: Math.max(a.x, b.x), y0: Math.min(a.y, b.y) - 6, y1: (a.y + chin.y) / 2 };
    const shown = (await window.pictureBox(box)).white;
    face.setRenderOptions({ showTeeth: false });
    const hidden = (await window.pictureBox(box)).white;
    face.setRenderOptions({ showTeeth: true });
    return { shown, hidden };
  });
  console.log(`near-white pixels in the turned mouth: ${teeth.shown} with teeth, ${teeth.hidden} without`);
  expect(teeth.shown).toBeGreaterThan(teeth.hidden + 20);

  // Back to neutral, the head faces ahead again.
  await page.evaluate(async () => {
    window.face.setFACS('');
    await window.face.settle(30_000);
  });
  const back = await where();
  expect(Math.abs(back.nose.x - before.nose.x)).toBeLessThan(0.5);
});
