import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { unzipSync } from 'fflate';
import { launchWithFakeCamera } from './fake-camera';
import { openFace } from './face';
import { control, openFolder } from './panels';
import { expect, test } from './fixtures';

/**
 * The webcam tracker without a person: the face records itself playing a known timeline, the frames become a fake
 * camera file (YUV4MPEG2, which Chromium plays as its camera, looping), and a second browser with that camera tracks
 * it. Each frame carries its number in a row of black and white squares at its top left, so the test knows which
 * frame the camera shows: it takes the viewer's neutral face in the clip's neutral lead-in (`calibrateTracking`), and
 * compares the Action Units the tracker recovers with the timeline's at the frames they were read from (matched by
 * the frame's capture time, `trackingState().capturedAt`), at each unit's best lag up to a second.
 */
const FPS = 6;
/**
 * The clip's neutral lead-in, seconds. The camera starts with the tracker, which is ready 2 to 3 s later: a lead-in
 * that long still has the calibration's second (and a frame or two of latency) left, so the test need not wait for
 * the clip to come round again.
 */
const LEAD = 5;
const SECONDS = LEAD + 9;
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
const MARK = 24;
const BITS = 8;
const UNITS = [
  ['AU1+AU2', ['AU1L', 'AU1R', 'AU2L', 'AU2R']],
  ['AU12', ['AU12L', 'AU12R']],
  ['AU26', ['AU26']],
  ['AU43', ['AU43L', 'AU43R']],
] as const;

function correlation(a: number[], b: number[]): number {
  const n = a.length;
  const ma = a.reduce((s, x) => s + x, 0) / n;
  const mb = b.reduce((s, x) => s + x, 0) / n;
  let ab = 0;
  let aa = 0;
  let bb = 0;
  for (let i = 0; i < n; i++) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) ** 2;
    bb += (b[i] - mb) ** 2;
  }
  return aa > 0 && bb > 0 ? ab / Math.sqrt(aa * bb) : 0;
}

/** The `q` quantile of `values` (nearest rank). */
function quantile(values: number[], q: number): number {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
}

test('the tracker follows a recorded face from a fake camera: AU1+AU2, AU12, AU26 and AU43 correlate with the timeline', async ({
  page,
  baseURL,
}) => {
  test.setTimeout(300_000);
  await openFace(page, '/?resolution=low');
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
  const dir = mkdtempSync(join(tmpdir(), 'softface-camera-'));
  const file = join(dir, 'face.y4m');
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
  writeFileSync(file, Buffer.concat(parts));
  // The recording's page is done with: closed, so that nothing of it runs beside the tracker.
  await page.close();

  // A browser whose camera is the clip (looping), and the app tracking it.
  const browser = await launchWithFakeCamera(file);
  try {
    // A small page: in software WebGL every drawn frame of the face takes the tracker's time.
    const camera = await browser.newPage({ viewport: { width: 360, height: 270 } });
    await camera.context().grantPermissions(['camera'], { origin: baseURL });
    await openFace(camera, `${baseURL}/?resolution=low`);
    const run = await camera.evaluate(
      async ({ seconds, lead, mark, bits }) => {
        const face = window.face;
        await face.startTracking();
        const video = face.trackingPreview()!;
        const canvas = new OffscreenCanvas(bits * mark, mark);
        const g = canvas.getContext('2d', { willReadFrequently: true })!;
        // The number of the frame the camera shows, from its squares.
        const shown = (): number => {
          g.drawImage(video, 0, 0, bits * mark, mark, 0, 0, bits * mark, mark);
          const { data } = g.getImageData(0, 0, bits * mark, mark);
          let n = 0;
          for (let bit = 0; bit < bits; bit++) if (data[4 * ((mark >> 1) * bits * mark + bit * mark + (mark >> 1))] > 128) n |= 1 << bit;
          return n;
        };
        // Every frame the video presents, by its capture time: the tracker reads the same frames (its Action Units
        // carry the capture time of the frame they come from), so each sample is matched with the frame it was made of.
        const numbers = new Map<number, number>();
        let watching = true;
        const watch = (_now: number, meta: VideoFrameCallbackMetadata): void => {
          if (meta.captureTime !== undefined) numbers.set(meta.captureTime, shown());
          if (watching) video.requestVideoFrameCallback(watch);
        };
        video.requestVideoFrameCallback(watch);
        const frame = () => new Promise((r) => requestAnimationFrame(r));
        // The neutral face: taken in the lead-in, with at least two seconds of it left (else when it comes round).
        while (shown() > lead) await frame();
        face.calibrateTracking();
        const start = performance.now();
        const samples: { frame: number; e: Record<string, number> }[] = [];
        // The latency (smoothed over a few frames) at each frame read: it is higher while the face moves.
        const latencies: number[] = [];
        let frames = face.trackingState().frames;
        while (performance.now() - start < seconds * 1000) {
          await frame();
          const state = face.trackingState();
          if (state.frames === frames) continue;
          frames = state.frames;
          const shownThen = numbers.get(state.capturedAt);
          if (state.calibrated && shownThen !== undefined) {
            samples.push({ frame: shownThen, e: face.getEffectiveActionUnits() });
            latencies.push(state.latencyMs);
          }
        }
        watching = false;
        const state = face.trackingState();
        face.stopTracking();
        return { samples, state, latencies };
      },
      { seconds: SECONDS, lead: (LEAD - 2) * FPS, mark: MARK, bits: BITS },
    );
    console.log(`tracking: ${run.samples.length} samples, ${JSON.stringify(run.state)}`);
    expect(run.samples.length).toBeGreaterThan(20);
    const tracked = run.samples.map((s) => UNITS.map(([, ids]) => ids.reduce((sum, id) => sum + s.e[id], 0) / ids.length));
    // The timeline at the frame each sample was made from, less a lag for each unit (the best of 0 to a second): the
    // tracker's smoothing, and the skin's own time to follow the timeline in the recording, which differs by unit
    // (0 to 2 frames here).
    const best = UNITS.map((_, u) => {
      let unit = { lag: 0, r: -Infinity };
      for (let lag = 0; lag <= FPS; lag++) {
        const r = correlation(
          tracked.map((v) => v[u]),
          run.samples.map((s) => expected[(s.frame - lag + frames) % frames][u]),
        );
        if (r > unit.r) unit = { lag, r };
      }
      return unit;
    });
    console.log(
      `correlation at the best lag (frames): ${UNITS.map(([name], u) => `${name} ${best[u].r.toFixed(2)} (${best[u].lag})`).join(', ')}; ` +
        `latency from camera frame to overlay: median ${quantile(run.latencies, 0.5).toFixed(0)} ms, 90th percentile ` +
        `${quantile(run.latencies, 0.9).toFixed(0)} ms, at the end ${run.state.latencyMs.toFixed(0)} ms ` +
        `(face mesh ${run.state.processMs.toFixed(0)} ms)`,
    );
    for (const [u, [name]] of UNITS.entries()) expect(best[u].r, name).toBeGreaterThanOrEqual(0.8);

    // The Tracking folder starts the same tracker, shows its state and the camera, and stops it.
    await openFolder(camera, 'Tracking');
    await control(camera, 'tracking-toggle').locator('button').click();
    await expect(control(camera, 'tracking-status')).toHaveText(/^(calibrating|tracking) · \d+ frames\/s/, { timeout: 60_000 });
    await expect(control(camera, 'tracking-preview').locator('video')).toHaveCount(1);
    await control(camera, 'tracking-toggle').locator('button').click();
    await expect(control(camera, 'tracking-status')).toHaveText('off');
    expect(await camera.evaluate(() => window.face.trackingState().on)).toBe(false);
  } finally {
    await browser.close();
    rmSync(dir, { recursive: true, force: true });
  }
});
