import {
  ANTIALIAS_CHOICES,
  createFace,
  decodeIdentity,
  encodeExpression,
  RESOLUTIONS,
  type Antialias,
  type FaceOptions,
  type Resolution,
} from '../embed/index';
import { HashSync } from './hash-sync';
import { requestedSolver, requestedWorkers } from './solver-choice';

/** How often the status bar's solver line is refreshed, in ms (text changes allocate, so not every frame). */
const SOLVER_STATUS_MS = 500;

/** `?resolution=low|medium|high` picks the head; medium is the default. */
function requestedResolution(): Resolution {
  const r = new URLSearchParams(location.search).get('resolution');
  return RESOLUTIONS.includes(r as Resolution) ? (r as Resolution) : 'medium';
}

/** `?antialias=auto|always|still` picks how the face is antialiased (FaceOptions.antialias); auto is the default. */
function requestedAntialias(): Antialias {
  const a = new URLSearchParams(location.search).get('antialias');
  return ANTIALIAS_CHOICES.includes(a as Antialias) ? (a as Antialias) : 'auto';
}

/** Keeps the expression (and a short timeline) in the URL hash once the face is ready. */
let hashSync: HashSync | undefined;

/** Reloads the page with another head resolution, carrying the current expression and timeline over in the URL hash. */
function switchResolution(resolution: Resolution): void {
  const params = new URLSearchParams(location.search);
  params.set('resolution', resolution);
  const presets = Object.fromEntries(window.face.listPresets().map((p) => [p.name, p.weight]));
  const hash = hashSync?.currentHash() ?? encodeExpression({ actionUnits: window.face.getActionUnits(), presets });
  location.assign(`${location.pathname}?${params}${hash}`);
}

const modelStatus = document.getElementById('status-model')!;
const solverStatus = document.getElementById('status-solver')!;
const isolationStatus = document.getElementById('status-isolation')!;
isolationStatus.textContent = crossOriginIsolated ? 'cross-origin isolated' : 'not cross-origin isolated';
isolationStatus.dataset.isolated = String(crossOriginIsolated);

const resolution = requestedResolution();
const solver = requestedSolver(location.search);
solverStatus.textContent = `solver: ${solver}, starting…`;
try {
  // The page is one user of the embedding API: one face filling the window, with panels, fetching its models and
  // rig from beside the page as the app has always been served.
  const options: FaceOptions = {
    resolution,
    solver,
    workers: requestedWorkers(location.search),
    antialias: requestedAntialias(),
    panels: true,
    assetBase: import.meta.env.BASE_URL,
    onResolution: switchResolution,
    // The app keeps an edited rig across visits; embedding pages opt in.
    autosave: true,
  };
  // The person a link names is the first head built; a name the face refuses leaves the default head.
  const identity = decodeIdentity(location.hash);
  const viewport = document.getElementById('viewport')!;
  const face = await createFace(viewport, { ...options, identity }).catch((error: Error) => {
    if (identity === null || !error.message.startsWith('createFace: identity')) throw error;
    console.warn(`URL hash: ${error.message}`);
    return createFace(viewport, options);
  });
  window.face = face;
  const showModel = (): void => {
    const head = face.describeHead();
    const vertices = face.stats().vertices;
    const triangles = face.getSkin().triangles.length / 3;
    const what = head.source === 'default' ? `${resolution} head` : head.name;
    modelStatus.textContent = `${what}: ${vertices.toLocaleString('en-US')} vertices, ${triangles.toLocaleString('en-US')} triangles`;
  };
  showModel();
  face.onChange((change) => {
    if (change === 'head') showModel();
  });
  const showSolver = (): void => {
    const s = face.stats();
    const threads = s.workers > 1 ? ` (${s.workers} workers)` : '';
    solverStatus.textContent = `solver: ${s.mode}${threads}, ${s.solveMs.toFixed(1)} ms per frame${s.sleeping ? ', at rest' : ''}`;
  };
  showSolver();
  setInterval(showSolver, SOLVER_STATUS_MS);
  // The expression lives in the URL hash from here on: a copied link reopens the same face.
  hashSync = new HashSync(face);
  document.documentElement.dataset.state = 'ready';
} catch (error) {
  modelStatus.textContent = `The face could not start: ${(error as Error).message}`;
  modelStatus.className = 'error';
  solverStatus.textContent = '';
  document.documentElement.dataset.state = 'error';
  console.error(error);
}

declare global {
  interface Window {
    /** The app's face, for scripts and tests. */
    face: import('../embed/create-face').Face;
  }
}
