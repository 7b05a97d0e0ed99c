import { test as base, expect, type Page } from '@playwright/test';

/** Every test fails if the page logs a console error or throws. */
export const test = base.extend<{ consoleErrors: string[] }>({
  consoleErrors: [
    async ({ page }, use) => {
      const errors: string[] = [];
      page.on('console', (m) => {
        if (m.type() === 'error') errors.push(m.text());
      });
      page.on('pageerror', (e) => errors.push(e.message));
      await use(errors);
      expect(errors, 'console errors').toEqual([]);
    },
    { auto: true },
  ],
});

export { expect };

/** Waits until the page has loaded the head (or reported why not). */
export async function waitForHead(page: Page): Promise<void> {
  await expect(page.locator('html')).toHaveAttribute('data-state', /ready|error/, { timeout: 45_000 });
  await expect(page.locator('html')).toHaveAttribute('data-state', 'ready');
}

/** RGB of a screenshot's pixels, decoded by the browser itself: a patch of size x size around (x, y). */
export async function screenshotPatch(page: Page, png: Buffer, x: number, y: number, size = 8): Promise<number[][]> {
  return page.evaluate(
    async ({ data, x, y, size }) => {
      const img = new Image();
      img.src = `data:image/png;base64,${data}`;
      await img.decode();
      const c = new OffscreenCanvas(img.width, img.height);
      const ctx = c.getContext('2d')!;
      ctx.drawImage(img, 0, 0);
      const d = ctx.getImageData(Math.round(x - size / 2), Math.round(y - size / 2), size, size).data;
      const out: number[][] = [];
      for (let i = 0; i < d.length; i += 4) out.push([d[i], d[i + 1], d[i + 2]]);
      return out;
    },
    { data: png.toString('base64'), x, y, size },
  );
}

/** The page's background colour (the scene clears to the same). */
export const BACKGROUND: [number, number, number] = [0x1d, 0x20, 0x24];

/** Mean distance of a patch's pixels from a colour, summed over the channels. */
export function meanDistance(patch: number[][], rgb: readonly number[]): number {
  return patch.reduce((s, p) => s + Math.abs(p[0] - rgb[0]) + Math.abs(p[1] - rgb[1]) + Math.abs(p[2] - rgb[2]), 0) / patch.length;
}

/** How two pictures (PNG bytes) differ, decoded by the browser: mean and largest channel difference, RGB only. */
export interface PictureDifference {
  sameSize: boolean;
  mean: number;
  max: number;
  /** Pixels of the first picture brighter than the background in red (the face's, not the backdrop's). */
  lit: number;
}

export async function comparePictures(page: Page, a: Buffer, b: Buffer): Promise<PictureDifference> {
  return page.evaluate(
    async ([a, b]) => {
      const pixels = async (data: string): Promise<Uint8ClampedArray> => {
        const image = await createImageBitmap(await (await fetch(`data:image/png;base64,${data}`)).blob());
        const c = new OffscreenCanvas(image.width, image.height);
        const ctx = c.getContext('2d')!;
        ctx.drawImage(image, 0, 0);
        return ctx.getImageData(0, 0, image.width, image.height).data;
      };
      const [A, B] = [await pixels(a), await pixels(b)];
      if (A.length !== B.length) return { sameSize: false, mean: Number.NaN, max: Number.NaN, lit: 0 };
      let sum = 0;
      let max = 0;
      let lit = 0;
      for (let i = 0; i < A.length; i += 4) {
        for (let c = 0; c < 3; c++) {
          const d = Math.abs(A[i + c] - B[i + c]);
          sum += d;
          max = Math.max(max, d);
        }
        if (A[i] > 90) lit++;
      }
      return { sameSize: true, mean: sum / ((3 * A.length) / 4), max, lit };
    },
    [a.toString('base64'), b.toString('base64')],
  );
}
