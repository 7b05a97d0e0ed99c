/**
 * An automatic expression recogniser for the app's renders, shared by `npm run recognize` (scripts/recognize.mjs)
 * and the presets' browser test (e2e/recognition.spec.ts): @vladmandic/face-api's SSD MobileNet v1 finds the
 * face and FaceExpressionNet reads the detector's crop of it as one of 7 classes (neutral, happy, sad, angry,
 * fearful, disgusted, surprised), in headless Chromium with tfjs's wasm backend.
 *
 * The recogniser's page, face-api's browser bundle and its weights are served from node_modules by a small HTTP
 * server on 127.0.0.1 (a free port): nothing is copied into the repository or fetched from the internet. The
 * recogniser runs in a page of its own, so that its tensors stay out of the page being measured (which, cross-origin
 * isolated, could not load scripts from another origin anyway).
 *
 *   await showExpression(page, 'happiness');             // the app's page: settled from the neutral face
 *   const png = await renderView(page, -30);             // PNG bytes, camera turned 30° to the viewer's left
 *   const recognizer = await startRecognizer(browser);   // a Playwright Browser or BrowserContext
 *   const { top, probability, expressions } = await recognizer.recognize(png);
 *   await recognizer.close();
 *
 * Why these choices: SSD MobileNet found the face in every render (front and 30° to either side, score 0.91 or more
 * at 512 and 900 px); TinyFaceDetector missed most views from the subject's left at its usual input sizes. tfjs's
 * wasm backend (its .wasm files from @tensorflow/tfjs-backend-wasm, the version face-api's bundle carries) needs no GPU
 * and gave the seven front views of the presets the cpu backend's probabilities to three places, in 0.4 s an image
 * against the cpu backend's 6.3 s and the webgl backend's 2.3 s (SwiftShader here; 6.7 s for its first); both stay
 * options.
 */
import { createReadStream } from 'node:fs';
import { createServer } from 'node:http';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';

/** FaceExpressionNet's classes, in its output order. */
export const LABELS = ['neutral', 'happy', 'sad', 'angry', 'fearful', 'disgusted', 'surprised'];

/** The class each prototype (and the neutral face) is meant to read as; contempt has none. */
const EMOTION_LABELS = {
  neutral: 'neutral',
  happiness: 'happy',
  sadness: 'sad',
  anger: 'angry',
  fear: 'fearful',
  disgust: 'disgusted',
  surprise: 'surprised',
  contempt: null,
  // The thesis's laughing is a strong happiness.
  laughing: 'happy',
};

/**
 * The class `preset` (a preset's name, or `neutral`) is meant to read as: the prototypes by their emotion, each
 * `thesis-X` like X, `thesis-laughing` as happy; null for contempt, which the recogniser has no class for, and for a
 * name that says no emotion.
 */
export function meantLabel(preset) {
  const emotion = preset.startsWith('thesis-') ? preset.slice('thesis-'.length) : preset;
  return EMOTION_LABELS[emotion] ?? null;
}

/** The camera views: front, and turned 30° to the viewer's left (the subject's right) and right. */
export const VIEWS = [
  { view: 'front', yaw: 0 },
  { view: 'left30', yaw: -30 },
  { view: 'right30', yaw: 30 },
];

/** The page's panel column and status bar would cover part of the face (and be read as part of it). */
export const HIDE_PANELS_CSS = '.softface-panels, #status { display: none !important; }';

/**
 * Shows `preset` (or `neutral`) at full intensity in the app's `page`, started from the settled neutral face, and
 * waits until the skin settles; resolves to whether it did within `timeoutMs`. Starting from rest matters: the skin
 * may settle to a slightly different shape from another expression, and that moved the recogniser's answer (happiness
 * 0.95 happy from rest, 0.84 from fear).
 */
export async function showExpression(page, preset, timeoutMs = 60_000) {
  return page.evaluate(
    async ({ preset, timeoutMs }) => {
      const face = window.face;
      try {
        face.reset();
        await face.settle(timeoutMs);
        if (preset !== 'neutral') face.applyPreset(preset, 1);
        await face.settle(timeoutMs);
        return true;
      } catch {
        return false;
      }
    },
    { preset, timeoutMs },
  );
}

/**
 * A PNG of the app's canvas with the camera turned `yaw` degrees round the head (pitch 0, the default distance), as
 * `face.savePNG` draws it: always at full resolution, where the page's own frames may still be at the lower
 * resolution of a moving face. Resolves to its bytes (a Buffer).
 */
export async function renderView(page, yaw) {
  const dataUrl = await page.evaluate(async (yaw) => {
    const face = window.face;
    face.setCamera({ yaw, pitch: 0, distance: 1 });
    const blob = await face.savePNG();
    return new Promise((resolve, reject) => {
      const reader = new FileReader();
      reader.onload = () => resolve(reader.result);
      reader.onerror = () => reject(reader.error);
      reader.readAsDataURL(blob);
    });
  }, yaw);
  return Buffer.from(dataUrl.slice(dataUrl.indexOf(',') + 1), 'base64');
}

/**
 * The turns (degrees) around a view whose readings `recognizeView` averages. The recogniser's answer for one render
 * flips with a turn of a degree where the face is near the border between two classes (on 2026-12-06, from the
 * front: surprise surprised 0.40 at 0°, angry 0.38 at -1°; anger angry 0.88 at 0°, neutral 0.61 at 1°; turned 30° to
 * the right, fear read happy, sad and neutral at 29°, 30° and 31°), so a single render says more about the pixels
 * than about the expression.
 */
export const VIEW_JITTER = Object.freeze([-1, 0, 1]);

/**
 * What `recognizer` reads of the face in the app's `page` seen from `yaw`: renders at `yaw` plus each turn of `jitter`,
 * each class's probability averaged over the renders the detector found a face in, and the top class of that mean.
 * Resolves to a Recognition (the detection's score and box those of the render at `yaw` itself, or of the first
 * found), with `png` the render at `yaw` and `reads` each render's own top class and probability (null where no face
 * was found).
 */
export async function recognizeView(page, recognizer, yaw, jitter = VIEW_JITTER) {
  let png = null;
  const found = [];
  const reads = [];
  for (const turn of jitter) {
    const image = await renderView(page, yaw + turn);
    if (turn === 0 || png === null) png = image;
    const r = await recognizer.recognize(image);
    reads.push(r.detected ? { turn, top: r.top, probability: r.probability } : { turn, top: null, probability: null });
    if (r.detected) found.push({ turn, r });
  }
  if (found.length === 0) return { detected: false, score: null, box: null, top: null, probability: null, expressions: null, png, reads };
  const expressions = {};
  for (const label of LABELS) expressions[label] = found.reduce((sum, f) => sum + f.r.expressions[label], 0) / found.length;
  const [top, probability] = Object.entries(expressions).sort((a, b) => b[1] - a[1])[0];
  const centre = (found.find((f) => f.turn === 0) ?? found[0]).r;
  return { detected: true, score: centre.score, box: centre.box, top, probability, expressions, png, reads };
}

const faceApiDir = dirname(createRequire(import.meta.url).resolve('@vladmandic/face-api/package.json'));
/** The WebAssembly binaries of tfjs's wasm backend, which face-api's bundle carries the JavaScript of (same version). */
const wasmDir = join(dirname(createRequire(import.meta.url).resolve('@tensorflow/tfjs-backend-wasm/package.json')), 'dist');

/** The installed face-api's version (for the results' record). */
export const FACE_API_VERSION = createRequire(import.meta.url)('@vladmandic/face-api/package.json').version;

/** What the recogniser's page may ask for: the browser bundle (tfjs inside) and the networks' weights. */
const FILES = {
  '/face-api.esm.js': { file: join(faceApiDir, 'dist', 'face-api.esm.js'), type: 'text/javascript' },
};
for (const file of ['tfjs-backend-wasm.wasm', 'tfjs-backend-wasm-simd.wasm', 'tfjs-backend-wasm-threaded-simd.wasm'])
  FILES[`/wasm/${file}`] = { file: join(wasmDir, file), type: 'application/wasm' };
for (const model of ['ssd_mobilenetv1_model', 'tiny_face_detector_model', 'face_landmark_68_model', 'face_expression_model']) {
  FILES[`/model/${model}-weights_manifest.json`] = {
    file: join(faceApiDir, 'model', `${model}-weights_manifest.json`),
    type: 'application/json',
  };
  FILES[`/model/${model}.bin`] = { file: join(faceApiDir, 'model', `${model}.bin`), type: 'application/octet-stream' };
}
const PAGE = `<!doctype html>
<meta charset="utf-8">
<title>recogniser</title>
<script type="module">
  import * as faceapi from './face-api.esm.js';
  window.faceapi = faceapi;
  document.documentElement.dataset.state = 'loaded';
</script>
`;

/** Serves the recogniser's page and files on 127.0.0.1 at a free port; resolves to its URL and a close function. */
async function serve() {
  const server = createServer((req, res) => {
    const path = new URL(req.url ?? '/', 'http://localhost').pathname;
    if (path === '/') {
      res.writeHead(200, { 'Content-Type': 'text/html; charset=utf-8' }).end(PAGE);
      return;
    }
    const entry = FILES[path];
    if (!entry) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'Content-Type': entry.type });
    createReadStream(entry.file).pipe(res);
  });
  await new Promise((resolve, reject) => server.once('error', reject).listen(0, '127.0.0.1', resolve));
  const { port } = server.address();
  return {
    url: `http://127.0.0.1:${port}/`,
    close: () =>
      new Promise((resolve) => {
        // The browser keeps its connections open; closing only the listener would wait for them to time out.
        server.closeAllConnections();
        server.close(() => resolve());
      }),
  };
}

/**
 * The recogniser's settings. `detector`: 'ssd' (SSD MobileNet v1) or 'tiny' (TinyFaceDetector, input 416);
 * `minScore`: the least detection score taken as a face (face-api's default for SSD); `backend`: tfjs's, 'wasm',
 * 'cpu' or 'webgl'; `crop`: 'box' (the detector's box as it is) or 'aligned' (face-api's other pipeline: the 68-point landmark
 * net places the face, and FaceExpressionNet reads the square cut around its landmarks). On this build's renders the
 * aligned cut read 3 of the 6 prototypes as meant in front (the box 6), anger as neutral 0.99: it leaves out most of
 * the forehead, where the brows' movement shows, so the box stays the default.
 */
export const DEFAULTS = Object.freeze({ detector: 'ssd', minScore: 0.5, backend: 'wasm', crop: 'box' });

/**
 * Opens the recogniser in a new page of `browser` (a Playwright Browser or BrowserContext) and loads its networks.
 * `recognize(png)` takes PNG bytes and resolves to `{ detected, score, box, top, probability, expressions }`: the
 * detection's score and box (pixels), the top class and its probability, and every class's probability; with no face
 * found, `detected` is false and the rest null.
 */
export async function startRecognizer(browser, options = {}) {
  const settings = { ...DEFAULTS, ...options };
  if (!['ssd', 'tiny'].includes(settings.detector)) throw new Error(`detector must be ssd or tiny, got ${settings.detector}`);
  if (!['wasm', 'cpu', 'webgl'].includes(settings.backend)) throw new Error(`backend must be wasm, cpu or webgl, got ${settings.backend}`);
  if (!['aligned', 'box'].includes(settings.crop)) throw new Error(`crop must be aligned or box, got ${settings.crop}`);
  const server = await serve();
  let page;
  try {
    page = await browser.newPage();
    await page.goto(server.url);
    await page.waitForFunction(() => document.documentElement.dataset.state === 'loaded', null, { timeout: 60_000 });
    await page.evaluate(async ({ backend, detector }) => {
      const faceapi = window.faceapi;
      if (backend === 'wasm') faceapi.tf.setWasmPaths('./wasm/');
      if (!(await faceapi.tf.setBackend(backend))) throw new Error(`tfjs could not start its ${backend} backend`);
      await faceapi.tf.ready();
      const net = detector === 'ssd' ? faceapi.nets.ssdMobilenetv1 : faceapi.nets.tinyFaceDetector;
      await Promise.all([
        net.loadFromUri('./model'),
        faceapi.nets.faceLandmark68Net.loadFromUri('./model'),
        faceapi.nets.faceExpressionNet.loadFromUri('./model'),
      ]);
    }, settings);
  } catch (error) {
    await page?.close();
    await server.close();
    throw error;
  }
  return {
    settings,
    async recognize(png) {
      return page.evaluate(
        async ({ data, detector, minScore, crop }) => {
          const faceapi = window.faceapi;
          const image = new Image();
          image.src = `data:image/png;base64,${data}`;
          await image.decode();
          const options =
            detector === 'ssd'
              ? new faceapi.SsdMobilenetv1Options({ minConfidence: minScore })
              : new faceapi.TinyFaceDetectorOptions({ inputSize: 416, scoreThreshold: minScore });
          // face-api's own pipelines: with landmarks, FaceExpressionNet reads the cut around the 68 points (as its
          // README's examples do); without, the detector's box.
          const detection = faceapi.detectSingleFace(image, options);
          const result = await (crop === 'aligned' ? detection.withFaceLandmarks().withFaceExpressions() : detection.withFaceExpressions());
          if (!result) return { detected: false, score: null, box: null, top: null, probability: null, expressions: null };
          const { x, y, width, height } = result.detection.box;
          const expressions = Object.fromEntries(Object.entries(result.expressions).filter(([, p]) => typeof p === 'number'));
          const [top, probability] = Object.entries(expressions).sort((a, b) => b[1] - a[1])[0];
          return { detected: true, score: result.detection.score, box: { x, y, width, height }, top, probability, expressions };
        },
        { data: Buffer.from(png).toString('base64'), ...settings },
      );
    },
    async close() {
      await page.close();
      await server.close();
    },
  };
}
