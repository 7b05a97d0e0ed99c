import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import type { BrowserContext } from '@playwright/test';
import { openFace } from './face';
import { expect, test } from './fixtures';
import { control, openFolder, setSlider } from './panels';

/** AU12 (the smile) rising from 0.2 s, held, and gone by 1.8 s: the first frames are neutral, the middle smiles. */
const SMILE = {
  format: 'softface-timeline',
  duration: 2,
  actions: [{ target: 'AU12', start: 0.2, intensity: 1, onset: 0.5, apex: 0.6, offset: 0.5 }],
};

/** The page where videos are decoded: the app's own page has its copy of mediabunny, which may be loaded only once. */
const DECODER_ORIGIN = 'http://localhost:4394';
const MEDIABUNNY = fileURLToPath(new URL('../node_modules/mediabunny/dist/bundles/mediabunny.cjs', import.meta.url));

/** What the decoding page reports of a WebM video, against a PNG of the neutral face. */
interface Decoded {
  codec: string;
  width: number;
  height: number;
  timestamps: number[];
  /** SHA-256 of each decoded frame's RGBA pixels. */
  hashes: string[];
  /** Per frame: mean absolute difference from the neutral picture (per channel, 0..255). */
  meanDifference: number[];
  /** Per frame: pixels that differ from the neutral picture by more than 40 (summed over RGB), and their centroid. */
  changed: number[];
  centroid: [number, number][];
}

/** Demuxes (mediabunny) and decodes (WebCodecs VideoDecoder) a WebM video in a page of its own on localhost. */
async function decode(context: BrowserContext, webm: string, neutral: string): Promise<Decoded> {
  const page = await context.newPage();
  try {
    await page.route(`${DECODER_ORIGIN}/**`, (route) =>
      route.fulfill({ contentType: 'text/html', body: '<!doctype html><title>decode</title>' }),
    );
    await page.goto(`${DECODER_ORIGIN}/`);
    await page.addScriptTag({ path: MEDIABUNNY });
    return await page.evaluate(
      async ({ webm, neutral }) => {
        const M = (globalThis as unknown as { Mediabunny: typeof import('mediabunny') }).Mediabunny;
        const bytes = Uint8Array.from(atob(webm), (c) => c.charCodeAt(0));
        const input = new M.Input({ source: new M.BufferSource(bytes), formats: [M.WEBM] });
        const track = (await input.getPrimaryVideoTrack())!;
        const config = (await track.getDecoderConfig())!;
        const frames: VideoFrame[] = [];
        let failure: Error | undefined;
        const decoder = new VideoDecoder({ output: (f) => frames.push(f), error: (e) => (failure = e) });
        decoder.configure(config);
        for await (const packet of new M.EncodedPacketSink(track).packets()) decoder.decode(packet.toEncodedVideoChunk());
        await decoder.flush();
        if (failure) throw failure;
        const reference = await createImageBitmap(
          new Blob([Uint8Array.from(atob(neutral), (c) => c.charCodeAt(0))], { type: 'image/png' }),
        );
        const w = config.codedWidth!;
        const h = config.codedHeight!;
        const canvas = new OffscreenCanvas(w, h);
        const ctx = canvas.getContext('2d', { willReadFrequently: true })!;
        ctx.drawImage(reference, 0, 0);
        const base = ctx.getImageData(0, 0, w, h).data;
        const out = {
          codec: config.codec,
          width: w,
          height: h,
          timestamps: [] as number[],
          hashes: [] as string[],
          meanDifference: [] as number[],
          changed: [] as number[],
          centroid: [] as [number, number][],
        };
        for (const frame of frames) {
          out.timestamps.push(frame.timestamp);
          ctx.drawImage(frame, 0, 0);
          frame.close();
          const d = ctx.getImageData(0, 0, w, h).data;
          const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', d));
          out.hashes.push(Array.from(digest, (b) => b.toString(16).padStart(2, '0')).join(''));
          let sum = 0;
          let changed = 0;
          let cx = 0;
          let cy = 0;
          for (let i = 0; i < d.length; i += 4) {
            const diff = Math.abs(d[i] - base[i]) + Math.abs(d[i + 1] - base[i + 1]) + Math.abs(d[i + 2] - base[i + 2]);
            sum += diff;
            if (diff > 40) {
              changed++;
              cx += (i / 4) % w;
              cy += Math.floor(i / 4 / w);
            }
          }
          out.meanDifference.push(sum / (3 * w * h));
          out.changed.push(changed);
          out.centroid.push(changed > 0 ? [cx / changed / w, cy / changed / h] : [Number.NaN, Number.NaN]);
        }
        return out;
      },
      { webm, neutral },
    );
  } finally {
    await page.close();
  }
}

test.use({ viewport: { width: 320, height: 240 } });

test('record video: 2 s at 10 fps decode to 20 frames from the neutral face, the smile in the middle, the same twice', async ({
  page,
  context,
}) => {
  test.setTimeout(120_000);
  await openFace(page, '/?resolution=low');
  const recorded = await page.evaluate(async (timeline) => {
    const face = window.face;
    await face.settle(30_000);
    // The view shows the settled skin from its next frame on.
    for (let i = 0; i < 3; i++) await new Promise((resolve) => requestAnimationFrame(resolve));
    // The canvas is 320 x 240 here: the neutral face as the view shows it, at the video's size.
    const neutral = await face.savePNG();
    const toBase64 = async (blob: Blob): Promise<string> => {
      const bytes = new Uint8Array(await blob.arrayBuffer());
      let s = '';
      for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      return btoa(s);
    };
    const progress: number[] = [];
    const started = performance.now();
    const first = await face.recordVideo({ timeline, fps: 10, width: 320, height: 240, onProgress: (f) => progress.push(f) });
    const firstMs = performance.now() - started;
    // The page goes on between the recordings: the timeline plays on its own clock, as a user might let it, and the
    // eyes blink and look around (random, and kept out of the video).
    face.play();
    face.setEyeSimulation(true, { seed: 7 });
    await new Promise((resolve) => setTimeout(resolve, 700));
    const second = await face.recordVideo({ fps: 10, width: 320, height: 240, seconds: 2 });
    return {
      eyesAfter: face.getEyeSimulation(),
      playingAfter: face.timelineState().playing,
      mode: face.stats().mode,
      type: first.type,
      canvas: [
        document.querySelector('#viewport canvas')!.clientWidth,
        (document.querySelector('#viewport canvas') as HTMLCanvasElement).width,
      ],
      progress,
      firstMs,
      neutral: await toBase64(neutral),
      first: await toBase64(first),
      second: await toBase64(second),
      size: first.size,
    };
  }, SMILE);
  console.log(`recorded 20 frames in ${Math.round(recorded.firstMs)} ms, ${recorded.size} bytes, solver mode ${recorded.mode}`);
  expect(recorded.mode).toBe('shared');
  // What the recording switched off or paused runs again.
  expect(recorded.eyesAfter).toBe(true);
  expect(recorded.playingAfter).toBe(true);
  expect(recorded.type).toBe('video/webm');
  // The canvas is its own size again after the recording.
  expect(recorded.canvas).toEqual([320, 320]);
  expect(recorded.progress).toHaveLength(20);
  expect(recorded.progress[19]).toBe(1);

  const first = await decode(context, recorded.first, recorded.neutral);
  console.log(
    `${first.codec} ${first.width} x ${first.height}; mean difference from ` +
      `neutral ${first.meanDifference.map((d) => d.toFixed(1)).join(' ')}`,
  );
  console.log(`changed pixels ${first.changed.join(' ')}; middle centroid ${first.centroid[10].map((c) => c.toFixed(2))}`);
  expect(first.codec).toMatch(/^(vp09|vp8)/);
  expect([first.width, first.height]).toEqual([320, 240]);
  expect(first.timestamps).toEqual(Array.from({ length: 20 }, (_, i) => i * 100_000));
  // The first frame is the neutral face (up to the encoder's loss); the middle one smiles, around the mouth: below the
  // middle of the picture, near its vertical midline.
  expect(first.meanDifference[0]).toBeLessThan(1.5);
  expect(first.changed[0]).toBeLessThan(100);
  expect(first.changed[10]).toBeGreaterThan(500);
  const [x, y] = first.centroid[10];
  expect(x).toBeGreaterThan(0.4);
  expect(x).toBeLessThan(0.6);
  expect(y).toBeGreaterThan(0.5);
  expect(y).toBeLessThan(0.85);

  // The same timeline recorded again, after the face moved on in between, gives the same pictures.
  const second = await decode(context, recorded.second, recorded.neutral);
  expect(second.hashes).toHaveLength(20);
  expect(second.hashes).toEqual(first.hashes);
  // Not twenty copies of one picture.
  expect(new Set(first.hashes).size).toBeGreaterThan(10);
});

/** The files of a zip, by name, read through its central directory (the recorder stores PNGs uncompressed). */
function unzip(zip: Buffer): Map<string, Buffer> {
  let end = zip.length - 22;
  while (end >= 0 && zip.readUInt32LE(end) !== 0x06054b50) end--;
  expect(end).toBeGreaterThanOrEqual(0);
  const files = new Map<string, Buffer>();
  let at = zip.readUInt32LE(end + 16);
  for (let k = 0; k < zip.readUInt16LE(end + 10); k++) {
    expect(zip.readUInt32LE(at)).toBe(0x02014b50);
    expect(zip.readUInt16LE(at + 10)).toBe(0);
    const size = zip.readUInt32LE(at + 20);
    const nameLength = zip.readUInt16LE(at + 28);
    const name = zip.toString('utf8', at + 46, at + 46 + nameLength);
    const local = zip.readUInt32LE(at + 42);
    const data = local + 30 + zip.readUInt16LE(local + 26) + zip.readUInt16LE(local + 28);
    files.set(name, zip.subarray(data, data + size));
    at += 46 + nameLength + zip.readUInt16LE(at + 30) + zip.readUInt16LE(at + 32);
  }
  return files;
}

test.describe('the Video panel', () => {
  test.use({ viewport: { width: 640, height: 480 } });

  test('bad options change nothing; the panel records a PNG zip whose first frame is the neutral face, and cancels', async ({ page }) => {
    test.setTimeout(120_000);
    await openFace(page, '/?resolution=low');
    const refused = await page.evaluate(async (timeline) => {
      const face = window.face;
      const messages: string[] = [];
      for (const options of [
        { timeline, fps: Number.NaN },
        { timeline, width: 0 },
        { timeline, width: 8192 },
        { timeline, height: 241 },
        {},
        { timeline, format: 'gif' },
      ]) {
        try {
          await face.recordVideo(options as never);
          messages.push('recorded');
        } catch (error) {
          messages.push((error as Error).message);
        }
      }
      return { messages, timeline: face.getTimeline(), recording: face.isRecording() };
    }, SMILE);
    expect(refused.messages[0]).toMatch(/^recordVideo: fps: .*NaN/);
    expect(refused.messages[1]).toMatch(/^recordVideo: width: .*got 0/);
    expect(refused.messages[2]).toMatch(/^recordVideo: width: .*4096.*8192/);
    expect(refused.messages[3]).toMatch(/^recordVideo: height: expected an even number/);
    expect(refused.messages[4]).toMatch(/^recordVideo: seconds: /);
    expect(refused.messages[5]).toMatch(/^recordVideo: format: /);
    // The timeline of a refused recording was not loaded.
    expect(refused.timeline).toBeNull();
    expect(refused.recording).toBe(false);

    const neutral = await page.evaluate(async (timeline) => {
      await window.face.settle(30_000);
      for (let i = 0; i < 3; i++) await new Promise((resolve) => requestAnimationFrame(resolve));
      const png = new Uint8Array(await (await window.face.savePNG()).arrayBuffer());
      window.face.setTimeline(timeline);
      return Array.from(png);
    }, SMILE);
    await openFolder(page, 'Timeline');
    await control(page, 'video-fps').locator('select').selectOption('10');
    await control(page, 'video-format').locator('select').selectOption('PNG frames (zip)');
    await setSlider(page, 'video-seconds', 0.5);
    const [download] = await Promise.all([page.waitForEvent('download'), control(page, 'video-record').locator('button').click()]);
    expect(download.suggestedFilename()).toMatch(/^softface-\d{4}-\d\d-\d\dT\d\d-\d\d-\d\d\.zip$/);
    const files = unzip(await readFile(await download.path()));
    expect([...files.keys()]).toEqual(['frame-00000.png', 'frame-00001.png', 'frame-00002.png', 'frame-00003.png', 'frame-00004.png']);
    // The same pixels as the neutral face the view showed at this size, so the same PNG.
    expect(files.get('frame-00000.png')!.equals(Buffer.from(neutral))).toBe(true);
    // By 0.4 s the smile has started.
    expect(files.get('frame-00004.png')!.equals(Buffer.from(neutral))).toBe(false);
    await expect(control(page, 'video-message')).toHaveText(/^recorded \d+ KB$/);
    expect(await control(page, 'video-progress').evaluate((p) => (p as HTMLProgressElement).value)).toBe(1);

    // The whole timeline as WebM, cancelled once under way: the face is live again (the solver settles on its own).
    await control(page, 'video-format').locator('select').selectOption('WebM video');
    await setSlider(page, 'video-seconds', 0);
    await control(page, 'video-record').locator('button').click();
    await expect.poll(() => control(page, 'video-progress').evaluate((p) => (p as HTMLProgressElement).value)).toBeGreaterThan(0);
    await control(page, 'video-cancel').locator('button').click();
    await expect(control(page, 'video-message')).toHaveText('recording cancelled');
    const after = await page.evaluate(async () => {
      window.face.setActionUnit('AU12', 0.5);
      await window.face.settle(30_000);
      return { recording: window.face.isRecording(), au12: window.face.getActionUnits().AU12L };
    });
    expect(after).toEqual({ recording: false, au12: 0.5 });
    // The canvas has its own size back, at full resolution once the face stands still (software WebGL draws a moving
    // face at half resolution).
    const size = (): Promise<number[]> =>
      page.evaluate(() => {
        const canvas = document.querySelector('#viewport canvas') as HTMLCanvasElement;
        return [canvas.width, canvas.height];
      });
    await expect.poll(size).toEqual([640, 480]);
  });
});

test('the three solver modes record the same frames', async ({ page }) => {
  test.setTimeout(120_000);
  const zips: Record<string, string> = {};
  for (const mode of ['shared', 'transfer', 'main']) {
    await openFace(page, `/?resolution=low&solver=${mode}`);
    const recorded = await page.evaluate(async (timeline) => {
      const zip = await window.face.recordVideo({ timeline, fps: 10, width: 320, height: 240, seconds: 1, format: 'png-zip' });
      const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', await zip.arrayBuffer()));
      return { mode: window.face.stats().mode, hash: Array.from(digest, (b) => b.toString(16).padStart(2, '0')).join(''), size: zip.size };
    }, SMILE);
    expect(recorded.mode).toBe(mode);
    expect(recorded.size).toBeGreaterThan(10 * 10_000);
    zips[mode] = recorded.hash;
  }
  expect(zips.transfer).toBe(zips.shared);
  expect(zips.main).toBe(zips.shared);
});
