import type { Collider } from '../../core/solver/colliders';
import type { MouthCorners } from '../../core/solver/lip-contact';
import type { RigEdit } from './protocol';
import { JawFollower } from '../../core/rig/jaw-follower';
import { LidSlack } from '../../core/rig/lid-slack';
import { MuscleRig } from '../../core/rig/muscles';
import { NeckCarry } from '../../core/rig/neck-carry';
import { isRestingPose, restingHeadPose } from '../../core/expression/head-pose';
import { mulberry32 } from '../../core/random';
import type { Muscle } from '../../core/rig/rig-types';
import { reachableBuffers, touchPages, type Memory } from '../../core/solver/memory';
import type { PartArrays } from '../../core/solver/part-arrays';
import { createBoard, partnerRunning, type Board } from '../../core/solver/partner-board';
import { PartnerLink } from '../../core/solver/partner-link';
import type { MuscleInputs } from '../../core/solver/muscle-inputs';
import { SKIN_DEFAULTS, type SkinParameters } from '../../core/solver/skin-parameters';
import { SkinSolver } from '../../core/solver/solver';
import { createSolverBuffers } from '../../core/solver/solver-buffers';
import { buildTopology, describeTopology, type SkinTopology } from '../../core/solver/topology';
import {
  CONSTRAINT_INDEX,
  CONSTRAINT_KINDS,
  readHeadPose,
  readParameters,
  writeFrameHeader,
  writeSlotBounds,
  type FrameHeader,
  type FrameSlot,
} from './layout';

/** What a solver host is built from: the skin's render mesh (head space), the colliders and the parameters. */
export interface SolverHostInput {
  renderPositions: Float32Array;
  indices: Uint16Array | Uint32Array;
  colliders: Collider[];
  /** The mouth's corners (head space), for the lips' contact; none: the lips may pass through each other. */
  mouth?: MouthCorners;
  parameters: SkinParameters;
  /** The rig's muscles (may be empty); contractions arrive in this order. */
  muscles: Muscle[];
  /** Solve only the skin that moves (the default; see SkinSolver). */
  activeRegion?: boolean;
  /** `shared` puts the solver's arrays on shared memory, for a partner thread (see SkinSolver.partArrays). */
  memory?: Memory;
}

/** Frames the host may spend settling the rest shape before it counts as ready. */
const MAX_SETTLING_FRAMES = 64;

/** Every muscle's contraction in the warm-up: the jaw opens, the lips reach the teeth, the region grows. */
const WARM_UP_CONTRACTION = 0.6;
/** Frames the warm-up solves; by the fourth a frame of the medium head costs what it costs warm. */
const WARM_UP_FRAMES = 4;
/**
 * Seeded random contraction sets (each muscle off or at a random contraction) the warm-up then runs the rig for, so
 * that its compiled code has seen every branch (muscles off, fading in, skin slid out of its zones); past 5 the first
 * input applies no faster, and each set costs 12 to 30 ms of the worker's time at every page load (docs/page-notes.md).
 */
const WARM_UP_RIG_SETS = 6;
/**
 * How long the warm-up waits for its partner thread to take jobs before it solves without it (ms): the partner's
 * worker is started with the host, so it usually runs long before the throwaway solver is built.
 */
const WARM_UP_PARTNER_WAIT_MS = 500;
/**
 * Bytes of the solver's arrays whose pages a warm-up piece maps (see touchPages): about 10 ms of the page's worker
 * where fresh pages are slow, so that an input waits no longer for the piece than for a frame.
 */
const WARM_UP_TOUCH_BYTES = 4 * 1024 * 1024;

/**
 * The partner thread the warm-up's throwaway solver hands half of its passes to, so that the partner's code is compiled
 * before the first expression too (cold, it made the first two-thread frame of the high head twice as long).
 */
export interface WarmUpPartner {
  /** Hands the partner thread the throwaway solver's arrays and the board it takes their jobs on. */
  start(arrays: PartArrays, board: Board): void;
  /** Called once the throwaway solver is done with the partner (the warm-up's frames are over, or were cut short). */
  finished(): void;
}

/**
 * Owns a SkinSolver wherever it runs (worker or main thread): applies published input batches between frames, steps,
 * and writes frames into output slots. Every mode goes through this one class, so every mode solves alike.
 */
export class SolverHost {
  readonly topology: SkinTopology;
  readonly solver: SkinSolver;
  /** Turns contractions into the solver's muscle targets and weights; absent without muscles. */
  private rig: MuscleRig | undefined;
  /** Unfolds the skin above a closing lid (see LidSlack); absent without muscles. */
  private slack: LidSlack | undefined;
  /** The neck's pull under a turned head (AU51 to AU58); null for a skin without a neck cut. */
  readonly neck: NeckCarry | null;
  /** The head pose last applied. */
  private readonly headPose = restingHeadPose();
  /** Moves the lower teeth's colliders with the jaw muscle; null without a jaw or lower teeth. */
  private jaw: JawFollower | null;
  /** The rig edits applied so far (see RigMessage). */
  rigRevision = 0;
  private readonly colliders: Collider[];
  private readonly mouth: MouthCorners | undefined;
  private readonly activeRegion: boolean | undefined;
  /** The colliders as the model placed them, to put the jaw's back before a new jaw takes them. */
  private readonly restColliders: Collider[];
  /** The contractions last applied, for recomputing the targets after a muscle changes; null until some arrive. */
  private contractions: Float32Array | null = null;
  private readonly header: FrameHeader = { frames: 0, sleeping: true, appliedInput: 0, solveMs: 0, workers: 1 };
  /** Constraint counts change only when inputs do, so they are counted per input batch, not per frame. */
  private readonly constraints = new Int32Array(CONSTRAINT_KINDS.length);
  private readonly parameterScratch: SkinParameters = { ...SKIN_DEFAULTS };

  constructor(input: SolverHostInput) {
    this.topology = buildTopology(input.renderPositions, input.indices);
    console.info(describeTopology(this.topology));
    this.solver = new SkinSolver(this.topology, {
      parameters: input.parameters,
      colliders: input.colliders,
      mouth: input.mouth,
      activeRegion: input.activeRegion,
      memory: input.memory,
    });
    this.rig = input.muscles.length > 0 ? new MuscleRig(this.topology.rest, input.muscles) : undefined;
    this.slack = this.rig ? new LidSlack(this.topology, input.muscles) : undefined;
    this.neck = NeckCarry.create(this.topology.rest, this.topology.triangles);
    this.colliders = input.colliders;
    this.mouth = input.mouth;
    this.activeRegion = input.activeRegion;
    this.restColliders = structuredClone(input.colliders);
    this.jaw = JawFollower.create(input.muscles, input.colliders);
    // Start from the skin's own equilibrium (the float32 rest lengths move it by a hair), so that every mode starts
    // from the same sleeping shape however many frames pass before the first input arrives.
    for (let i = 0; i < MAX_SETTLING_FRAMES && this.step(); i++);
    this.countConstraints();
  }

  /**
   * Applies one input batch (null parts did not change), as of input sequence number `seq`. `headPose` (see
   * HEAD_POSE_SLOTS in layout.ts) comes with the contractions; without it the pose stays.
   */
  apply(
    seq: number,
    muscles: MuscleInputs | null,
    parameters: Float64Array | null,
    contractions: Float32Array | null = null,
    headPose: Float32Array | null = null,
  ): void {
    if (muscles) {
      this.solver.buffers.targets.set(muscles.targets);
      this.solver.buffers.weights.set(muscles.weights);
      this.solver.buffers.normalWeights.set(muscles.normalWeights);
      // Targets set directly turn no skin bodily (see SolverBuffers.turnWeights).
      this.solver.buffers.turnWeights.fill(0);
      this.solver.updateMuscles();
    }
    // Rig contractions replace directly set targets: the rig computes every vertex's target and weights. The block
    // holds room for more muscles than the rig may have now; the rig's come first.
    if (headPose) readHeadPose(headPose, this.headPose);
    if (contractions && this.rig) {
      this.contractions = Float32Array.from(contractions.subarray(0, this.rig.muscles.length));
      this.computeMuscles();
    }
    if (parameters) this.solver.setParameters(readParameters(parameters, this.parameterScratch));
    this.header.appliedInput = seq;
    this.countConstraints();
  }

  /**
   * Applies a rig edit (as of `revision`): one muscle replaced, whose candidates alone are chosen again and the targets
   * recomputed with the last contractions (an editor's drag, every pointer move); or a new muscle list, whose
   * contractions come with the next input batch (until then the skin keeps its targets). Throws, changing nothing, if
   * a muscle is not valid.
   */
  editRig(revision: number, edit: RigEdit): void {
    if ('index' in edit) {
      if (!this.rig) throw new Error('editRig: the rig has no muscles to replace');
      const before = this.rig.muscles[edit.index];
      this.rig.setMuscle(edit.index, edit.muscle);
      if (before?.type === 'lid' || edit.muscle.type === 'lid') this.newSlack(this.rig.muscles);
      if (before?.type === 'jaw' || edit.muscle.type === 'jaw') this.newJaw(this.rig.muscles);
      if (this.contractions) this.computeMuscles();
    } else {
      this.rig = edit.muscles.length > 0 ? new MuscleRig(this.topology.rest, edit.muscles) : undefined;
      this.newSlack(edit.muscles);
      this.newJaw(edit.muscles);
      this.contractions = null;
      if (!this.rig) {
        // No muscles hold anything now.
        this.solver.buffers.weights.fill(0);
        this.solver.buffers.normalWeights.fill(0);
        this.solver.updateMuscles();
      }
    }
    this.rigRevision = revision;
    this.countConstraints();
  }

  /** The input batch applied last (its sequence number). */
  get appliedInput(): number {
    return this.header.appliedInput;
  }

  /**
   * Whether the last frame solved any skin: false for the frames of an input that changed nothing at rest (a reset of
   * the neutral face solves two frames of an empty active region). The worker ends its warm-up only at a frame that
   * did (see warmUp).
   */
  get solvedSkin(): boolean {
    return this.solver.activeVertexCount > 0;
  }

  /**
   * Runs the rig and a solver on a throwaway copy of the skin, a piece per `next()`, so that the first expression a
   * user asks for meets compiled code (cold, the first frames cost about twice their warm time: docs/page-notes.md);
   * with `partner`, the throwaway solver shares its passes with that thread, which leaves their job loop at the end
   * (or when the generator is returned early) and may then take the host's solver.
   * This host's solver, rig and colliders are not changed; the first pieces map the pages of the solver's arrays (see
   * touchPages), which the first input would otherwise wait for, a few megabytes a piece (the high head's 53 MB took
   * the page's worker 107 ms in one piece).
   */
  *warmUp(partner?: WarmUpPartner): Generator<void, void, void> {
    let touched = 0;
    for (const buffer of reachableBuffers(this.solver)) {
      touchPages(buffer);
      touched += buffer.byteLength;
      if (touched < WARM_UP_TOUCH_BYTES) continue;
      touched = 0;
      yield;
    }
    yield;
    const rig = this.rig;
    if (!rig) return;
    const memory: Memory = partner ? 'shared' : 'local';
    const buffers = createSolverBuffers(this.topology, memory);
    const warm = new Float32Array(rig.muscles.length).fill(WARM_UP_CONTRACTION);
    rig.compute(warm, buffers);
    this.slack?.compute(warm, buffers.unfoldedLengths);
    yield;
    const colliders = structuredClone(this.colliders);
    const solver = new SkinSolver(this.topology, {
      parameters: this.solver.parameters(),
      buffers,
      colliders,
      mouth: this.mouth,
      activeRegion: this.activeRegion,
      memory,
    });
    solver.updateMuscles();
    const board = partner ? createBoard() : null;
    const link = board ? new PartnerLink(board) : null;
    try {
      if (partner && board && link) {
        partner.start(solver.partArrays(), board);
        const until = performance.now() + WARM_UP_PARTNER_WAIT_MS;
        while (!partnerRunning(board) && performance.now() < until) yield;
        if (partnerRunning(board)) solver.attachPartner(link);
      }
      for (let k = 0; k < WARM_UP_FRAMES; k++) {
        yield;
        solver.step();
      }
    } finally {
      // A partner that never started leaves its loop at once when it does.
      solver.attachPartner(null);
      link?.stop();
      partner?.finished();
    }
    const random = mulberry32(1);
    const contractions = new Float32Array(rig.muscles.length);
    for (let k = 0; k < WARM_UP_RIG_SETS; k++) {
      yield;
      for (let m = 0; m < contractions.length; m++) contractions[m] = random() < 0.5 ? 0 : random();
      rig.compute(contractions, buffers);
    }
  }

  /** Solves up to `frames` frames, stopping early once the solver sleeps; returns how many it solved. */
  run(frames: number): number {
    let solved = 0;
    while (solved < frames && this.step()) solved++;
    return solved;
  }

  /** Solves one frame unless the solver sleeps; returns whether it solved. */
  step(): boolean {
    const start = performance.now();
    if (!this.solver.step()) return false;
    this.header.solveMs = performance.now() - start;
    return true;
  }

  /** Writes the current shape into a slot: render-order and simulation-order vertices, bounds and header. */
  writeFrame(slot: FrameSlot): void {
    const { positions, normals } = this.solver.buffers;
    const renderToSim = this.topology.renderToSim;
    const rp = slot.renderPositions;
    const rn = slot.renderNormals;
    for (let r = 0; r < renderToSim.length; r++) {
      const s = 3 * renderToSim[r];
      const o = 3 * r;
      rp[o] = positions[s];
      rp[o + 1] = positions[s + 1];
      rp[o + 2] = positions[s + 2];
      rn[o] = normals[s];
      rn[o + 1] = normals[s + 1];
      rn[o + 2] = normals[s + 2];
    }
    slot.positions.set(positions);
    slot.normals.set(normals);
    writeSlotBounds(slot, positions);
    this.header.frames = this.solver.frames;
    this.header.sleeping = this.solver.sleeping;
    this.header.workers = this.solver.workers;
    writeFrameHeader(slot, this.header, this.constraints);
  }

  /** The muscle targets of the last contractions, and the jaw's teeth turned to match. */
  private computeMuscles(): void {
    if (!this.rig || !this.contractions) return;
    this.jaw?.update(this.contractions);
    this.rig.compute(this.contractions, this.solver.buffers);
    this.slack?.compute(this.contractions, this.solver.buffers.unfoldedLengths);
    if (this.neck && !isRestingPose(this.headPose)) this.neck.apply(this.headPose, this.solver.buffers);
    this.solver.updateMuscles();
  }

  /** A new slack for new lids; the skin's own rest lengths until contractions come. */
  private newSlack(muscles: readonly Muscle[]): void {
    this.slack = muscles.length > 0 ? new LidSlack(this.topology, muscles) : undefined;
    this.solver.buffers.unfoldedLengths.set(this.topology.restLength);
  }

  /** Puts the teeth back where the model placed them and lets the rig's jaw (if any) turn them from there. */
  private newJaw(muscles: readonly Muscle[]): void {
    this.restColliders.forEach((rest, k) => {
      const c = this.colliders[k];
      for (let i = 0; i < 3; i++) {
        c.a[i] = rest.a[i];
        if (rest.b && c.b) c.b[i] = rest.b[i];
        if (rest.up && c.up) c.up[i] = rest.up[i];
      }
    });
    this.jaw = JawFollower.create(muscles, this.colliders);
  }

  private countConstraints(): void {
    const counts = this.solver.counts();
    for (const kind of CONSTRAINT_KINDS) this.constraints[CONSTRAINT_INDEX[kind]] = counts[kind];
  }
}
