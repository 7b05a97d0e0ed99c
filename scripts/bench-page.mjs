/**
 * The solver's answer in the page: `npm run bench:page [-- options]`. Builds the app, serves it (vite preview, so the
 * page is cross-origin isolated), and for each expression, from rest, measures how long after the input the skin is
 * within 2 % of its final shape (every vertex nearer its final place than 2 % of the largest move), when that shape is
 * first on screen, when the first frame of the answer is, and when the solver sleeps; `reset` goes back to rest from
 * the expression before it, within 0.01 mm. A frame is on screen once the GPU has done the draw that showed it (a
 * WebGL fence after the draw). Prints a table of medians and writes bench-results/page.json.
 * Software WebGL (SwiftShader) draws on the same cores as the solver: the on-screen columns are the display's, the
 * first the skin's.
 *
 * Copying every frame out of the page costs the page time (a megabyte a frame through `getSkin`, about a tenth of
 * happiness's time to 2 % here), so a first pass copies the frames to find which frame is within 2 %, and the timed
 * runs read only the frame counter: the solver is deterministic, and each timed run must sleep after as many frames
 * as the first pass, or the script stops.
 *
 * Options:
 *   --resolution low|medium|high   the head (default medium)
 *   --workers 1|2|auto             solver threads (default: the page's choice, `auto`)
 *   --items AU12,happiness,AU26,reset   what to time, in this order (default)
 *   --runs N                       runs of the whole list, each in a fresh page (default 2)
 *   --wait MS                      quiet time before each input (default 3000)
 *   --no-build                     serve the last build (dist/) as it is
 */
import { spawn, execSync } from 'node:child_process';
import { mkdirSync, writeFileSync } from 'node:fs';
import { cpus } from 'node:os';
import { launchBrowser, openApp } from './browser.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(`--${name}`);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
};
const resolution = option('resolution', 'medium');
const workers = option('workers', 'auto');
const items = option('items', 'AU12,happiness,AU26,reset').split(',').filter(Boolean);
const runs = Number(option('runs', '2'));
const waitMs = Number(option('wait', '3000'));
if (!['low', 'medium', 'high'].includes(resolution)) throw new Error(`--resolution must be low, medium or high, got ${resolution}`);
if (!['1', '2', 'auto'].includes(workers)) throw new Error(`--workers must be 1, 2 or auto, got ${workers}`);
if (!Number.isInteger(runs) || runs < 1) throw new Error(`--runs must be a positive integer, got ${option('runs')}`);
/** Share of the largest move a vertex may still be from its final place; back at rest means within 0.01 mm. */
const NEAR_FINAL = 0.02;
const AT_REST = 1e-5;
const PORT = 4190;
const SETTLE_MS = 60_000;

/**
 * Runs one item in the page, polling the newest solver frame every 2 ms and sampling drawing. With `nearFrames`
 * null (the shape pass) it copies each new frame and finds the first within 2 %; otherwise it takes that frame
 * count as given and copies nothing.
 */
async function timeItem(page, item, nearFrames = null) {
  return page.evaluate(
    async ({ item, waitMs, nearFinal, atRest, settleMs, nearFrames }) => {
      const face = window.face;
      if (item !== 'reset') {
        face.reset();
        await face.settle(settleMs);
      }
      await new Promise((r) => setTimeout(r, waitMs));
      const start = face.getSkin().positions;
      const firstFrame = face.stats().frames;
      /** Each new solver frame: when the page first saw it, and its shape. */
      const frames = [];
      /**
       * Each animation frame: when, the newest solver frame then (what the view draws in it), and when the GPU had done
       * its work: a fence after the frame's draw (the view's animation-frame callback runs before this one) signals then.
       */
      const draws = [];
      const gl = document.querySelector('canvas')?.getContext('webgl2') ?? null;
      let sleptAt = null;
      let polling = true;
      const t0 = performance.now();
      const poll = () => {
        const s = face.stats();
        const n = s.frames - firstFrame;
        if (n > 0 && (frames.length === 0 || frames[frames.length - 1].n !== n))
          frames.push({ t: performance.now() - t0, n, x: nearFrames === null ? face.getSkin().positions : null });
        if (sleptAt === null && n > 0 && s.sleeping) sleptAt = { t: performance.now() - t0, n };
        for (const d of draws) {
          if (d.fence === null || gl.getSyncParameter(d.fence, gl.SYNC_STATUS) !== gl.SIGNALED) continue;
          d.doneMs = performance.now() - t0;
          gl.deleteSync(d.fence);
          d.fence = null;
        }
        if (polling) setTimeout(poll, 2);
      };
      const sample = () => {
        draws.push({
          t: performance.now() - t0,
          n: face.stats().frames - firstFrame,
          fence: gl?.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0) ?? null,
          doneMs: null,
        });
        if (polling) requestAnimationFrame(sample);
      };
      if (item === 'reset') face.reset();
      else if (item.startsWith('AU')) face.setActionUnit(item, 1);
      else face.applyPreset(item, 1);
      requestAnimationFrame(sample);
      poll();
      await face.settle(settleMs);
      // The draw of the last frames comes a little after the solver sleeps.
      await new Promise((r) => setTimeout(r, 1000));
      polling = false;
      const skin = face.getSkin();
      const final = item === 'reset' ? skin.rest : skin.positions;
      const farthest = (a, b) => {
        let worst = 0;
        for (let i = 0; i < a.length; i += 3)
          worst = Math.max(worst, (a[i] - b[i]) ** 2 + (a[i + 1] - b[i + 1]) ** 2 + (a[i + 2] - b[i + 2]) ** 2);
        return Math.sqrt(worst);
      };
      const tolerance = item === 'reset' ? atRest : nearFinal * farthest(start, final);
      const near =
        nearFrames === null
          ? (frames.find((f) => farthest(f.x, final) <= tolerance) ?? null)
          : (frames.find((f) => f.n >= nearFrames) ?? null);
      /** When the GPU had drawn the first animation frame that saw solver frame `n` or a later one. */
      const shown = (n) => draws.find((d) => d.n >= n)?.doneMs ?? null;
      for (const d of draws) if (d.fence !== null) gl.deleteSync(d.fence);
      return {
        item,
        nearMs: near?.t ?? null,
        nearFrames: near?.n ?? null,
        firstShownMs: shown(1),
        drawnMs: near ? shown(near.n) : null,
        sleepMs: sleptAt?.t ?? null,
        sleepFrames: sleptAt?.n ?? null,
      };
    },
    { item, waitMs, nearFinal: NEAR_FINAL, atRest: AT_REST, settleMs: SETTLE_MS, nearFrames },
  );
}

if (!args.includes('--no-build')) execSync('npx vite build', { stdio: 'ignore' });
const server = spawn('npx', ['vite', 'preview', '--host', '127.0.0.1', '--port', String(PORT), '--strictPort'], {
  stdio: 'ignore',
  detached: true,
});
const browser = await launchBrowser();
const results = [];
/** The shape pass's frames to 2 % and to sleep, per item. */
const shape = new Map();
try {
  // Run -1 is the shape pass; its times are not reported.
  for (let run = -1; run < runs; run++) {
    const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
    const query = new URLSearchParams({ resolution, ...(workers === 'auto' ? {} : { workers }) });
    // Tried again while the server starts.
    await openApp(page, `http://127.0.0.1:${PORT}/?${query}`, { retries: 50 });
    for (const item of items) {
      const r = await timeItem(page, item, run < 0 ? null : (shape.get(item)?.nearFrames ?? null));
      // Read after the item: a partner worker takes the solver once the warm-up is over, and shows in the next frame.
      const stats = await page.evaluate(() => window.face.stats());
      if (run < 0) {
        shape.set(item, r);
        continue;
      }
      if (r.sleepFrames !== shape.get(item).sleepFrames) {
        throw new Error(
          `${item}: the solver slept after ${r.sleepFrames} frames, the shape pass ` +
            `after ${shape.get(item).sleepFrames}: the runs did not solve the same frames`,
        );
      }
      results.push({ run, workers: stats.workers, mode: stats.mode, ...r });
    }
    await page.close();
  }
} finally {
  await browser.close();
  process.kill(-server.pid);
}

const median = (xs) => {
  const s = xs.filter((x) => x !== null).sort((a, b) => a - b);
  if (s.length === 0) return null;
  const m = s.length >> 1;
  return s.length % 2 === 1 ? s[m] : (s[m - 1] + s[m]) / 2;
};
const range = (xs) => {
  const s = xs.filter((x) => x !== null).sort((a, b) => a - b);
  return s.length === 0 ? '-' : s.length === 1 ? `${Math.round(s[0])}` : `${Math.round(s[0])}-${Math.round(s[s.length - 1])}`;
};
const rows = items.map((item) => {
  const r = results.filter((x) => x.item === item);
  return {
    item,
    medianNearMs: median(r.map((x) => x.nearMs)),
    nearMs: range(r.map((x) => x.nearMs)),
    nearFrames: median(r.map((x) => x.nearFrames)),
    medianFirstShownMs: median(r.map((x) => x.firstShownMs)),
    firstShownMs: range(r.map((x) => x.firstShownMs)),
    medianDrawnMs: median(r.map((x) => x.drawnMs)),
    drawnMs: range(r.map((x) => x.drawnMs)),
    medianSleepMs: median(r.map((x) => x.sleepMs)),
    sleepMs: range(r.map((x) => x.sleepMs)),
    sleepFrames: median(r.map((x) => x.sleepFrames)),
  };
});
const fmt = (x) => (x === null ? '-' : String(Math.round(x)));
const header =
  '| input | ms to 2 % (median, range) | frames to 2 % | first frame on screen, ms | 2 % on screen, ms | ms to sleep | frames to sleep |';
console.log(
  `The page: ${resolution} head, ${results[0]?.workers ?? '?'} worker(s), ` +
    `${results[0]?.mode ?? '?'} mode, ${runs} run(s), ${cpus().length} cores\n`,
);
console.log(
  [
    header,
    header.replace(/[^|]+/g, ' --- '),
    ...rows.map(
      (r) =>
        `| ${r.item} | ${fmt(r.medianNearMs)} (${r.nearMs}) | ${fmt(r.nearFrames)} | ${fmt(r.medianFirstShownMs)} (${r.firstShownMs}) ` +
        `| ${fmt(r.medianDrawnMs)} (${r.drawnMs}) | ${fmt(r.medianSleepMs)} (${r.sleepMs}) | ${fmt(r.sleepFrames)} |`,
    ),
  ].join('\n'),
);
mkdirSync('bench-results', { recursive: true });
const machine = { cpu: cpus()[0]?.model ?? 'unknown', cores: cpus().length };
writeFileSync(
  'bench-results/page.json',
  `${JSON.stringify({ machine, date: new Date().toISOString(), resolution, runs, rows, results }, null, 2)}\n`,
);
console.log('\nwrote bench-results/page.json');
