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
