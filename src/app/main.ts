import { Quaternion, Vector3 } from 'three';
import { DEGREES, eulerMatrix } from '../core/math3';
import { parseRigText } from '../core/rig-schema';
import type { Rig } from '../core/rig-types';
import { FaceHandle } from '../embed/face-handle';
import { headColliders } from '../render/head-colliders';
import { loadHeadModel, type HeadModel } from '../render/head-model';
import { HeadView } from '../render/head-view';
import { MuscleView } from '../render/muscle-view';
import { SkinView } from '../render/skin-view';
import { Panels } from '../ui/panels';
import { SkinSimulation } from '../worker/skin-simulation';
import { chooseSolverMode, chooseWorkers } from '../worker/solver-mode';
import { EyeDriver } from './eye-driver';
import { encodeExpression } from './expression-hash';
import { HashSync } from './hash-sync';

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
const rigStatus = document.getElementById('status-rig')!;
const isolationStatus = document.getElementById('status-isolation')!;
isolationStatus.textContent = crossOriginIsolated ? 'cross-origin isolated' : 'not cross-origin isolated';
isolationStatus.dataset.isolated = String(crossOriginIsolated);

const face = new FaceHandle();
window.face = face;

const view = new HeadView(document.getElementById('viewport')!);
face.attachView(view);
view.start();

/** Starts the skin solver for a shown head and feeds its frames to the skin mesh. */
async function startSkin(head: HeadModel, skinView: SkinView, rig: Rig | undefined): Promise<SkinSimulation> {
  const { mode, warning } = chooseSolverMode(location.search, crossOriginIsolated);
  if (warning) console.warn(warning);
  solverStatus.textContent = `solver: ${mode}, starting…`;
  const geometry = head.skin.geometry;
  const simulation = await SkinSimulation.create({
    mode,
    workers: chooseWorkers(location.search),
    renderPositions: geometry.getAttribute('position').array as Float32Array,
    indices: geometry.index!.array as Uint16Array | Uint32Array,
    colliders: headColliders(head),
    muscles: rig?.muscles ?? [],
  });
  skinView.connect(simulation);
  view.onFrame(() => {
    simulation.advance();
    skinView.update();
  });
  const showSolver = (): void => {
    const s = simulation.stats();
    const threads = s.workers > 1 ? ` (${s.workers} workers)` : '';
    solverStatus.textContent = `solver: ${s.mode}${threads}, ${s.solveMs.toFixed(1)} ms per frame${s.sleeping ? ', at rest' : ''}`;
  };
  showSolver();
  setInterval(showSolver, SOLVER_STATUS_MS);
  return simulation;
}

/**
 * Loads the default muscle rig. A rig that cannot be loaded leaves the skin running without muscles, and the status
 * bar says what is wrong.
 */
async function loadRig(): Promise<Rig | undefined> {
  const source = 'rigs/default.json';
  try {
    const response = await fetch(`${import.meta.env.BASE_URL}${source}`);
    if (!response.ok) throw new Error(`${source}: ${response.status} ${response.statusText}`);
    return parseRigText(await response.text(), source);
  } catch (error) {
    rigStatus.textContent = `The muscle rig could not be loaded: ${(error as Error).message}`;
    rigStatus.className = 'error';
    console.warn(error);
    return undefined;
  }
}

/**
 * Turns the lower teeth and tongue (the model's `jaw` node, placed at the jaw hinge) with the rig's jaw muscle, about
 * the muscle's local x axis, by the angle its contraction asks for.
 */
function jawFollower(head: HeadModel, rig: Rig): ((contractions: Float32Array) => void) | undefined {
  const index = rig.muscles.findIndex((m) => m.type === 'jaw');
  const muscle = rig.muscles[index];
  if (!head.jaw || !muscle || muscle.type !== 'jaw') return undefined;
  const jaw = head.jaw;
  const frame = new Array<number>(9);
  eulerMatrix(muscle.rotation, frame);
  const axis = new Vector3(frame[0], frame[3], frame[6]).normalize();
  const rest = jaw.quaternion.clone();
  const turn = new Quaternion();
  return (contractions) => {
    turn.setFromAxisAngle(axis, contractions[index] * muscle.maxAngle * DEGREES);
    jaw.quaternion.multiplyQuaternions(turn, rest);
  };
}

/** Reloads the page with another head resolution, carrying the current expression over in the URL hash. */
function switchResolution(resolution: Resolution): void {
  const params = new URLSearchParams(location.search);
  params.set('resolution', resolution);
  const presets = Object.fromEntries(face.listPresets().map((p) => [p.name, p.weight]));
  location.assign(`${location.pathname}?${params}${encodeExpression({ actionUnits: face.getActionUnits(), presets })}`);
}

const rigLoading = loadRig(); // in parallel with the head
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
  const rig = await rigLoading;
  face.attach(await startSkin(head, skinView, rig), rig);
  if (rig) {
    const jaw = jawFollower(head, rig);
    // The rig is in the model's frame, which the solver treats as the skin's own: the glyphs take the skin's transform.
    head.root.updateMatrixWorld(true);
    const muscles = new MuscleView(rig.muscles, head.skin.matrixWorld);
    view.scene.add(muscles.group);
    face.attachMuscles(muscles);
    face.onContractions = (contractions) => {
      jaw?.(contractions);
      muscles.setContractions(contractions);
    };
  }
  // Seeded from the clock: every page load blinks differently; the state machine is seeded for its tests.
  face.attachEyes(new EyeDriver(face, view, head.eyes, { lids: !!rig, simulation: { seed: Date.now() >>> 0 } }));
  // The expression lives in the URL hash from here on: a copied link reopens the same face.
  if (rig) new HashSync(face);
  new Panels(face, { frames: view, resolution, onResolution: switchResolution });
  document.documentElement.dataset.state = 'ready';
} catch (error) {
  failing.textContent = `${failure}: ${(error as Error).message}`;
  failing.className = 'error';
  face.fail(error as Error);
  document.documentElement.dataset.state = 'error';
  console.error(error);
}
