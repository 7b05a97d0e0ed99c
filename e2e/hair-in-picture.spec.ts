import { openFace } from './face';
import { expect, test } from './shared-app';

/**
 * The brows and lashes are in the pictures the face saves: `savePNG` with them is darker where they grow than with
 * them switched off (`setAppearance`), by a clear margin, and the same elsewhere on the face.
 */
test('savePNG shows the brows and lashes where they grow, and not once they are switched off', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const r = await page.evaluate(async () => {
    const face = window.face;
    await face.settle(60_000);
    const hair = face.getHair();
    /** The page box (client pixels) around the first 200 roots of a kind of hair on the subject's left. */
    const box = (part: typeof hair.brows): number[] => {
      const xs: number[] = [];
      const ys: number[] = [];
      for (let h = 0; h < part.count && xs.length < 200; h++) {
        const o = 3 * h * part.verticesPerHair;
        if (part.positions[o] <= 0) continue;
        const p = face.locatePoint([part.positions[o], part.positions[o + 1], part.positions[o + 2]]);
        if (p) {
          xs.push(p.x);
          ys.push(p.y);
        }
      }
      return [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
    };
    const brows = box(hair.brows);
    const lashes = box(hair.lashes);
    const canvas = document.querySelector('#viewport canvas') as HTMLCanvasElement;
    const rect = canvas.getBoundingClientRect();
    /** Mean brightness (0..255) of a page box in a PNG of the canvas. */
    const brightness = async (blob: Blob, [x0, y0, x1, y1]: number[]): Promise<number> => {
      const image = await createImageBitmap(blob);
      const c = new OffscreenCanvas(image.width, image.height);
      const ctx = c.getContext('2d')!;
      ctx.drawImage(image, 0, 0);
      const sx = image.width / rect.width;
      const sy = image.height / rect.height;
      const d = ctx.getImageData(
        Math.round((x0 - rect.left) * sx),
        Math.round((y0 - rect.top) * sy),
        Math.max(1, Math.round((x1 - x0) * sx)),
        Math.max(1, Math.round((y1 - y0) * sy)),
      ).data;
      let sum = 0;
      for (let i = 0; i < d.length; i += 4) sum += (d[i] + d[i + 1] + d[i + 2]) / 3;
      return sum / (d.length / 4);
    };
    // The cheek, well below both: no hair there.
    const cheek = [brows[0], lashes[3] + 40, brows[2], lashes[3] + 60];
    const on = await face.savePNG();
    face.setAppearance({ brows: false, lashes: false });
    const off = await face.savePNG();
    return {
      brows: [await brightness(on, brows), await brightness(off, brows)],
      lashes: [await brightness(on, lashes), await brightness(off, lashes)],
      cheek: [await brightness(on, cheek), await brightness(off, cheek)],
    };
  });
  console.log(
    `brightness with / without hair: brows ${r.brows.map((v) => v.toFixed(1))}, lashes ` +
      `${r.lashes.map((v) => v.toFixed(1))}, cheek ${r.cheek.map((v) => v.toFixed(1))}`,
  );
  expect(r.brows[1] - r.brows[0]).toBeGreaterThan(15);
  expect(r.lashes[1] - r.lashes[0]).toBeGreaterThan(5);
  expect(Math.abs(r.cheek[1] - r.cheek[0])).toBeLessThan(1);
});
