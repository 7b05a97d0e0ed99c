/**
 * Do the presets read as meant? `npm run recognize [-- low|medium|high] [options]`.
 * Builds the app, serves it, and shows neutral and every preset at full intensity (each settled from the neutral
 * face); renders each from the front and with the camera turned 30° to the viewer's left and right (900 x 900 px,
 * default light, the panels hidden), and asks an automatic recogniser (scripts/recognition.mjs: face-api's SSD
 * MobileNet face detector and FaceExpressionNet) which of its 7 classes the face shows. Prints a row per render (the
 * top class and its probability, the meant class and its probability) and a summary, writes them to
 * bench-results/recognition.json, and the same as a Markdown table for docs/recognition.md to bench-results/recognition.md.
 *
 * The meant class: happiness happy, sadness sad, anger angry, fear fearful, disgust disgusted, surprise surprised,
 * neutral neutral, each thesis-X as X and thesis-laughing as happy. Contempt has no class: its rows say `—`.
 *
 * Options:
 *   --markdown            print the Markdown table too
 *   --detector ssd|tiny   the face detector (default ssd; see recognition.mjs)
 *   --backend wasm|cpu|webgl   tfjs's backend (default wasm)
 *   --crop aligned|box    what FaceExpressionNet reads: the detector's box (default) or the cut around the 68 landmarks
 *   --images DIR          also write each render to DIR/<preset>_<view>.png
 *   --sheet FILE          also write a sheet (JPEG, or PNG if FILE ends in .png) of neutral and the seven prototypes from the front, each
 * labelled
 *                         with what it is meant to show and what the recogniser read
 *   --light JSON          light options for every render (face.setLight), e.g. '{"keyAzimuth":0}'; default the app's
 *   --appearance JSON     appearance options for every render (face.setAppearance), e.g. '{"lashes":false}'
 *   --presets a,b,...     only these presets (and neutral)
 *   --jitter -1,0,1       the turns (degrees) around each view whose readings are averaged (default -1,0,1; 0 alone:
 *                         one render a view; see VIEW_JITTER in recognition.mjs)
 *   --out PATH            where the results go: PATH.json and PATH.md (default bench-results/recognition)
 *   --no-build            serve the last build (dist/) as it is
 */
import { spawn, execSync } from 'node:child_process';
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname } from 'node:path';
import { createServer } from 'node:net';
import { cpus } from 'node:os';
import { join } from 'node:path';
import { launchBrowser, openApp } from './browser.mjs';
import {
  DEFAULTS,
  FACE_API_VERSION,
  HIDE_PANELS_CSS,
  VIEWS,
  VIEW_JITTER,
  meantLabel,
  recognizeView,
  showExpression,
  startRecognizer,
} from './recognition.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(`--${name}`);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
};
const resolution = args[0] && !args[0].startsWith('--') ? args[0] : 'medium';
if (!['low', 'medium', 'high'].includes(resolution)) throw new Error(`the resolution must be low, medium or high, got ${resolution}`);
const detector = option('detector', DEFAULTS.detector);
const backend = option('backend', DEFAULTS.backend);
const crop = option('crop', DEFAULTS.crop);
const imagesDir = option('images', null);
const sheetFile = option('sheet', null);
const light = option('light', null);
const appearance = option('appearance', null);
const only = option('presets', null)?.split(',');
const jitter = option('jitter', VIEW_JITTER.join(',')).split(',').map(Number);
if (!jitter.includes(0) || jitter.some((t) => !Number.isFinite(t) || Math.abs(t) > 10))
  throw new Error(`--jitter: turns in degrees, within 10 of the view and one of them 0, got ${option('jitter', '')}`);
const out = option('out', 'bench-results/recognition');
/** The sheet's tiles: neutral and the seven prototypes, front view. */
const SHEET_PRESETS = ['neutral', 'happiness', 'sadness', 'surprise', 'fear', 'anger', 'disgust', 'contempt'];
/** The part of the 900 px picture the face fills, for the sheet's tiles. */
const FACE_CROP = { x: 250, y: 230, width: 400, height: 520 };
const SIZE = 900;
const SETTLE_MS = 60_000;
/** The prototypes the summary counts (contempt, with no class, is left out). */
const PROTOTYPES = ['happiness', 'sadness', 'surprise', 'fear', 'anger', 'disgust'];

/** A port nothing listens on now: the script may run beside other servers of this project (tests, gallery). */
async function freePort() {
  const server = createServer();
  await new Promise((resolve, reject) => server.once('error', reject).listen(0, '127.0.0.1', resolve));
  const { port } = server.address();
  await new Promise((resolve) => server.close(resolve));
  return port;
}

const started = performance.now();
if (!args.includes('--no-build')) execSync('npx vite build', { stdio: 'ignore' });
const port = await freePort();
const server = spawn('npx', ['vite', 'preview', '--host', '127.0.0.1', '--port', String(port), '--strictPort'], {
  stdio: 'ignore',
  detached: true,
});
const browser = await launchBrowser();
const rows = [];
/** Front renders kept for the sheet, by preset. */
const fronts = new Map();
try {
  const recognizer = await startRecognizer(browser, { detector, backend, crop });
  const page = await browser.newPage({ viewport: { width: SIZE, height: SIZE } });
  // Tried again while the server starts.
  await openApp(page, `http://127.0.0.1:${port}/?resolution=${resolution}`, { timeout: 120_000, retries: 51, retryMs: 200 });
  await page.addStyleTag({ content: HIDE_PANELS_CSS });
  if (light) await page.evaluate((l) => window.face.setLight(l), JSON.parse(light));
  if (appearance) await page.evaluate((a) => window.face.setAppearance(a), JSON.parse(appearance));
  const all = await page.evaluate(() => window.face.listPresets().map((p) => p.name));
  for (const name of only ?? []) if (!all.includes(name)) throw new Error(`--presets: no preset ${name}`);
  const presets = ['neutral', ...all.filter((name) => !only || only.includes(name))];
  if (imagesDir) mkdirSync(imagesDir, { recursive: true });
  for (const preset of presets) {
    const settled = await showExpression(page, preset, SETTLE_MS);
    const meant = meantLabel(preset);
    for (const { view, yaw } of VIEWS) {
      const r = await recognizeView(page, recognizer, yaw, jitter);
      const png = r.png;
      if (imagesDir) writeFileSync(join(imagesDir, `${preset}_${view}.png`), png);
      if (sheetFile && view === 'front' && SHEET_PRESETS.includes(preset)) fronts.set(preset, { png, r, meant });
      const row = {
        preset,
        view,
        settled,
        detected: r.detected,
        detectionScore: r.score,
        top: r.top,
        probability: r.probability,
        meant,
        meantProbability: meant && r.expressions ? r.expressions[meant] : null,
        expressions: r.expressions,
        box: r.box,
        reads: r.reads,
      };
      rows.push(row);
      console.log(
        `${preset} ${view}: ${r.detected ? `${r.top} ${r.probability.toFixed(2)}` : 'no face found'}${settled ? '' : ' (not settled)'}` +
          (jitter.length > 1 ? ` (each: ${r.reads.map((x) => (x.top ? `${x.top} ${x.probability.toFixed(2)}` : 'none')).join(', ')})` : ''),
      );
    }
  }
  await recognizer.close();
  if (sheetFile) {
    const tiles = SHEET_PRESETS.filter((n) => fronts.has(n)).map((n) => {
      const { png, r, meant } = fronts.get(n);
      const read = r.detected ? `${r.top} ${r.probability.toFixed(2)}` : 'no face found';
      const label =
        meant === null
          ? `read: ${read} (no class for it)`
          : `read: ${read}${r.top === meant ? '' : ` (${meant} ${(r.expressions?.[meant] ?? 0).toFixed(2)})`}`;
      return { name: n, label, hit: meant !== null && r.top === meant, data: png.toString('base64') };
    });
    const jpeg = await page.evaluate(
      async ({ tiles, crop, type }) => {
        const columns = 4;
        const head = 28;
        const foot = 26;
        const canvas = document.createElement('canvas');
        canvas.width = columns * crop.width;
        canvas.height = Math.ceil(tiles.length / columns) * (crop.height + head + foot);
        const ctx = canvas.getContext('2d');
        ctx.fillStyle = '#1d2024';
        ctx.fillRect(0, 0, canvas.width, canvas.height);
        for (let i = 0; i < tiles.length; i++) {
          const img = new Image();
          img.src = `data:image/png;base64,${tiles[i].data}`;
          await img.decode();
          const x = (i % columns) * crop.width;
          const y = Math.floor(i / columns) * (crop.height + head + foot);
          ctx.drawImage(img, crop.x, crop.y, crop.width, crop.height, x, y + head, crop.width, crop.height);
          ctx.font = 'bold 18px sans-serif';
          ctx.fillStyle = '#e8e6e3';
          ctx.fillText(tiles[i].name, x + 10, y + 20);
          ctx.font = '15px sans-serif';
          ctx.fillStyle = tiles[i].hit ? '#8fd18f' : '#e8a0a0';
          ctx.fillText(tiles[i].label, x + 10, y + head + crop.height + 18);
        }
        return canvas.toDataURL(type, 0.85).split(',')[1];
      },
      { tiles, crop: FACE_CROP, type: sheetFile.endsWith('.png') ? 'image/png' : 'image/jpeg' },
    );
    mkdirSync(dirname(sheetFile), { recursive: true });
    writeFileSync(sheetFile, Buffer.from(jpeg, 'base64'));
    console.log(`wrote ${sheetFile}`);
  }
} finally {
  await browser.close();
  process.kill(-server.pid);
}

const hit = (r) => r.meant !== null && r.top === r.meant;
const mean = (xs) => (xs.length === 0 ? null : xs.reduce((a, b) => a + b, 0) / xs.length);
/**
 * How those of a group of presets that were rendered read (`--presets` may leave some out): hits in front, presets read
 * as meant in every view, hits over all views, mean p(meant).
 */
function group(names) {
  const shown = names.filter((n) => rows.some((r) => r.preset === n));
  const of = rows.filter((r) => shown.includes(r.preset));
  const front = of.filter((r) => r.view === 'front');
  return {
    presets: shown,
    frontHits: front.filter(hit).length,
    allViewsHits: shown.filter((n) => of.filter((r) => r.preset === n).every(hit)).length,
    viewHits: of.filter(hit).length,
    views: of.length,
    meanMeantProbability: mean(of.map((r) => r.meantProbability ?? 0)),
  };
}
const neutralRows = rows.filter((r) => r.preset === 'neutral');
const summary = {
  neutral: Object.fromEntries(neutralRows.map((r) => [r.view, { readsNeutral: hit(r), probability: r.meantProbability }])),
  prototypes: group(PROTOTYPES),
  thesis: group(rows.map((r) => r.preset).filter((p, i, all) => p.startsWith('thesis-') && all.indexOf(p) === i && meantLabel(p) !== null)),
};

const p = (x) => (x === null || x === undefined ? '-' : x.toFixed(2));
const table = [
  ['preset', 'view', 'top', 'p', 'meant', 'p(meant)'],
  ...rows.map((r) => [
    r.preset + (r.settled ? '' : ' (not settled)'),
    r.view,
    r.detected ? r.top : 'no face',
    p(r.probability),
    r.meant ?? '—',
    p(r.meantProbability),
  ]),
];
const widths = table[0].map((_, c) => Math.max(...table.map((row) => row[c].length)));
console.log(
  `\nRecognition: ${resolution} head, ${SIZE} x ${SIZE} px, face-api ${FACE_API_VERSION} ` +
    `(${detector} detector, ${crop} crop, FaceExpressionNet, tfjs ${backend})\n`,
);
console.log(table.map((row) => row.map((cell, c) => cell.padEnd(widths[c])).join('  ')).join('\n'));
const g = (x, n) =>
  `${x.frontHits} of ${n} in front, ${x.allViewsHits} of ${n} in all three views, ` +
  `${x.viewHits} of ${x.views} views; mean p(meant) ${p(x.meanMeantProbability)}`;
const neutralLine = neutralRows.map((r) => `${r.view} ${hit(r) ? 'yes' : `no (${r.top})`} ${p(r.meantProbability)}`).join(', ');
const summaryLines = [
  `neutral reads neutral: ${neutralLine}`,
  `prototypes read as meant (top label; contempt left out): ${g(summary.prototypes, summary.prototypes.presets.length)}`,
  `the thesis's presets read as meant: ${g(summary.thesis, summary.thesis.presets.length)}`,
];
console.log(`\n${summaryLines.join('\n')}`);

/** docs/recognition.md's table: a row per preset, a cell per view; the top class in bold where it is the meant one. */
const cell = (r) => {
  if (!r.detected) return 'no face found';
  if (r.meant === null) return `${r.top} ${p(r.probability)}`;
  return hit(r) ? `**${r.top} ${p(r.probability)}**` : `${r.top} ${p(r.probability)} (${p(r.meantProbability)})`;
};
const presets = rows.map((r) => r.preset).filter((x, i, all) => all.indexOf(x) === i);
const markdown = [
  "Each cell: the recogniser's top class and its probability, in bold where it is " +
    "the meant class; otherwise the meant class's probability follows in brackets. " +
    `Each view's probabilities are the mean over renders turned ${jitter.map((t) => `${t}°`).join(', ')} from it.`,
  '',
  '| preset | meant | front | 30° left | 30° right |',
  '| --- | --- | --- | --- | --- |',
  ...presets.map((name) => {
    const of = rows.filter((r) => r.preset === name);
    return `| ${name} | ${of[0].meant ?? '—'} | ${VIEWS.map(({ view }) => cell(of.find((r) => r.view === view))).join(' | ')} |`;
  }),
  '',
  ...summaryLines.map((line) => `- ${line}`),
].join('\n');
if (args.includes('--markdown')) console.log(`\n${markdown}`);

const seconds = (performance.now() - started) / 1000;
console.log(`\n${rows.length} views (${rows.length * jitter.length} renders) in ${Math.round(seconds)} s`);
mkdirSync(dirname(out), { recursive: true });
const machine = { cpu: cpus()[0]?.model ?? 'unknown', cores: cpus().length };
const recogniser = {
  faceApi: FACE_API_VERSION,
  detector,
  crop,
  backend,
  expression: 'FaceExpressionNet',
  minScore: DEFAULTS.minScore,
  jitter,
};
const lightUsed = light ? JSON.parse(light) : 'default';
writeFileSync(
  `${out}.json`,
  `${JSON.stringify(
    { machine, date: new Date().toISOString(), resolution, size: SIZE, light: lightUsed, recogniser, seconds, summary, rows },
    null,
    2,
  )}\n`,
);
writeFileSync(`${out}.md`, `${markdown}\n`);
console.log(`wrote ${out}.json and ${out}.md`);
