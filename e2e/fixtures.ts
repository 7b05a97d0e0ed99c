import { test as base, type ConsoleMessage, expect, type JSHandle, type Page } from '@playwright/test';

declare global {
  interface Window {
    /** RGBA of a canvas's or an image's pixels, read in the page (see installPixelReader). */
    readPixels: (source: HTMLCanvasElement | Blob) => Promise<Uint8ClampedArray>;
    /** Share of the pixels of two same-size pictures whose colour differs by more than 16 levels in a channel. */
    differingShare: (a: Uint8ClampedArray, b: Uint8ClampedArray) => number;
  }
}

/**
 * Gives the page `readPixels` and `differingShare` before its own scripts run: `page.addInitScript(installPixelReader)`
 * before it loads. It runs in the page, so it uses nothing from here.
 */
export function installPixelReader(): void {
  window.readPixels = async (source) => {
    const image = await createImageBitmap(source);
    const c = new OffscreenCanvas(image.width, image.height);
    const g = c.getContext('2d')!;
    g.drawImage(image, 0, 0);
    return g.getImageData(0, 0, image.width, image.height).data;
  };
  window.differingShare = (a, b) => {
    let n = 0;
    for (let i = 0; i < a.length; i += 4) {
      if (Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2])) > 16) n++;
    }
    return n / (a.length / 4);
  };
}

/** Every test fails if the page logs a console error or throws. */
export const test = base.extend<{ consoleErrors: string[] }>({
  consoleErrors: [
    async ({ page }, use) => {
      const errors: string[] = [];
      const onConsole = (m: ConsoleMessage): void => {
        if (m.type() === 'error') errors.push(m.text());
      };
      const onError = (e: Error): void => {
        errors.push(e.message);
      };
      page.on('console', onConsole);
      page.on('pageerror', onError);
      await use(errors);
      // The page may outlive the test (see shared-app.ts): the next test counts its own errors.
      page.off('console', onConsole);
      page.off('pageerror', onError);
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

/**
 * PNG bytes decoded in the page, by the browser itself: a handle to their pixels, to measure them there (a
 * screenshot's pixels would be megabytes to send back). Dispose of it when done.
 */
async function decodePNG(page: Page, png: Buffer): Promise<JSHandle<ImageData>> {
  return page.evaluateHandle(async (data) => {
    const image = await createImageBitmap(await (await fetch(`data:image/png;base64,${data}`)).blob());
    const c = new OffscreenCanvas(image.width, image.height);
    const ctx = c.getContext('2d')!;
    ctx.drawImage(image, 0, 0);
    return ctx.getImageData(0, 0, image.width, image.height);
  }, png.toString('base64'));
}

/**
 * Runs `measure` in the page on a PNG's pixels (see `decodePNG`) and returns what it returns. It runs in the page:
 * it sees only its argument, `arg` with the pixels added.
 */
export async function measurePNG<A extends object, R>(
  page: Page,
  png: Buffer,
  measure: (arg: A & { pixels: ImageData }) => R | Promise<R>,
  arg: A,
): Promise<R> {
  const pixels = await decodePNG(page, png);
  try {
    // The page gets the pixels in place of their handle; Playwright's types cannot follow that through a generic `A`.
    return await page.evaluate<R, A & { pixels: JSHandle<ImageData> }>(measure as never, { ...arg, pixels });
  } finally {
    await pixels.dispose();
  }
}

/** RGB of a screenshot's pixels, decoded by the browser itself: a patch of size x size around (x, y). */
export async function screenshotPatch(page: Page, png: Buffer, x: number, y: number, size = 8): Promise<number[][]> {
  return measurePNG(
    page,
    png,
    ({ pixels, x, y, size }) => {
      const { data: d, width, height } = pixels;
      const x0 = Math.round(x - size / 2);
      const y0 = Math.round(y - size / 2);
      const out: number[][] = [];
      for (let py = y0; py < y0 + size; py++) {
        for (let px = x0; px < x0 + size; px++) {
          const i = 4 * (py * width + px);
          // Outside the picture, black (as a canvas reads there).
          out.push(px >= 0 && px < width && py >= 0 && py < height ? [d[i], d[i + 1], d[i + 2]] : [0, 0, 0]);
        }
      }
      return out;
    },
    { x, y, size },
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
  const [first, second] = [await decodePNG(page, a), await decodePNG(page, b)];
  try {
    return await page.evaluate(
      ({ first, second }) => {
        const [A, B] = [first.data, second.data];
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
      { first, second },
    );
  } finally {
    await Promise.all([first.dispose(), second.dispose()]);
  }
}
