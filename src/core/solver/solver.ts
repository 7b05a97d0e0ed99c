/**
 * The skin solver (thesis 3.1.2 and 4.3): every frame, position, muscle and length constraints are projected in
 * that order, a number of times, over flat Float32Arrays. Added to the thesis: a bending constraint that sets the
 * wrinkle spacing in millimetres, collisions with rigid shapes (eyes, teeth) and between the lips, orientation constraints, a per-vertex
 * relaxation that turns cycles into convergence (see relaxation.ts), the active region: only skin that moves is solved, and
 * a partner thread that can take half of most passes with the same result (see solver-partner.ts).
 */
import { ACTIVE_GROW, ActiveRegion } from './active-region';
import { bendingAtRest, inverseDegrees, setBendingShares } from './bending-setup';
import type { Collider } from './colliders';
import { CarriedFrames } from './carried-frames';
import { LipContact, type MouthCorners } from './lip-contact';
import { CollisionCandidates } from './collision-candidates';
import {
  createBendingLists,
  createEdgeLists,
  createTriangleLists,
  fillBendingLists,
  fillEdgeLists,
  fillTriangleLists,
  neighbourOffsets,
  ringParts,
  vertexBlocks,
  type EdgeLists,
  type TriangleLists,
} from './constraint-lists';
import { restOutside } from './frame-kernels';
import { type KernelArray, KernelMemory, useKernels } from './kernel-memory';
import { createBulgeDirections } from './length-kernels';
import { allocate, allocateCopy, type Memory } from './memory';
import { checkMuscleTargets, clearMuscleInputs, writeMuscleTargets } from './muscle-inputs';
import { countTurnedOver, ORIENT_FULL, ORIENT_WATCHED, triangleFrames } from './orientation-kernel';
import type { PartArrays } from './part-arrays';
import { JOB_RELAX } from './partner-board';
import type { PartnerLink } from './partner-link';
import { SKIN_DEFAULTS, validateParameters, type SkinParameters } from './skin-parameters';
import { createSolverBuffers, type ConstraintCounts, type FrameTimings, type SolverBuffers } from './solver-buffers';
import { Relaxation } from './relaxation';
import { createSecondRing, setSecondRingShares } from './second-ring';
import { FramePasses } from './solver-passes';
import {
  FOLD_CHOICE_FRAMES,
  FOLD_CHOICE_MOMENTUM,
  LATE_MOTION,
  LOOP_STEP,
  ORIENTATION_PASSES,
  ORIENTATION_SHOWN_FLOOR,
  ORIENTATION_SHOWN_PASSES,
  START_MOMENTUM_FRAMES,
  STILL_MOVE,
} from './solver-schedule';
import type { SkinTopology } from './topology';

export class SkinSolver {
  readonly topology: SkinTopology;
  readonly buffers: SolverBuffers;
  private readonly params: SkinParameters = { ...SKIN_DEFAULTS };
  private readonly previous: Float32Array;
  /** Each vertex's move in the last frame (xyz), to tell a vertex that turns back from one going somewhere. */
  private readonly lastStep: Float32Array;
  /** Scratch: the region's positions while FramePasses.untangle tries. */
  private readonly untangleScratch: Float32Array;
  /** The relaxation's per-vertex state and the motion's age (see relaxation.ts). */
  private readonly relaxation: Relaxation;
  /** The watched triangles were cleared: the next frame's passes check every triangle (see restartMotion). */
  private watchFresh = true;
  private readonly held: Uint32Array;
  private heldCount = 0;
  /** Each vertex's bending share per pass, and its step per unit of the constraint (see PartArrays.bendGain). */
  private readonly bendStiffness: Float32Array;
  private readonly bendGain: Float32Array;
  /** Bending projections of each vertex per outer iteration, and the most any vertex takes (see setParameters). */
  private readonly bendPasses: Uint8Array;
  /** Per vertex, the bending constraint's value at rest (see projectBendingPart), so the frames need not read rest. */
  private readonly bendRest: Float64Array;
  private maxBendPasses = 1;
  /** Each vertex's bending part (see ringParts). */
  private readonly bendParts: Uint8Array;
  /** Per triangle: its rest unit normal (xyz) and the least area it may shrink to along that normal. */
  private readonly triangleFrames: Float32Array;
  /** Turns the triangles' frames with the skin the lids and the jaw carry (see CarriedFrames). */
  private readonly carriedFrames: CarriedFrames;
  /** The lists the per-frame loops walk (see constraint-lists.ts), part by part. */
  private readonly edgeLists: EdgeLists;
  private readonly triangleLists: TriangleLists;
  /** What the heaviest loops read and write (see part-arrays.ts); shared with the partner thread, if any. */
  private readonly parts: PartArrays;
  /** The frame's passes, with the partner thread if one is attached. */
  private readonly passes: FramePasses;
  private readonly memory: Memory;
  /** Each vertex's block, which sets the triangles' parts (see constraint-lists.ts). */
  private readonly blocks: Uint32Array;
  /** Scratch: each triangle's place in `parts.shadedTriangles`. */
  private readonly shadedPlaces: Int32Array;
  /** Scratch: each triangle's watched flag while the lists are refilled (see refreshLists). */
  private readonly watchedTriangles: Uint8Array;
  /** The topology's neighbours as xyz offsets (3 * vertex). */
  private readonly neighbourOffsets: Uint32Array;
  /** The skin a frame solves (see active-region.ts); the lists above hold its constraints as of `listedRevision`. */
  private readonly region: ActiveRegion;
  private listedRevision = -1;
  /** Each vertex's push per unit of compression of a held edge (see PartArrays.bulgeDirections). */
  private readonly bulgeDirections: Float32Array;
  /** The skin checked against the colliders (see collision-candidates.ts). */
  private readonly collisions: CollisionCandidates;
  /** The lips' contact across the slit; null without a mouth (see LipContact). */
  readonly lips: LipContact | null;
  /** The mouth corners' height, where the lips' red keeps the colliders' finer bending cap; null without a mouth. */
  private readonly mouthHeight: number | null;
  private inputsChanged = false;
  private asleep = true;
  /** Largest vertex move of the last frame, in model units. */
  lastMove = 0;
  /** Frames solved since creation. */
  frames = 0;
  /** Where the last frame's time went (reused, never reallocated). */
  readonly timings: FrameTimings = { positions: 0, lengths: 0, bending: 0, collisions: 0, orientation: 0, normals: 0, total: 0 };

  /**
   * `activeRegion` (default true) solves only the skin that moves (see active-region.ts); false solves the whole mesh
   * every frame.
   */
  constructor(
    topology: SkinTopology,
    options: {
      parameters?: Partial<SkinParameters>;
      buffers?: SolverBuffers;
      colliders?: Collider[];
      /** The mouth's corners: where given, the lips meet instead of passing through each other (see LipContact). */
      mouth?: MouthCorners;
      activeRegion?: boolean;
      memory?: Memory;
    } = {},
  ) {
    this.topology = topology;
    const n = topology.vertexCount;
    const memory = options.memory ?? 'local';
    this.memory = memory;
    this.buffers = options.buffers ?? createSolverBuffers(topology, memory);
    if (memory === 'shared' && !Object.values(this.buffers).every((b: Float32Array) => b.buffer instanceof SharedArrayBuffer)) {
      // The partner thread reads the positions and the muscle inputs.
      throw new Error('a solver on shared memory needs its buffers on shared memory');
    }
    const kernel = KernelMemory.of(this.buffers.positions);
    // Outside the active region `previous` is only written when the region changes, and stays at rest.
    this.previous = allocateCopy(topology.rest, memory, kernel);
    this.lastStep = allocate(Float32Array, 3 * n, memory, kernel);
    this.untangleScratch = new Float32Array(3 * n);
    this.relaxation = new Relaxation(n, memory, kernel);
    this.held = new Uint32Array(n);
    this.bendStiffness = new Float32Array(n);
    const place = <T extends KernelArray>(array: T): T => KernelMemory.place(kernel, array);
    this.bendGain = allocate(Float32Array, n, memory, kernel);
    this.bendPasses = allocate(Uint8Array, n, memory, kernel);
    this.triangleFrames = triangleFrames(topology.rest, topology.triangles);
    this.carriedFrames = new CarriedFrames(topology.rest, topology.restNormals, topology.triangles, this.triangleFrames);
    this.edgeLists = createEdgeLists(topology, memory, kernel);
    this.bulgeDirections = createBulgeDirections(topology, memory, kernel);
    this.triangleLists = createTriangleLists(topology, memory, kernel);
    this.watchedTriangles = new Uint8Array(topology.triangles.length / 3);
    this.shadedPlaces = new Int32Array(topology.triangles.length / 3);
    this.neighbourOffsets = place(neighbourOffsets(topology));
    this.bendRest = place(bendingAtRest(topology, this.neighbourOffsets));
    this.blocks = vertexBlocks(topology);
    this.bendParts = ringParts(topology, this.blocks);
    this.region = new ActiveRegion(topology, options.activeRegion ?? true, memory, kernel);
    this.collisions = new CollisionCandidates(topology, options.colliders ?? [], memory, kernel);
    this.lips = options.mouth ? LipContact.find(topology.rest, topology.restNormals, options.mouth) : null;
    this.mouthHeight = options.mouth ? (options.mouth.left[1] + options.mouth.right[1]) / 2 : null;
    const triangleCount = topology.triangles.length / 3;
    // Rounded up to whole words (see PartArrays.uncheckedWords); the flags past the last triangle stay 0.
    const flagBytes = 4 * Math.ceil(triangleCount / 4);
    const unchecked = allocate(Uint8Array, flagBytes, memory, kernel);
    const watched = allocate(Uint8Array, flagBytes, memory, kernel);
    this.parts = {
      positions: this.buffers.positions,
      rest: place(topology.rest),
      restNormals: place(topology.restNormals),
      targets: this.buffers.targets,
      weights: this.buffers.weights,
      normalWeights: this.buffers.normalWeights,
      normals: this.buffers.normals,
      shadedTriangles: createTriangleLists(topology, memory, kernel, false),
      neighbourStart: place(topology.neighbourStart),
      neighbourOffsets: this.neighbourOffsets,
      vertexTriangleStart: place(topology.vertexTriangleStart),
      vertexTriangles: place(topology.vertexTriangles),
      edges: this.edgeLists,
      kernelMemory: null,
      kernelModule: null,
      collisionKernel: false,
      bulgeDirections: this.bulgeDirections,
      triangles: this.triangleLists,
      bending: createBendingLists(n, memory, kernel),
      bendRest: this.bendRest,
      bendGain: this.bendGain,
      inverseDegree: place(inverseDegrees(topology, memory)),
      bendPasses: this.bendPasses,
      secondRing: createSecondRing(topology, memory, kernel),
      unchecked,
      uncheckedWords: new Uint32Array(unchecked.buffer, unchecked.byteOffset, flagBytes / 4),
      watched,
      watchedWords: new Uint32Array(watched.buffer, watched.byteOffset, flagBytes / 4),
      listedTriangle: allocate(Int32Array, triangleCount, memory, kernel),
      regionVertices: this.region.vertices,
      shadedVertices: this.region.shadedVertices,
      previous: this.previous,
      lastStep: this.lastStep,
      relaxation: this.relaxation.share,
      restart: this.relaxation.restart,
      calm: this.relaxation.calm,
      path: this.relaxation.path,
      ...this.collisions.partArrays(),
    };
    useKernels(this.parts, kernel);
    this.passes = new FramePasses(this.parts, this.lips, this.region.inside);
    this.setParameters(options.parameters ?? {});
    this.updateMuscles();
  }

  /** The current parameters (a copy). */
  parameters(): SkinParameters {
    return { ...this.params };
  }

  /** Changes parameters; throws, changing nothing, if one is not a finite number in its range. */
  setParameters(p: Partial<SkinParameters>): void {
    const next = { ...this.params, ...p };
    validateParameters(next);
    Object.assign(this.params, next);
    this.maxBendPasses = setBendingShares(
      this.topology,
      next,
      this.collisions.colliderVertices,
      this.mouthHeight,
      this.bendPasses,
      this.bendStiffness,
      this.bendGain,
    );
    setSecondRingShares(this.parts.secondRing, this.topology, next);
    this.listBending();
    // New parameters start a new motion, as new muscle inputs do.
    this.restartMotion();
  }

  /**
   * Sets muscle targets for some vertices (others keep theirs). `weight` pulls along the surface, `normalWeight`
   * along the rest normal; both 0 releases a vertex.
   */
  setMuscleTargets(vertices: ArrayLike<number>, targets: ArrayLike<number>, weight = 1, normalWeight = weight): void {
    checkMuscleTargets(this.topology.vertexCount, vertices, targets, weight, normalWeight);
    writeMuscleTargets(this.buffers, vertices, targets, weight, normalWeight);
    this.updateMuscles();
  }

  /** Releases every muscle constraint. */
  clearMuscleTargets(): void {
    clearMuscleInputs(this.buffers, this.topology.rest);
    this.buffers.turnWeights.fill(0);
    this.buffers.unfoldedLengths.set(this.topology.restLength);
    this.updateMuscles();
  }

  /** Re-reads the target and weight buffers (after writing them directly, as the worker's control block does). */
  updateMuscles(): void {
    const W = this.buffers.weights;
    const WN = this.buffers.normalWeights;
    let count = 0;
    for (let v = 0; v < W.length; v++) if (W[v] > 0 || WN[v] > 0) this.held[count++] = v;
    this.heldCount = count;
    this.region.seed(this.held, count);
    // The frames first: the lists (refilled or kept below) copy them.
    const B = this.buffers;
    this.carriedFrames.update(B.targets, W, WN, B.turnWeights, this.triangleFrames, this.triangleLists.frames, this.parts.listedTriangle);
    this.collisions.joinReachedCandidates(this.region, this.buffers.positions, ACTIVE_GROW * this.topology.size);
    // Of the lists, only the edges' depend on the weights (held edges apart, with their weight): while a slider moves
    // the region mostly stays as it is, and the other lists with it.
    if (this.region.revision !== this.listedRevision) this.refreshLists();
    else
      fillEdgeLists(
        this.edgeLists,
        this.topology,
        this.buffers.weights,
        this.region.enabled ? this.region.inside : null,
        this.buffers.unfoldedLengths,
      );
    this.inputsChanged = true;
    this.restartMotion();
  }

  /** A new motion (new inputs or parameters): every vertex may take whole steps again. */
  private restartMotion(): void {
    this.relaxation.restartMotion();
    this.lastStep.fill(0);
    // A motion from rest watches anew: its first frame's passes check every triangle (see ORIENT_WATCH). Inputs that
    // come while the skin still moves (a slider dragged, a timeline played) keep the set, which only grows, so that
    // each frame of a drag is not a first one: the frame's last passes check every triangle either way, and add those
    // near their bound (a drag's frames cost more when each one checked every triangle: docs/solver-notes.md).
    if (this.asleep) {
      this.parts.watched.fill(0);
      this.watchFresh = true;
    }
    this.wake();
  }

  /** Wakes the solver so the next step() solves a frame. */
  wake(): void {
    this.asleep = false;
  }

  /** Vertices in the active region: those the solver solves (all of them without the active region). */
  get activeVertexCount(): number {
    return this.region.count;
  }

  /** Edges a length pass projects: those touching the active region. */
  get activeEdgeCount(): number {
    return this.edgeLists.runs[this.edgeLists.runs.length - 1];
  }

  /** Workers (threads) that solve: 2 with a partner attached, else 1; the same count as the `workers` option. */
  get workers(): number {
    return this.passes.partner ? 2 : 1;
  }

  /**
   * The arrays a partner thread projects its part of the constraints on (see SolverPartner); post them to it. Only a
   * solver on shared memory has them.
   */
  partArrays(): PartArrays {
    if (this.memory !== 'shared') throw new Error('only a solver on shared memory can have a partner thread');
    return this.parts;
  }

  /**
   * Hands half of each position, length, orientation, bending and collision pass to a partner thread from the next
   * pass on (null: this thread solves alone again). The shape is the same either way: the parts share no vertex.
   */
  attachPartner(link: PartnerLink | null): void {
    if (link && this.memory !== 'shared') throw new Error('only a solver on shared memory can have a partner thread');
    this.passes.partner = link;
  }

  /**
   * Triangles of the whole skin turned over now: their area along their frame (the rest normal, turned where the
   * lids and the jaw carry the skin; see CarriedFrames) below zero.
   */
  turnedOverCount(): number {
    return countTurnedOver(this.buffers.positions, this.topology.triangles, this.triangleFrames);
  }

  /** True once the shape has converged for the current inputs; step() then does nothing until an input changes. */
  get sleeping(): boolean {
    return this.asleep;
  }

  counts(): ConstraintCounts {
    const t = this.topology;
    return {
      position: t.vertexCount,
      length: t.restLength.length,
      muscle: this.heldCount,
      bending: this.params.wrinkleSpacing > 0 ? t.vertexCount : 0,
      collision: this.collisions.colliderVertices.length,
    };
  }

  /** Solves one frame unless asleep; returns whether it solved. Allocates nothing. */
  step(): boolean {
    if (this.asleep) return false;
    const time = this.timings;
    const start = now();
    time.positions = time.lengths = time.bending = time.collisions = time.orientation = 0;
    const p = this.params;
    const foldMomentum =
      this.relaxation.motionFrames < FOLD_CHOICE_FRAMES && p.foldMomentum > FOLD_CHOICE_MOMENTUM ? FOLD_CHOICE_MOMENTUM : p.foldMomentum;
    this.passes.startFrame(
      this.region.count,
      this.relaxation.motionFrames < START_MOMENTUM_FRAMES ? p.startMomentum : p.momentum,
      foldMomentum,
    );
    // A motion's first frame from rest checks every triangle and so starts the watched set (see ORIENT_WATCH).
    this.passes.iterate(p, this.maxBendPasses, this.region.count, this.watchFresh ? ORIENT_FULL : ORIENT_WATCHED, time);
    this.watchFresh = false;
    // The iterations take back half of each crossing of the lips; what is shown keeps them apart (see LIP_CONTACT_SHARE).
    this.passes.closeLips();
    // Dense fans (the mouth's corners) need a few passes to untangle. After the relaxation, which blends two shapes
    // and so could turn a sliver over, the passes hold only half the bound: whole-bound passes there undid the
    // relaxation in the fans, where the corrections then took turns with the other constraints until the safety net
    // (see ORIENTATION_SHOWN_FLOOR).
    let untangle = now();
    this.passes.orientationRounds(ORIENTATION_PASSES);
    time.orientation += now() - untangle;
    this.settleRegion();
    this.relax();
    untangle = now();
    this.passes.orientationRounds(ORIENTATION_SHOWN_PASSES, ORIENTATION_SHOWN_FLOOR);
    time.orientation += now() - untangle;
    // The frame's true move, after every pass: what the sleep test and the relaxation see.
    this.lastMove = this.passes.recordSteps(this.region.count);
    if (this.relaxation.motionFrames % LOOP_STEP === 0) this.relaxation.breakLoops(this.region.vertices, this.region.count, this.topology);
    this.frames++;
    const size = this.topology.size;
    const still = !this.inputsChanged && this.lastMove <= p.sleepTolerance * size;
    // Before the skin just outside the region goes back to rest, which the passes may nudge.
    if (still && this.passes.turnedOver()) {
      untangle = now();
      this.passes.untangle(this.region.count, this.untangleScratch);
      time.orientation += now() - untangle;
    }
    this.restRegionRing();
    const beforeNormals = now();
    this.passes.computeNormals(this.region, this.topology.triangles);
    const end = now();
    time.normals = end - beforeNormals;
    time.total = end - start;
    this.inputsChanged = false;
    // Still skin sleeps; with a triangle turned over that FramePasses.untangle could not lift, which the next frames'
    // passes may yet untangle, only once as still as STILL_MOVE (or stopped by the safety net).
    if (still) this.asleep = this.lastMove <= STILL_MOVE * size || this.relaxation.motionFrames > LATE_MOTION || !this.passes.turnedOver();
    return true;
  }

  /**
   * The active region's part of a frame before the relaxation: it grows where the motion spreads, and the skin just
   * outside it goes back to rest (so that this does not count as a move).
   */
  private settleRegion(): void {
    const b = this.buffers;
    if (this.region.grow(b.positions)) this.refreshLists();
  }

  /**
   * At the frame's end, skin outside the region goes back exactly to rest (the last orientation passes may have nudged
   * it), and skin back at rest leaves the region. Once no muscle holds the skin and the solver is about to sleep, the
   * skin is back at rest within the sleep tolerance: the region empties, its vertices going exactly to rest.
   */
  private restRegionRing(): void {
    const b = this.buffers;
    const asleepNext = !this.inputsChanged && this.lastMove <= this.params.sleepTolerance * this.topology.size;
    if (this.heldCount === 0 && asleepNext) this.region.clear(b.positions, b.normals);
    else this.region.finish(b.positions, b.weights, b.normalWeights, b.normals);
    if (this.region.revision !== this.listedRevision) this.refreshLists();
  }

  /** Rebuilds the constraint lists for the current region and muscle weights. */
  private refreshLists(): void {
    const included = this.region.enabled ? this.region.inside : null;
    fillEdgeLists(this.edgeLists, this.topology, this.buffers.weights, included, this.buffers.unfoldedLengths);
    this.listBending();
    // Skin that left the region has no step (see projectSecondRingPart).
    this.parts.secondRing.ringMove.fill(0);
    this.parts.secondRing.ownStep.fill(0);
    // The watched flags follow their triangles to their new places.
    const places = this.parts.listedTriangle;
    const watched = this.parts.watched;
    const kept = this.watchedTriangles;
    for (let t = 0; t < places.length; t++) kept[t] = places[t] >= 0 ? watched[places[t]] : 0;
    fillTriangleLists(this.triangleLists, this.topology.triangles, this.triangleFrames, included, places, this.blocks);
    if (this.region.enabled)
      fillTriangleLists(
        this.parts.shadedTriangles,
        this.topology.triangles,
        this.triangleFrames,
        this.region.shaded,
        this.shadedPlaces,
        this.blocks,
      );
    watched.fill(0);
    for (let t = 0; t < places.length; t++) if (places[t] >= 0) watched[places[t]] = kept[t];
    this.listedRevision = this.region.revision;
    if (this.region.enabled) {
      restOutside(this.parts, this.region.inside);
      this.relaxation.restOutside(this.region.inside);
    }
    this.collisions.listCandidates(this.region);
  }

  /** Lists the region's vertices for bending, part by part (see FramePasses.projectBending). */
  private listBending(): void {
    fillBendingLists(this.parts.bending, this.region.vertices, this.region.count, this.bendPasses, this.bendParts);
  }

  /**
   * Takes a share of each vertex's solved move (see relaxation.ts), at most the cap the motion's age sets, half on the
   * partner if any.
   */
  private relax(): void {
    this.passes.share(JOB_RELAX, this.region.count, this.relaxation.nextCap());
  }
}

/** Milliseconds from a monotonic clock (performance.now exists in browsers, workers and Node). */
const now = (): number => performance.now();
