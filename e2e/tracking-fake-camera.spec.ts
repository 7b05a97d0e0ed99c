import { launchWithFakeCamera } from './fake-camera';
import { openFace } from './face';
import { control, openFolder } from './panels';
import { expect, test } from './fixtures';
import { FPS, LEAD, MARK, BITS, SECONDS, UNITS, readTrackingClip } from './tracking-clip';

/**
 * The webcam tracker without a person: a browser whose camera plays the clip of the face itself playing a known
 * timeline (e2e/tracking-clip.ts, recorded by the `clip` project before this test) tracks it. Each frame carries its
 * number in a row of black and white squares at its top left, so the test knows which frame the camera shows: it
 * takes the viewer's neutral face in the clip's neutral lead-in (`calibrateTracking`), and compares the Action Units
 * the tracker recovers with the timeline's at the frames they were read from (matched by the frame's capture time,
 * `trackingState().capturedAt`), at each unit's best lag up to a second.
 */
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
  const { file, expected } = readTrackingClip();
  const frames = FPS * SECONDS;
  // The page every test gets is not used: closed, so that nothing of it runs beside the tracker.
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
    // What the tracker reads in units the clip never moves (cross-talk: an opening jaw read as lip corners down, say),
    // printed for the record: the largest of each over the clip, where above 0.05.
    // (AU25, the lips parting, comes with the jaw's drop.)
    const moved = new Set<string>([...UNITS.flatMap(([, ids]) => ids), 'AU25']);
    const stray = new Map<string, number>();
    for (const s of run.samples)
      for (const [id, v] of Object.entries(s.e)) if (!moved.has(id) && v > 0.05 && v > (stray.get(id) ?? 0)) stray.set(id, v);
    console.log(`units the clip never moves, largest read: ${[...stray].map(([id, v]) => `${id} ${v.toFixed(2)}`).join(', ') || 'none'}`);

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
  }
});
