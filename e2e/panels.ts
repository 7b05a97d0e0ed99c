import type { Locator, Page } from '@playwright/test';
import { BACKGROUND, expect, measurePNG } from './fixtures';

/** A panel control by its `data-control` name (`AU12L`, `AU12-link`, `preset-happiness`, `light-keyAzimuth`, ...). */
export function control(page: Page, name: string): Locator {
  return page.locator(`.softface-panels [data-control="${name}"]`);
}

/** Opens a closed top-level panel folder (Presets, Rendering, Light) by its title. */
export async function openFolder(page: Page, title: string): Promise<void> {
  const folder = page.locator('.softface-panels .lil-gui', {
    has: page.locator(':scope > .lil-title', { hasText: new RegExp(`^${title}$`) }),
  });
  if (await folder.evaluate((e) => e.classList.contains('lil-closed'))) await folder.locator(':scope > .lil-title').click();
}

/** Types a value into a slider's number box, as a user would, and leaves the box. */
export async function setSlider(page: Page, name: string, value: number): Promise<void> {
  const input = control(page, name).locator('input');
  await input.fill(String(value));
  await input.press('Enter');
}

/** The number a control's number box shows. */
export async function sliderValue(page: Page, name: string): Promise<number> {
  return Number(await control(page, name).locator('input').inputValue());
}

/** Skin positions after the solver has settled, as plain arrays, and the largest vertex move from rest (m). */
export async function settledSkin(page: Page): Promise<{ positions: number[]; moved: number }> {
  return page.evaluate(async () => {
    await window.face.settle(45_000);
    const { rest, positions } = window.face.getSkin();
    let moved = 0;
    for (let i = 0; i < rest.length; i += 3) {
      moved = Math.max(moved, Math.hypot(positions[i] - rest[i], positions[i + 1] - rest[i + 1], positions[i + 2] - rest[i + 2]));
    }
    return { positions: Array.from(positions), moved };
  });
}

/** Brightness of a face crop: its mean, its left and right halves', top and bottom halves', and the crop's pixels. */
export interface FaceCrop {
  mean: number;
  left: number;
  right: number;
  top: number;
  bottom: number;
  /** Mean distance of the crop's pixels from the background colour (summed over the channels). */
  fromBackground: number;
  /** Grey values, row by row, for comparing two pictures of the same crop. */
  grey: number[];
  /** The crop, in page pixels: left, top, right, bottom. */
  rect: [number, number, number, number];
}

/**
 * Screenshots the page once the picture stands still and measures the face: the box of non-background pixels left of
 * the panel column, narrowed to its middle (the face, without ears and neck). Pass an earlier crop's `rect` to
 * measure the same pixels again.
 */
export async function faceCrop(page: Page, rect?: FaceCrop['rect'], panelLeft = 700): Promise<FaceCrop> {
  // The still picture is judged where the face is: the panel column's live outputs change at every frame.
  const viewport = page.viewportSize();
  const still = viewport ? { x: 0, y: 0, width: Math.min(panelLeft, viewport.width), height: viewport.height - 60 } : undefined;
  const png = await stillScreenshot(page, { still });
  return measurePNG(
    page,
    png,
    ({ pixels, rect, panelLeft, background }) => {
      const { data: d, width } = pixels;
      const w = Math.min(panelLeft, width);
      const h = pixels.height - 60; // above the status bar
      let [x0, y0, x1, y1] = [w, h, 0, 0];
      for (let y = 0; y < h; y++) {
        for (let x = 0; x < w; x++) {
          const i = 4 * (y * width + x);
          if (Math.abs(d[i] - background[0]) + Math.abs(d[i + 1] - background[1]) + Math.abs(d[i + 2] - background[2]) > 30) {
            x0 = Math.min(x0, x);
            x1 = Math.max(x1, x);
            y0 = Math.min(y0, y);
            y1 = Math.max(y1, y);
          }
        }
      }
      if (x1 <= x0 || y1 <= y0) throw new Error('faceCrop: no head on the page');
      // The face: the middle 60 % of the head's width, from 25 % to 85 % of its height.
      const [left, top, right, bottom] = rect ?? [
        Math.round(x0 + 0.2 * (x1 - x0)),
        Math.round(y0 + 0.25 * (y1 - y0)),
        Math.round(x0 + 0.8 * (x1 - x0)),
        Math.round(y0 + 0.85 * (y1 - y0)),
      ];
      const midX = (left + right) / 2;
      const midY = (top + bottom) / 2;
      const sums = { all: 0, left: 0, right: 0, top: 0, bottom: 0, bg: 0 };
      const counts = { all: 0, left: 0, right: 0, top: 0, bottom: 0 };
      const grey: number[] = [];
      for (let y = top; y < bottom; y++) {
        for (let x = left; x < right; x++) {
          const i = 4 * (y * width + x);
          const g = (d[i] + d[i + 1] + d[i + 2]) / 3;
          grey.push(g);
          sums.all += g;
          counts.all++;
          sums.bg += Math.abs(d[i] - background[0]) + Math.abs(d[i + 1] - background[1]) + Math.abs(d[i + 2] - background[2]);
          if (x < midX) {
            sums.left += g;
            counts.left++;
          } else {
            sums.right += g;
            counts.right++;
          }
          if (y < midY) {
            sums.top += g;
            counts.top++;
          } else {
            sums.bottom += g;
            counts.bottom++;
          }
        }
      }
      return {
        mean: sums.all / counts.all,
        left: sums.left / counts.left,
        right: sums.right / counts.right,
        top: sums.top / counts.top,
        bottom: sums.bottom / counts.bottom,
        fromBackground: sums.bg / counts.all,
        grey,
        rect: [left, top, right, bottom] as [number, number, number, number],
      };
    },
    { rect, panelLeft, background: BACKGROUND },
  );
}

/** Mean absolute difference between two crops of the same size (grey levels). */
export function pictureDifference(a: FaceCrop, b: FaceCrop): number {
  if (a.grey.length !== b.grey.length) throw new Error(`pictureDifference: crops of ${a.grey.length} and ${b.grey.length} pixels`);
  let s = 0;
  for (let i = 0; i < a.grey.length; i++) s += Math.abs(a.grey[i] - b.grey[i]);
  return s / a.grey.length;
}

/** A part of the page, in CSS pixels. */
type Clip = { x: number; y: number; width: number; height: number };

/** Animation frames a still picture must outlast: the view draws a change for up to 3 frames after it. */
const STILL_FRAMES = 4;
/** Screenshot pairs tried before giving up. */
const STILL_TRIES = 20;

/**
 * A screenshot of the app's face once its picture is final: the face at rest is drawn only when something changed,
 * and a change is first drawn at a lower resolution where draws are slow (software WebGL), then again at full
 * resolution once nothing new has come for a while. So it waits for that state, the skin settled and the canvas back
 * at full resolution, then takes screenshots until two in a row, a few animation frames apart, are the same to the
 * byte. A fixed wait before one screenshot caught the lower one now and then. `clip` is the part returned; `still`
 * the part that must stand still (by default `clip`, or the whole page), so that live text elsewhere (the panels'
 * outputs) does not count.
 */
export async function stillScreenshot(page: Page, options: { clip?: Clip; still?: Clip } = {}, timeoutMs = 30_000): Promise<Buffer> {
  await page.evaluate((t) => window.face.settle(t), timeoutMs);
  const atFull = (): Promise<boolean> =>
    page.evaluate(() => {
      const canvas = document.querySelector('canvas') as HTMLCanvasElement;
      return canvas.width === Math.floor(canvas.clientWidth * Math.min(devicePixelRatio, 2));
    });
  await expect.poll(atFull, { timeout: timeoutMs }).toBe(true);
  const frames = (n: number): Promise<void> =>
    page.evaluate(async (n) => {
      for (let i = 0; i < n; i++) await new Promise((resolve) => requestAnimationFrame(resolve));
    }, n);
  const judged = { clip: options.still ?? options.clip };
  let last = await page.screenshot(judged);
  for (let tries = 0; tries < STILL_TRIES; tries++) {
    await frames(STILL_FRAMES);
    const next = await page.screenshot(judged);
    if (next.equals(last)) return options.still ? page.screenshot({ clip: options.clip }) : next;
    last = next;
  }
  throw new Error(`stillScreenshot: the picture still changed after ${STILL_TRIES} pairs of screenshots`);
}
