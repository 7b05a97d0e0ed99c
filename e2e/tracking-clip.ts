import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import type { Page } from '@playwright/test';
import { unzipSync } from 'fflate';
import { ISOLATED_PORT } from '../playwright.config';
import { expect } from './fixtures';

/**
 * The fake camera's clip for the webcam tracker's test (e2e/tracking-fake-camera.spec.ts): the face records itself
 * playing a known timeline, and the frames become a YUV4MPEG2 file, which Chromium plays as its camera, looping. Each
 * frame carries its number in a row of black and white squares at its top left, so the test knows which frame the
 * camera shows. Recording it is its own Playwright project (`clip`, e2e/tracking-clip.setup.ts), which runs beside
 * the other tests; the tracker's test runs by itself afterwards and reads the clip.
 */
export const FPS = 6;
/**
 * The clip's neutral lead-in, seconds. The camera starts with the tracker, which is ready 2 to 3 s later: a lead-in
 * that long still has the calibration's second (and a frame or two of latency) left, so the test need not wait for
 * the clip to come round again.
 */
export const LEAD = 5;
export const SECONDS = LEAD + 9;
const WIDTH = 480;
const HEIGHT = 480;
/** One event at a time after the neutral lead-in: brows, smile, jaw, closed eyes. */
const TIMELINE = {
  format: 'softface-timeline',
  version: 1,
  duration: SECONDS,
  tracks: {},
  actions: [
    { target: 'AU1', start: LEAD, intensity: 1, onset: 0.25, apex: 1.5, offset: 0.25 },
    { target: 'AU2', start: LEAD, intensity: 1, onset: 0.25, apex: 1.5, offset: 0.25 },
    { target: 'AU12', start: LEAD + 2.2, intensity: 1, onset: 0.25, apex: 1.5, offset: 0.25 },
    { target: 'AU26', start: LEAD + 4.4, intensity: 1, onset: 0.25, apex: 1.5, offset: 0.25 },
    { target: 'AU43', start: LEAD + 6.6, intensity: 1, onset: 0.25, apex: 1.5, offset: 0.25 },
  ],
};
/** The frame number's squares: 8 bits, each MARK pixels wide, along the top left. */
export const MARK = 24;
export const BITS = 8;
export const UNITS = [
  ['AU1+AU2', ['AU1L', 'AU1R', 'AU2L', 'AU2R']],
  ['AU12', ['AU12L', 'AU12R']],
  ['AU26', ['AU26']],
  ['AU43', ['AU43L', 'AU43R']],
] as const;

/** Where the clip is kept between the two projects (per port, so that two checkouts can run their tests at once). */
const CLIP_DIR = join(tmpdir(), `softface-e2e-${ISOLATED_PORT}`);
const CLIP = { file: join(CLIP_DIR, 'face.y4m'), expected: join(CLIP_DIR, 'face.json') };

/** A recorded clip: its camera file, and the Action Units (UNITS) each of its frames shows. */
export interface TrackingClip {
  file: string;
  expected: number[][];
}

/**
 * Records the clip in `page` (the app, opened on the low head) and writes it where `readTrackingClip` finds it. The
 * timeline's values at each frame's time are taken first, then the recording, each frame converted by the browser.
 */
export async function recordTrackingClip(page: Page): Promise<void> {
  const frames = FPS * SECONDS;
  // What each frame of the clip shows: the timeline's values at its time.
  const expected = await page.evaluate(
    ({ timeline, frames, fps, units }) => {
      const face = window.face;
      face.setTimeline(timeline);
      const out: number[][] = [];
      for (let i = 0; i < frames; i++) {
        face.seek(i / fps);
        const e = face.getEffectiveActionUnits();
        out.push(units.map(([, ids]) => ids.reduce((s, id) => s + e[id], 0) / ids.length));
      }
      face.seek(0);
      return out;
    },
    { timeline: TIMELINE, frames, fps: FPS, units: UNITS as unknown as [string, string[]][] },
  );
  // The clip as the recorder makes it, a zip of PNG frames.
  const zip = await page.evaluate(
    async ({ fps, width, height }) => {
      const blob = await window.face.recordVideo({ fps, width, height, format: 'png-zip' });
      const bytes = new Uint8Array(await blob.arrayBuffer());
      let text = '';
      for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      return btoa(text);
    },
    { fps: FPS, width: WIDTH, height: HEIGHT },
  );
  const pngs = Object.entries(unzipSync(Buffer.from(zip, 'base64')))
    .filter(([name]) => name.endsWith('.png'))
    .sort(([a], [b]) => a.localeCompare(b));
  expect(pngs).toHaveLength(frames);
  // Each frame decoded by the browser and turned into the camera file's YUV 4:2:0 (full range, as C420jpeg says).
  const parts: Buffer[] = [Buffer.from(`YUV4MPEG2 W${WIDTH} H${HEIGHT} F${FPS}:1 Ip A1:1 C420jpeg\n`)];
  for (const [index, [, png]] of pngs.entries()) {
    const yuv = await page.evaluate(
      async ({ data, index, mark, bits }) => {
        const image = await createImageBitmap(await (await fetch(`data:image/png;base64,${data}`)).blob());
        const c = new OffscreenCanvas(image.width, image.height);
        const g = c.getContext('2d')!;
        g.drawImage(image, 0, 0);
        const { data: rgba, width, height } = g.getImageData(0, 0, image.width, image.height);
        const out = new Uint8Array(width * height * 1.5);
        const u0 = width * height;
        const v0 = u0 + (width * height) / 4;
        for (let i = 0; i < width * height; i++) out[i] = 0.299 * rgba[4 * i] + 0.587 * rgba[4 * i + 1] + 0.114 * rgba[4 * i + 2];
        for (let y = 0; y < height; y += 2) {
          for (let x = 0; x < width; x += 2) {
            let r = 0;
            let gr = 0;
            let b = 0;
            for (const k of [y * width + x, y * width + x + 1, (y + 1) * width + x, (y + 1) * width + x + 1]) {
              r += rgba[4 * k] / 4;
              gr += rgba[4 * k + 1] / 4;
              b += rgba[4 * k + 2] / 4;
            }
            const j = (y / 2) * (width / 2) + x / 2;
            out[u0 + j] = 128 - 0.168736 * r - 0.331264 * gr + 0.5 * b;
            out[v0 + j] = 128 + 0.5 * r - 0.418688 * gr - 0.081312 * b;
          }
        }
        // The frame's number, grey squares (no colour) white for a 1.
        for (let bit = 0; bit < bits; bit++) {
          const on = (index >> bit) & 1;
          for (let y = 0; y < mark; y++) {
            for (let x = bit * mark; x < (bit + 1) * mark; x++) {
              out[y * width + x] = on ? 235 : 16;
              out[u0 + (y >> 1) * (width / 2) + (x >> 1)] = 128;
              out[v0 + (y >> 1) * (width / 2) + (x >> 1)] = 128;
            }
          }
        }
        let text = '';
        for (let i = 0; i < out.length; i += 0x8000) text += String.fromCharCode(...out.subarray(i, i + 0x8000));
        return btoa(text);
      },
      { data: Buffer.from(png).toString('base64'), index, mark: MARK, bits: BITS },
    );
    parts.push(Buffer.from('FRAME\n'), Buffer.from(yuv, 'base64'));
  }
  mkdirSync(CLIP_DIR, { recursive: true });
  writeFileSync(CLIP.file, Buffer.concat(parts));
  writeFileSync(CLIP.expected, JSON.stringify(expected));
}

/** The clip `recordTrackingClip` wrote; throws, saying how to make it, if there is none. */
export function readTrackingClip(): TrackingClip {
  if (!existsSync(CLIP.file) || !existsSync(CLIP.expected))
    throw new Error(`no fake camera clip in ${CLIP_DIR}: the clip project records it (playwright test --project=clip)`);
  return { file: CLIP.file, expected: JSON.parse(readFileSync(CLIP.expected, 'utf8')) as number[][] };
}
