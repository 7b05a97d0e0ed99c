import type { HeadPose } from '../../core/expression/head-pose';
import type { Collider } from '../../core/solver/colliders';
import type { MouthCorners } from '../../core/solver/lip-contact';
import { validateMuscle } from '../../core/rig/muscle-validation';
import type { Muscle } from '../../core/rig/rig-types';
import { SKIN_DEFAULTS, validateParameters, type SkinParameters } from '../../core/solver/skin-parameters';
import type { ConstraintCounts } from '../../core/solver/solver-buffers';
import type { SolverBackend } from './backend';
import { InputStaging } from './input-staging';
import {
  contractionCapacity,
  controlLayout,
  controlViews,
  initControl,
  readSlotBounds,
  slotAppliedInput,
  slotConstraints,
  slotFrames,
  slotLayout,
  slotSleeping,
  slotSolveMs,
  slotWorkers,
  type ControlViews,
} from '../shared/layout';
import { MainBackend } from './main-backend';
import type { RigEdit, SolverClock, SolverMode } from '../shared/protocol';
import { SharedBackend } from './shared-backend';
import { TransferBackend } from './transfer-backend';
import { WorkerConnection } from './worker-connection';

/** What the simulation is built from. */
export interface SkinSimulationOptions {
  /** The skin's render mesh in head space: xyz per render vertex, and its triangles. */
  renderPositions: Float32Array;
  indices: Uint16Array | Uint32Array;
  colliders?: Collider[];
  /** The mouth's corners in head space: the lips then meet instead of passing through each other (see LipContact). */
  mouth?: MouthCorners;
  parameters?: Partial<SkinParameters>;
  /** The rig's muscles; `setContractions` then drives them, in this order. */
  muscles?: Muscle[];
  /** Defaults to `shared` on cross-origin isolated pages and `transfer` elsewhere. */
  mode?: SolverMode;
  /**
   * Threads that solve in `shared` mode: 2 adds a partner worker that takes half of most passes (same shape, less
   * time per frame where a core is free for it). `auto` (the default) takes 2 on machines with at least 4 cores.
   * Other modes solve on one thread.
   */
  workers?: 1 | 2 | 'auto';
}

/** The simulation's state, as of the newest frame. */
export interface SkinSimulationStats {
  /** Where the solver runs: `shared` or `transfer` (in a worker), or `main` (on the page's thread). */
  mode: SolverMode;
  /** Simulation vertices: the skin mesh's vertices after welding those that share a position (along UV seams). */
  vertices: number;
  /** Edges of the simulation mesh, each held near its rest length by a length constraint. */
  edges: number;
  /** How many constraints of each kind the solver projects. */
  constraints: ConstraintCounts;
  /** Time the last solved frame took, in ms. */
  solveMs: number;
  /** Whether the skin has settled for the current inputs, so the solver waits, solving nothing, until one changes. */
  sleeping: boolean;
  /** Frames solved so far. */
  frames: number;
  /** Threads that solved the newest frame (2 once a partner worker helps). */
  workers: number;
}

/** Cores a machine needs before `auto` adds a partner worker: one each for the page, the solver and its partner. */
const PARTNER_MIN_CORES = 4;

/** Solve time the render loop gives the `main` mode solver per frame, in ms. */
const MAIN_THREAD_BUDGET_MS = 8;
/**
 * How long after an input `awaitsAnswer` may say the skin has not answered it: twice the delay of the last input's
 * first answer (the most before the first), within these bounds (docs/page-notes.md); a view waits no longer. A medium head's
 * first frame comes 20 to 60 ms after an input in the page, a high head's 170 to 230 in software WebGL, where a
 * draw of the skin as it was costs the GPU 200 to 600 ms, and the answer's draw waits behind it.
 */
const ANSWER_WAIT_MS = 150;
const ANSWER_WAIT_MAX_MS = 600;
const SETTLE_POLL_MS = 8;

/**
 * The skin simulation as the main thread sees it, whichever mode runs the solver: inputs in, newest complete frame
 * out, never waiting for the solver.
 */
export class SkinSimulation {
  /** Bounds of the frame last read by readFrame: min xyz, max xyz. */
  readonly bounds = new Float32Array(6);
  private readonly staging: InputStaging;
  private readFrames = -1;
  /** Whether the frame last read by readFrame came from a solver still at work. */
  private readMoving = false;
  private disposed = false;
  /** When the newest input batch was published (performance.now()). */
  private publishedAt = -Infinity;
  /**
   * Whether the newest input has not been answered yet; how long the last input's first answer took (ms): until one
   * was measured, the longest wait.
   */
  private answerPending = false;
  private answerDelayMs = ANSWER_WAIT_MAX_MS / 2;
  /** Rig edits handed to the solver so far. */
  private rigRevision = 0;
  private muscleCount: number;

  private constructor(
    private readonly backend: SolverBackend,
    control: ControlViews,
    /** Rest positions, xyz per simulation vertex. */
    readonly rest: Float32Array,
    /** Triangles over simulation vertices. */
    readonly triangles: Uint32Array,
    readonly edgeCount: number,
    readonly renderVertexCount: number,
    muscleCount: number,
  ) {
    this.muscleCount = muscleCount;
    this.staging = new InputStaging(
      control,
      rest,
      (seq, changed) => {
        this.publishedAt = performance.now();
        this.answerPending = true;
        backend.publish(seq, changed);
      },
      muscleCount,
    );
  }

  /** Builds the skin's topology and solver (in a worker unless `mode` is `main`) and resolves once it is running. */
  static async create(options: SkinSimulationOptions): Promise<SkinSimulation> {
    const parameters = { ...SKIN_DEFAULTS, ...options.parameters };
    validateParameters(parameters);
    const mode = options.mode ?? (crossOriginIsolated ? 'shared' : 'transfer');
    if (mode === 'shared' && typeof SharedArrayBuffer === 'undefined')
      throw new Error("solver mode 'shared' needs a cross-origin isolated page");
    const renderCount = options.renderPositions.length / 3;
    const muscles = options.muscles ?? [];
    // What the solver host is built from, here or in the worker.
    const skin = {
      renderPositions: options.renderPositions,
      indices: options.indices,
      colliders: options.colliders ?? [],
      mouth: options.mouth,
      parameters,
      muscles,
    };
    if (mode === 'main') {
      // The solver's own code is a chunk of its own: the worker modes carry theirs in the worker, so a page that never
      // asks for the main thread does not download it.
      const { SolverHost } = await import('../shared/solver-host');
      const host = new SolverHost(skin);
      const t = host.topology;
      const mainLayout = controlLayout(t.vertexCount, contractionCapacity(muscles.length));
      const control = controlViews(new ArrayBuffer(mainLayout.byteLength), mainLayout);
      initControl(control, t.rest, parameters);
      const backend = new MainBackend(host, control, slotLayout(renderCount, t.vertexCount));
      return new SkinSimulation(backend, control, t.rest.slice(), t.triangles.slice(), t.restLength.length, renderCount, muscles.length);
    }
    const workers = options.workers ?? 'auto';
    const cores = typeof navigator === 'undefined' ? 1 : navigator.hardwareConcurrency || 1;
    const { connection, ready } = await WorkerConnection.start({
      type: 'init',
      mode,
      workers: mode === 'shared' && (workers === 2 || (workers === 'auto' && cores >= PARTNER_MIN_CORES)) ? 2 : 1,
      ...skin,
    });
    const layout = slotLayout(renderCount, ready.vertexCount);
    const cLayout = controlLayout(ready.vertexCount, contractionCapacity(muscles.length));
    if (mode === 'shared') {
      const backend = new SharedBackend(connection, ready.output!, layout);
      return new SkinSimulation(
        backend,
        controlViews(ready.control!, cLayout),
        ready.rest,
        ready.triangles,
        ready.edgeCount,
        renderCount,
        muscles.length,
      );
    }
    const control = controlViews(new ArrayBuffer(cLayout.byteLength), cLayout);
    initControl(control, ready.rest, parameters);
    const backend = new TransferBackend(connection, control, ready.frame!, layout);
    return new SkinSimulation(backend, control, ready.rest, ready.triangles, ready.edgeCount, renderCount, muscles.length);
  }

  get mode(): SolverMode {
    return this.backend.mode;
  }

  get vertexCount(): number {
    return this.rest.length / 3;
  }

  /**
   * Pulls some simulation vertices toward targets (xyz each) with a weight from 0 to 1 along the surface and one along
   * the normal (both 0 release them); other vertices keep theirs. Throws, changing nothing, on a bad vertex, a
   * non-finite target or a bad weight.
   */
  setMuscleTargets(vertices: ArrayLike<number>, targets: ArrayLike<number>, weight = 1, normalWeight = weight): void {
    this.checkAlive();
    this.staging.setMuscleTargets(vertices, targets, weight, normalWeight);
  }

  /** Sets every rig muscle's contraction (0..1, clamped), in the rig's order; throws, changing nothing, on a bad one. */
  setContractions(values: ArrayLike<number>): void {
    this.checkAlive();
    this.staging.setContractions(values);
  }

  /**
   * Sets the head pose (AU51 to AU58, see head-pose.ts) the neck is solved for: its base turns by the inverse pose
   * (see neck-carry.ts). Throws, changing nothing, on a value that is not finite.
   */
  setHeadPose(pose: HeadPose): void {
    this.checkAlive();
    this.staging.setHeadPose(pose);
  }

  /**
   * Replaces rig muscle `index` (an editor moving it): the solver chooses that muscle's skin again and recomputes the
   * targets with the current contractions, without rebuilding anything else. Throws, changing nothing, if the muscle
   * is not valid.
   */
  updateMuscle(index: number, muscle: Muscle): void {
    this.checkAlive();
    if (!Number.isInteger(index) || index < 0 || index >= this.muscleCount)
      throw new Error(`updateMuscle: index ${index} is not one of the rig's ${this.muscleCount} muscles`);
    validateMuscle(muscle);
    this.sendRigEdit({ index, muscle }, this.muscleCount);
  }

  /**
   * Replaces the rig's whole muscle list (muscles added, removed or reordered); `setContractions` takes the new
   * list's contractions from then on, and should follow at once (until it does, the skin keeps its targets).
   */
  setMuscles(muscles: Muscle[]): void {
    this.checkAlive();
    for (const m of muscles) validateMuscle(m);
    this.sendRigEdit({ muscles }, muscles.length);
  }

  /** Releases every muscle pull. */
  clearMuscleTargets(): void {
    this.checkAlive();
    this.staging.clearMuscleTargets();
  }

  /** Changes some skin parameters; throws, changing nothing, if one is unknown or not a finite number in range. */
  setParameters(partial: Partial<SkinParameters>): void {
    this.checkAlive();
    this.staging.setParameters(partial);
  }

  /** The parameters as last set (a copy). */
  parameters(): SkinParameters {
    return this.staging.parameters();
  }

  /**
   * Resolves once the solver has applied every input given so far and sleeps (its shape has converged). Rejects if
   * the solver fails, or after `timeoutMs`.
   */
  async settle(timeoutMs = Infinity): Promise<void> {
    this.checkAlive();
    this.staging.flush();
    const seq = this.staging.publishedSeq();
    const start = performance.now();
    for (;;) {
      this.checkAlive();
      const failure = this.backend.failure();
      if (failure) throw failure;
      const slot = this.backend.latest();
      if (slotAppliedInput(slot) >= seq && slotSleeping(slot)) return;
      if (performance.now() - start > timeoutMs) {
        throw new Error(
          `the skin did not settle within ${timeoutMs} ms (${slotFrames(slot)} frames solved, last in ${slotSolveMs(slot).toFixed(1)} ms)`,
        );
      }
      // In `main` mode nothing else may be stepping the solver (a hidden page gets no animation frames).
      this.backend.advance(MAIN_THREAD_BUDGET_MS);
      await new Promise((resolve) => setTimeout(resolve, SETTLE_POLL_MS));
    }
  }

  /** Gives the `main` mode solver up to `budgetMs` of this frame; the worker modes need nothing. */
  advance(budgetMs = MAIN_THREAD_BUDGET_MS): void {
    if (!this.disposed) this.backend.advance(budgetMs);
  }

  /**
   * Paces the solver: `free` (the default) solves whenever the skin is awake; `stepped` solves only the frames
   * `runFrames` asks for, whatever the machine's speed (a recorder's clock). `settle` needs the free clock.
   */
  setClock(clock: SolverClock): void {
    this.checkAlive();
    if (clock !== 'free' && clock !== 'stepped') throw new Error(`setClock: expected 'free' or 'stepped', got ${String(clock)}`);
    this.backend.setClock(clock);
  }

  /**
   * Publishes the inputs given so far, then solves exactly `frames` frames from them (fewer if the skin falls asleep,
   * which would change nothing more) and makes the last one the newest frame; resolves to the frames solved since
   * the solver started. Meant for the `stepped` clock, under which nothing else solves.
   */
  async runFrames(frames: number): Promise<number> {
    this.checkAlive();
    if (!Number.isInteger(frames) || frames < 0) throw new Error(`runFrames: expected a whole number of frames, got ${String(frames)}`);
    this.staging.flush();
    return this.backend.run(this.staging.publishedSeq(), frames);
  }

  /**
   * Copies the newest complete frame in render-vertex order (xyz per render vertex) and its bounds into `bounds`.
   * Returns false, copying nothing, if that frame was read already. Allocates nothing.
   */
  readFrame(intoPositions: Float32Array, intoNormals: Float32Array): boolean {
    if (this.disposed) return false;
    const slot = this.backend.latest();
    const frames = slotFrames(slot);
    if (frames === this.readFrames) return false;
    if (intoPositions.length !== slot.renderPositions.length || intoNormals.length !== slot.renderNormals.length) {
      throw new Error(`readFrame needs arrays of ${slot.renderPositions.length} floats (3 per render vertex)`);
    }
    intoPositions.set(slot.renderPositions);
    intoNormals.set(slot.renderNormals);
    readSlotBounds(slot, this.bounds);
    this.readFrames = frames;
    this.readMoving = !slotSleeping(slot);
    if (this.answerPending && slotAppliedInput(slot) >= this.staging.publishedSeq()) {
      this.answerPending = false;
      this.answerDelayMs = performance.now() - this.publishedAt;
    }
    return true;
  }

  /**
   * Whether more frames are coming: the frame last read by readFrame came from a solver still at work, or the newest
   * input has not been answered yet (its first frame not read).
   */
  moving(): boolean {
    return (this.readMoving || this.answerPending) && !this.disposed;
  }

  /**
   * Whether the newest frame is older than the newest input, published less than the answer's wait ago: the skin is about
   * to answer it (a view holds its drawing meanwhile, see FrameHook).
   */
  awaitsAnswer(): boolean {
    const wait = Math.min(ANSWER_WAIT_MAX_MS, Math.max(ANSWER_WAIT_MS, 2 * this.answerDelayMs));
    if (this.disposed || performance.now() - this.publishedAt > wait) return false;
    return slotAppliedInput(this.backend.latest()) < this.staging.publishedSeq();
  }

  /** Copies the newest complete frame in simulation-vertex order (the order of `rest`). Allocates nothing. */
  readSimulation(intoPositions: Float32Array, intoNormals: Float32Array): void {
    this.checkAlive();
    const slot = this.backend.latest();
    intoPositions.set(slot.positions);
    intoNormals.set(slot.normals);
  }

  /** Copies the newest complete frame in render-vertex order (xyz per render vertex), read or not. Allocates nothing. */
  readRender(intoPositions: Float32Array, intoNormals: Float32Array): void {
    this.checkAlive();
    const slot = this.backend.latest();
    if (intoPositions.length !== slot.renderPositions.length || intoNormals.length !== slot.renderNormals.length) {
      throw new Error(`readRender needs arrays of ${slot.renderPositions.length} floats (3 per render vertex)`);
    }
    intoPositions.set(slot.renderPositions);
    intoNormals.set(slot.renderNormals);
  }

  stats(): SkinSimulationStats {
    this.checkAlive();
    const slot = this.backend.latest();
    return {
      mode: this.mode,
      vertices: this.vertexCount,
      edges: this.edgeCount,
      constraints: slotConstraints(slot),
      solveMs: slotSolveMs(slot),
      sleeping: slotSleeping(slot),
      frames: slotFrames(slot),
      workers: slotWorkers(slot),
    };
  }

  /** Whether `dispose` was called. */
  isDisposed(): boolean {
    return this.disposed;
  }

  /** Stops the solver (terminating its worker) and removes every listener. */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.backend.dispose();
  }

  /** Counts the edit into the input batch (so `settle` waits for it) and hands it to the solver. */
  private sendRigEdit(edit: RigEdit, muscleCount: number): void {
    const revision = this.rigRevision + 1;
    this.staging.touchRig(revision, muscleCount);
    this.rigRevision = revision;
    this.muscleCount = muscleCount;
    this.backend.editRig(revision, edit);
  }

  private checkAlive(): void {
    if (this.disposed) throw new Error('the skin simulation was disposed');
  }
}
