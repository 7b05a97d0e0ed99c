import { FaceHandle } from '../embed/face-handle';
import { headColliders } from '../render/head-colliders';
import { loadHeadModel, type HeadModel } from '../render/head-model';
import { HeadView } from '../render/head-view';
import { SkinView } from '../render/skin-view';
import { SkinSimulation } from '../worker/skin-simulation';
import { chooseSolverMode } from '../worker/solver-mode';

const RESOLUTIONS = ['low', 'medium', 'high'] as const;
type Resolution = (typeof RESOLUTIONS)[number];

/** How often the status bar's solver line is refreshed, in ms (text changes allocate, so not every frame). */
const SOLVER_STATUS_MS = 500;

/** `?resolution=low|medium|high` picks the head; medium is the default. */
function requestedResolution(): Resolution {
  const r = new URLSearchParams(location.search).get('resolution');
  return RESOLUTIONS.includes(r as Resolution) ? (r as Resolution) : 'medium';
}

const modelStatus = document.getElementById('status-model')!;
const solverStatus = document.getElementById('status-solver')!;
const isolationStatus = document.getElementById('status-isolation')!;
isolationStatus.textContent = crossOriginIsolated ? 'cross-origin isolated' : 'not cross-origin isolated';
isolationStatus.dataset.isolated = String(crossOriginIsolated);

const face = new FaceHandle();
window.face = face;

const view = new HeadView(document.getElementById('viewport')!);
view.start();

/** Starts the skin solver for a shown head and feeds its frames to the skin mesh. */
async function startSkin(head: HeadModel, skinView: SkinView): Promise<SkinSimulation> {
  const { mode, warning } = chooseSolverMode(location.search, crossOriginIsolated);
  if (warning) console.warn(warning);
  solverStatus.textContent = `solver: ${mode}, starting…`;
  const geometry = head.skin.geometry;
  const simulation = await SkinSimulation.create({
    mode,
    renderPositions: geometry.getAttribute('position').array as Float32Array,
    indices: geometry.index!.array as Uint16Array | Uint32Array,
    colliders: headColliders(head),
  });
  skinView.connect(simulation);
  view.onFrame(() => {
    simulation.advance();
    skinView.update();
  });
  const showSolver = (): void => {
    const s = simulation.stats();
    solverStatus.textContent = `solver: ${s.mode}, ${s.solveMs.toFixed(1)} ms per frame${s.sleeping ? ', at rest' : ''}`;
  };
  showSolver();
  setInterval(showSolver, SOLVER_STATUS_MS);
  return simulation;
}

const resolution = requestedResolution();
const url = `${import.meta.env.BASE_URL}models/head-${resolution}.glb`;
/** What failed, for the status bar. */
let failing: HTMLElement = modelStatus;
let failure = 'The head could not be loaded';
try {
  const head = await loadHeadModel(url);
  // Before the first render: the skin's attributes become dynamic.
  const skinView = new SkinView(head.skin);
  view.setHead(head);
  const l = head.info.level;
  modelStatus.textContent = `${l.name} head: ${l.skinVertices.toLocaleString('en-US')} vertices, ${l.triangles.toLocaleString('en-US')} triangles`;
  failing = solverStatus;
  failure = 'The skin solver could not start';
  face.attach(await startSkin(head, skinView));
  document.documentElement.dataset.state = 'ready';
} catch (error) {
  failing.textContent = `${failure}: ${(error as Error).message}`;
  failing.className = 'error';
  face.fail(error as Error);
  document.documentElement.dataset.state = 'error';
  console.error(error);
}
