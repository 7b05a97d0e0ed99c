/**
 * The skin solver (thesis 3.1.2 and 4.3): every frame, position, muscle and length constraints are projected in
 * that order, a number of times, over flat Float32Arrays. Added to the thesis: a bending constraint that sets the
 * wrinkle spacing in millimetres, collisions with rigid shapes (eyes, teeth), orientation constraints, a per-vertex
 * relaxation that turns cycles into convergence (see `relax`), the active region: only skin that moves is solved, and
 * a partner thread that can take half of most passes with the same result (see solver-partner.ts).
 */
import { ACTIVE_GROW, ActiveRegion } from './active-region';
import { COLLIDER_SHAPE, colliderDistance, slabSide, writeColliderShape, type Collider } from './colliders';
import {
  createBendingLists,
  createEdgeLists,
  createTriangleLists,
  fillBendingLists,
  fillEdgeLists,
  fillTriangleLists,
  neighbourOffsets,
  PART_EVEN,
  PART_EVEN_SEAM,
  PART_ODD,
  PART_ODD_SEAM,
  PARTS,
  ringParts,
  vertexBlocks,
  type EdgeLists,
  type TriangleLists,
} from './constraint-lists';
import { allocate, type Memory } from './memory';
import {
  JOB_BENDING,
  JOB_COLLISIONS,
  JOB_LENGTHS,
  JOB_NORMALS,
  JOB_ORIENTATION,
  JOB_POSITIONS,
  JOB_RELAX,
  JOB_START_FRAME,
  JOB_STEPS,
} from './partner-board';
import type { PartnerLink } from './partner-link';
import { ALONE, LEADER, runShare } from './solver-partner';
import { ORIENT_AGAIN, ORIENT_FULL, ORIENT_WATCHED, projectOrientationPart } from './orientation-kernel';
import type { PartArrays } from './part-arrays';
import { projectBendingPart } from './solver-kernels';
import { computeNormals, type SkinTopology } from './topology';

/** The skin's parameters; every one can change while the solver runs. */
export interface SkinParameters {
  /** Outer iterations per frame; each projects position, muscle, length (x lengthIterations), bending, collisions. */
  positionIterations: number;
  /** Passes over all length constraints per outer iteration (the thesis found 3 the least that looks soft). */
  lengthIterations: number;
  /** Fraction of the way back to rest per projection: the skin's elasticity (the tissue under it). */
  positionStiffness: number;
  /** Fraction of an edge's length error removed per projection: how little the skin compresses. */
  lengthStiffness: number;
  /** Fraction of the way to a muscle target per projection, times the vertex's muscle weight. */
  muscleStiffness: number;
  /**
   * Wrinkle spacing in metres: the wavelength at which compressed skin folds. It sets the bending stiffness against
   * the position stiffness (a plate on an elastic foundation buckles at 2 pi (B / k)^(1/4)). 0 turns bending off.
   */
  wrinkleSpacing: number;
  /** How much harder the tissue resists skin sinking in along the rest normal than lifting out (1 = symmetric). */
  inwardResistance: number;
  /**
   * Outward push per unit of edge compression, along the rest normal, scaled by the muscle weight at the edge: it
   * starts compressed skin buckling (a flat patch has no other reason to leave its plane) and, being fixed per
   * vertex, pins the fold pattern so the solver settles instead of letting folds drift. Where no muscle holds the skin
   * it is zero, so released skin returns exactly to rest.
   */
  bulge: number;
  /**
   * The solver sleeps once no vertex moves more than this in a frame, relative to the mesh size. The default, 2e-6
   * (0.8 um a frame on the default head), stops within 33 um of where 1e-6 stops on the medium head's expressions,
   * 7 to 30 % sooner (happiness 100 frames against 132, AU26 64 against 91).
   */
  sleepTolerance: number;
  /**
   * Share of its last frame's move each vertex starts the next frame with (heavy-ball acceleration). The frame's
   * fixed points are unchanged (a settled vertex has no move to carry), and the slow fading modes of a soft skin on
   * stiff edges settle in about two thirds of the frames (see the benchmark).
   */
  momentum: number;
  /**
   * The share along the surface in a motion's first START_MOMENTUM_FRAMES frames, when the skin travels farthest. The
   * default rig's 33 expressions on the medium head came within 2 % of their shapes after 937 frames in all against
   * 1,012 with `momentum` throughout (the thesis's laughing 25 against 43) and slept after 2,332 against 2,562, with no
   * more frames showing a triangle turned over on the way; the test field folds as before (see START_MOMENTUM_FRAMES).
   */
  startMomentum: number;
  /**
   * The same share for the part of the move along the vertex's rest normal: how folds rise and settle. A fold near
   * its buckling point moves slowly (AU12's last folds, by the upper lip, stay 1.4 to 1.8 mm off their height for
   * some 20 frames); a larger share there took the default rig's 33 expressions from 1,663 to 1,129 frames to come
   * within 2 % of their shapes. Along the surface, where the fold pattern is chosen, 0.65 or more picks longer folds
   * than `wrinkleSpacing` asks for; along the normal, 0.8 does (0.77 does not), so a motion's first frames, while the
   * pattern forms, take at most FOLD_CHOICE_MOMENTUM (see there).
   */
  foldMomentum: number;
}

export const SKIN_DEFAULTS: Readonly<SkinParameters> = {
  positionIterations: 4,
  lengthIterations: 3,
  positionStiffness: 0.05,
  lengthStiffness: 0.9,
  muscleStiffness: 0.5,
  wrinkleSpacing: 0.012,
  inwardResistance: 3,
  bulge: 0.2,
  sleepTolerance: 2e-6,
  momentum: 0.5,
  startMomentum: 0.7,
  foldMomentum: 0.85,
};

/**
 * Relates the bending stiffness to the wavelength. For the scalar Laplacian constraint on the normal displacement,
 * projected once per outer iteration as the position constraint is, small-slope theory gives
 * lambda = 2 pi h (s_b / (C s_p))^(1/4) for the mesh spacing h across the folds (`SkinTopology.spacing`, the finest
 * direction's: with the mean edge length, the forehead's long quads got a seventh of the stiffness, and both heads
 * folded at their own mesh scale); C was measured on triangle grids (see tests).
 */
const BENDING_CALIBRATION = 6;

/**
 * The most bending share one projection takes; a vertex that needs more is projected in passes of equal parts. The
 * share grows as the spacing to the -4th power, so fine skin asks for whole-strength bending: on the 68k forehead one
 * such projection an iteration, against the muscles' hold, left vertices circling for good (a loop of some 40 frames,
 * each move turning a little, which the relaxation cannot tell from progress); the same share in thirds converges.
 */
const MAX_BENDING_SHARE = 0.35;

/**
 * Skin closer than this to a collider at rest (metres) is checked against it: the lids over the eyes, the lips over
 * the teeth. Farther skin does not reach it in an expression, and checking it would only cost time.
 */
const COLLISION_BAND = 0.006;

/** Typed arrays the solver reads and writes; pass them to place them in shared memory. */
export interface SolverBuffers {
  /** Current positions, xyz per simulation vertex. */
  positions: Float32Array;
  /** Current unit normals. */
  normals: Float32Array;
  /** Muscle target of each vertex, xyz. */
  targets: Float32Array;
  /** Muscle weight of each vertex along the skin's surface, 0..1 (0 on both: no muscle constraint). */
  weights: Float32Array;
  /**
   * Muscle weight of each vertex along its rest normal, 0..1. Muscles that slide skin over the face (linear,
   * sphincter) leave this low so compressed skin is free to fold; rotation muscles (jaw, lids) carry the skin
   * bodily and set it as high as the surface weight.
   */
  normalWeights: Float32Array;
}

/** Allocates the solver's buffers for a topology, positions at rest (on shared memory if `memory` says so). */
export function createSolverBuffers(topology: SkinTopology, memory: Memory = 'local'): SolverBuffers {
  const n = topology.vertexCount;
  const copy = (from: Float32Array): Float32Array => {
    const to = allocate(Float32Array, from.length, memory);
    to.set(from);
    return to;
  };
  return {
    positions: copy(topology.rest),
    normals: copy(topology.restNormals),
    targets: copy(topology.rest),
    weights: allocate(Float32Array, n, memory),
    normalWeights: allocate(Float32Array, n, memory),
  };
}

/** Milliseconds spent in each phase of the last solved frame. */
export interface FrameTimings {
  /** Position and muscle constraints. */
  positions: number;
  lengths: number;
  bending: number;
  collisions: number;
  /** Orientation passes, within the outer iterations and at the frame's end. */
  orientation: number;
  normals: number;
  total: number;
}

/** Counts of each constraint type, as the app's outputs show them. */
export interface ConstraintCounts {
  position: number;
  length: number;
  muscle: number;
  bending: number;
  collision: number;
}

export class SkinSolver {
  readonly topology: SkinTopology;
  readonly buffers: SolverBuffers;
  private readonly params: SkinParameters = { ...SKIN_DEFAULTS };
  private readonly previous: Float32Array;
  /** Each vertex's move in the last frame (xyz), to tell a vertex that turns back from one going somewhere. */
  private readonly lastStep: Float32Array;
  /** Share of its solved move each vertex takes this frame (see `relax`). */
  private readonly relaxation: Float32Array;
  /** 1 for a vertex whose last move turned back on the one before: it carries no momentum into the next frame. */
  private readonly restart: Uint8Array;
  /** Frames since each vertex last turned back, up to 255 (see relax). */
  private readonly calm: Uint8Array;
  /** Frames solved since the last input or parameter change. */
  private motionFrames = 0;
  /** The watched triangles were cleared: the next frame's passes check every triangle (see restartMotion). */
  private watchFresh = true;
  /** Each vertex's way (the sum of its moves) since the loop window began (see breakLoops). */
  private readonly path: Float32Array;
  /** Scratch marks of the vertices breakLoops slows. */
  private readonly looping: Uint8Array;
  /** The longest way a vertex went in the last loop window. */
  private lastLongest = 0;
  private readonly held: Uint32Array;
  private heldCount = 0;
  /** Each vertex's bending share per pass, and its step per unit of the constraint (see PartArrays.bendGain). */
  private readonly bendStiffness: Float32Array;
  private readonly bendGain: Float32Array;
  /** Bending projections of each vertex per outer iteration, and the most any vertex takes (see setParameters). */
  private readonly bendPasses: Uint8Array;
  /** Per vertex, the bending constraint's value at rest (see projectBending), so the frames need not read rest. */
  private readonly bendRest: Float64Array;
  private maxBendPasses = 1;
  /** Each vertex's bending part (see ringParts). */
  private readonly bendParts: Uint8Array;
  /** Per triangle: its rest unit normal (xyz) and the least area it may shrink to along that normal. */
  private readonly triangleFrames: Float32Array;
  /** The lists the per-frame loops walk (see constraint-lists.ts), part by part. */
  private readonly edgeLists: EdgeLists;
  private readonly triangleLists: TriangleLists;
  /** What the heaviest loops read and write (see part-arrays.ts); shared with the partner thread, if any. */
  private readonly parts: PartArrays;
  private partner: PartnerLink | null = null;
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
  private readonly colliders: Collider[];
  private readonly colliderStart: Uint32Array;
  private readonly colliderVertices: Uint32Array;
  private readonly colliderClearance: Float32Array;
  /** Per collision candidate: the side of its slab it lies on at rest (+1 or -1), 0 for spheres and capsules. */
  private readonly colliderSide: Int8Array;
  /**
   * The candidates a frame checks, as indices into the lists above, collider by collider (`activeCandidates[
   * activeCandidateStart[c]..activeCandidateStart[c + 1]]`): those in or next to the active region (all without it),
   * as of `listedRevision`. The others are at rest, where no collider reaches them (see joinReachedCandidates).
   */
  private readonly activeCandidates: Uint32Array;
  private readonly activeCandidateStart: Uint32Array;
  /** Each collider's shape (a, b, up, radius) when the candidates were last checked against it. */
  private readonly colliderShapes: Float64Array;
  /** Scratch: candidates a moved collider reaches. */
  private readonly reached: Uint32Array;
  private readonly direction = new Float32Array(3);
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
    // Outside the active region `previous` is only written when the region changes, and stays at rest.
    this.previous = allocate(Float32Array, 3 * n, memory);
    this.previous.set(topology.rest);
    this.lastStep = allocate(Float32Array, 3 * n, memory);
    this.relaxation = allocate(Float32Array, n, memory).fill(1);
    this.restart = allocate(Uint8Array, n, memory);
    this.calm = allocate(Uint8Array, n, memory).fill(255);
    this.path = allocate(Float32Array, n, memory);
    this.looping = new Uint8Array(n);
    this.held = new Uint32Array(n);
    this.bendStiffness = new Float32Array(n);
    this.bendGain = allocate(Float32Array, n, memory);
    this.bendPasses = allocate(Uint8Array, n, memory);
    // A fixed, deterministic per-vertex seed in [-0.25, 0.75) along the rest normal: breaks the symmetry of a flat
    // compressed patch so it buckles at the wavelength the skin prefers; its positive mean makes folds rise rather than
    // sink. A larger mean lifts the whole patch in one bulge instead of folding it.
    this.bulgeDirections = allocate(Float32Array, 3 * n, memory);
    for (let v = 0; v < n; v++) {
      const seed = hash01(v) - 0.25;
      for (let k = 3 * v; k < 3 * v + 3; k++) this.bulgeDirections[k] = seed * topology.restNormals[k];
    }
    this.triangleFrames = triangleFrames(topology.rest, topology.triangles);
    this.edgeLists = createEdgeLists(topology, memory);
    this.triangleLists = createTriangleLists(topology, memory);
    this.watchedTriangles = new Uint8Array(topology.triangles.length / 3);
    this.shadedPlaces = new Int32Array(topology.triangles.length / 3);
    this.neighbourOffsets = neighbourOffsets(topology);
    this.bendRest = bendingAtRest(topology, this.neighbourOffsets);
    this.blocks = vertexBlocks(topology);
    this.bendParts = ringParts(topology, this.blocks);
    this.region = new ActiveRegion(topology, options.activeRegion ?? true, memory);
    this.colliders = options.colliders ?? [];
    const c = this.collisionCandidates(this.colliders);
    this.colliderStart = c.start;
    this.colliderVertices = c.vertices;
    this.colliderClearance = c.clearance;
    this.colliderSide = c.side;
    this.activeCandidates = allocate(Uint32Array, c.vertices.length, memory);
    this.activeCandidateStart = allocate(Uint32Array, this.colliders.length + 1, memory);
    this.reached = new Uint32Array(c.vertices.length);
    this.colliderShapes = allocate(Float64Array, COLLIDER_SHAPE * this.colliders.length, memory);
    for (let k = 0; k < this.colliders.length; k++) writeColliderShape(this.colliders[k], this.colliderShapes, k);
    const triangleCount = topology.triangles.length / 3;
    // Rounded up to whole words (see PartArrays.uncheckedWords); the flags past the last triangle stay 0.
    const unchecked = allocate(Uint8Array, 4 * Math.ceil(triangleCount / 4), memory);
    const watched = allocate(Uint8Array, unchecked.length, memory);
    this.parts = {
      positions: this.buffers.positions,
      rest: topology.rest,
      restNormals: topology.restNormals,
      targets: this.buffers.targets,
      weights: this.buffers.weights,
      normalWeights: this.buffers.normalWeights,
      normals: this.buffers.normals,
      shadedTriangles: createTriangleLists(topology, memory),
      neighbourStart: topology.neighbourStart,
      neighbourOffsets: this.neighbourOffsets,
      vertexTriangleStart: topology.vertexTriangleStart,
      vertexTriangles: topology.vertexTriangles,
      edges: this.edgeLists,
      bulgeDirections: this.bulgeDirections,
      triangles: this.triangleLists,
      bending: createBendingLists(n, memory),
      bendRest: this.bendRest,
      bendGain: this.bendGain,
      inverseDegree: inverseDegrees(topology, memory),
      bendPasses: this.bendPasses,
      unchecked,
      uncheckedWords: new Uint32Array(unchecked.buffer),
      watched,
      watchedWords: new Uint32Array(watched.buffer),
      listedTriangle: allocate(Int32Array, triangleCount, memory),
      regionVertices: this.region.vertices,
      shadedVertices: this.region.shadedVertices,
      previous: this.previous,
      lastStep: this.lastStep,
      relaxation: this.relaxation,
      restart: this.restart,
      calm: this.calm,
      path: this.path,
      colliders: this.colliders,
      colliderShapes: this.colliderShapes,
      colliderVertices: c.vertices,
      colliderClearance: c.clearance,
      colliderSide: c.side,
      activeCandidates: this.activeCandidates,
      activeCandidateStart: this.activeCandidateStart,
    };
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
    const n = this.topology.vertexCount;
    const twoPi = 2 * Math.PI;
    for (let v = 0; v < n; v++) {
      const h = this.topology.spacing[v];
      const ratio = next.wrinkleSpacing > 0 && h > 0 ? next.wrinkleSpacing / (twoPi * h) : 0;
      // Up to a whole share, in passes of at most MAX_BENDING_SHARE.
      const share = Math.min(1, BENDING_CALIBRATION * next.positionStiffness * ratio ** 4);
      const passes = Math.max(1, Math.ceil(share / MAX_BENDING_SHARE));
      this.bendPasses[v] = passes;
      this.bendStiffness[v] = share / passes;
    }
    // Skin at a collider and the ring around it: one pass, see COLLIDER_BENDING_STIFFNESS.
    const start = this.topology.neighbourStart;
    const nb = this.topology.neighbours;
    const cap = (v: number): void => {
      this.bendStiffness[v] = Math.min(COLLIDER_BENDING_STIFFNESS, this.bendPasses[v] * this.bendStiffness[v]);
      this.bendPasses[v] = 1;
    };
    for (let j = 0; j < this.colliderVertices.length; j++) {
      const v = this.colliderVertices[j];
      cap(v);
      for (let k = start[v]; k < start[v + 1]; k++) cap(nb[k]);
    }
    this.maxBendPasses = 1;
    for (let v = 0; v < n; v++) {
      if (this.bendPasses[v] > this.maxBendPasses) this.maxBendPasses = this.bendPasses[v];
      // The share over the gradient's squared norm, 1 + 1 / degree (see projectBendingPart).
      const degree = start[v + 1] - start[v];
      this.bendGain[v] = degree > 0 ? this.bendStiffness[v] / (1 + 1 / degree) : 0;
    }
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
    this.joinReachedCandidates();
    // Of the lists, only the edges' depend on the weights (held edges apart, with their weight): while a slider moves
    // the region mostly stays as it is, and the other lists with it.
    if (this.region.revision !== this.listedRevision) this.refreshLists();
    else fillEdgeLists(this.edgeLists, this.topology, this.buffers.weights, this.region.enabled ? this.region.inside : null);
    this.inputsChanged = true;
    this.restartMotion();
  }

  /** A new motion (new inputs or parameters): every vertex may take whole steps again. */
  private restartMotion(): void {
    this.motionFrames = 0;
    this.relaxation.fill(1);
    this.calm.fill(255);
    this.path.fill(0);
    this.lastLongest = 0;
    this.lastStep.fill(0);
    // A motion from rest watches anew: its first frame's passes check every triangle (see ORIENT_WATCH). Inputs that
    // come while the skin still moves (a slider dragged, a timeline played) keep the set, which only grows, so that
    // each frame of a drag is not a first one: the frame's last passes check every triangle either way, and add those
    // near their bound. A drag's frames cost a fifth more when each one checked every triangle in its iterations.
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

  /** Threads that solve: 2 with a partner attached, else 1. */
  get threads(): number {
    return this.partner ? 2 : 1;
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
    this.partner = link;
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
      collision: this.colliderVertices.length,
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
      this.motionFrames < FOLD_CHOICE_FRAMES && p.foldMomentum > FOLD_CHOICE_MOMENTUM ? FOLD_CHOICE_MOMENTUM : p.foldMomentum;
    this.startFrame(this.motionFrames < START_MOMENTUM_FRAMES ? p.startMomentum : p.momentum, foldMomentum);
    for (let it = 0; it < p.positionIterations; it++) {
      let t0 = now();
      this.projectPositions();
      let t1 = now();
      time.positions += t1 - t0;
      t0 = t1;
      this.projectLengths(p.lengthIterations);
      t1 = now();
      time.lengths += t1 - t0;
      // A motion's first frame from rest checks every triangle and so starts the watched set (see ORIENT_WATCH).
      this.projectOrientation(this.watchFresh ? ORIENT_FULL : ORIENT_WATCHED);
      t0 = now();
      time.orientation += t0 - t1;
      t1 = t0;
      this.projectBending();
      t0 = now();
      time.bending += t0 - t1;
      this.projectCollisions();
      time.collisions += now() - t0;
    }
    this.watchFresh = false;
    // Dense fans (the mouth's corners) need a few passes to untangle. After the relaxation, which blends two shapes
    // and so could turn a sliver over, the passes hold only half the bound: whole-bound passes there undid the
    // relaxation in the fans, where the corrections then took turns with the other constraints until the safety net
    // (AU43 ran 1,249 frames, 247 with half; see ORIENTATION_SHOWN_FLOOR).
    let untangle = now();
    for (let k = 0; k < ORIENTATION_PASSES && this.projectOrientation(k > 0 ? ORIENT_AGAIN : ORIENT_FULL); k++);
    time.orientation += now() - untangle;
    this.settleRegion();
    this.relax();
    untangle = now();
    for (
      let k = 0;
      k < ORIENTATION_SHOWN_PASSES && this.projectOrientation(k > 0 ? ORIENT_AGAIN : ORIENT_FULL, ORIENTATION_SHOWN_FLOOR);
      k++
    );
    time.orientation += now() - untangle;
    // The frame's true move, after every pass: what the sleep test and the relaxation see.
    this.lastMove = this.recordSteps();
    if (this.motionFrames % LOOP_WINDOW === 0) this.breakLoops();
    this.frames++;
    this.restRegionRing();
    const beforeNormals = now();
    this.computeNormals();
    const end = now();
    time.normals = end - beforeNormals;
    time.total = end - start;
    const changed = this.inputsChanged;
    this.inputsChanged = false;
    if (!changed && this.lastMove <= p.sleepTolerance * this.topology.size) this.asleep = true;
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
    fillEdgeLists(this.edgeLists, this.topology, this.buffers.weights, included);
    this.listBending();
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
      // Skin outside the region is at rest and does not move: its last step is zero, its previous place rest and it
      // has no turn to remember, so that a vertex joining within a frame (see settleRegion) starts from there, as it
      // would had it never been in the region.
      const inside = this.region.inside;
      const last = this.lastStep;
      const prev = this.previous;
      const restart = this.restart;
      const X = this.topology.rest;
      for (let v = 0; v < inside.length; v++) {
        if (inside[v]) continue;
        const i = 3 * v;
        restart[v] = 0;
        this.path[v] = 0;
        last[i] = last[i + 1] = last[i + 2] = 0;
        prev[i] = X[i];
        prev[i + 1] = X[i + 1];
        prev[i + 2] = X[i + 2];
      }
    }
    this.listCandidates();
  }

  /** Lists the region's vertices for bending, part by part (see projectBending). */
  private listBending(): void {
    fillBendingLists(this.parts.bending, this.region.vertices, this.region.count, this.bendPasses, this.bendParts);
  }

  /** Lists the collision candidates a frame checks: those in or next to the region (all of them without it). */
  private listCandidates(): void {
    const r = this.region;
    const near = r.shaded;
    const V = this.colliderVertices;
    const list = this.activeCandidates;
    const start = this.activeCandidateStart;
    let count = 0;
    for (let c = 0; c < this.colliders.length; c++) {
      for (let j = this.colliderStart[c]; j < this.colliderStart[c + 1]; j++) if (!r.enabled || near[V[j]] === 1) list[count++] = j;
      start[c + 1] = count;
    }
  }

  /**
   * When the inputs change, a collider may have moved (the lower teeth turn with the jaw; colliders move only with an
   * input change): the candidates outside the region that one which moved now pushes farther than the region's
   * tolerance join it, as they would had the frame pushed them (see ActiveRegion.grow). Skin outside the region is
   * at rest, which no collider reaches as long as it is where it was at rest, so the frames check only candidates in
   * or next to the region.
   */
  private joinReachedCandidates(): void {
    const r = this.region;
    const x = this.buffers.positions;
    const dir = this.direction;
    const tolerance = ACTIVE_GROW * this.topology.size;
    let count = 0;
    for (let c = 0; c < this.colliders.length; c++) {
      const collider = this.colliders[c];
      if (!writeColliderShape(collider, this.colliderShapes, c) || !r.enabled) continue;
      for (let j = this.colliderStart[c]; j < this.colliderStart[c + 1]; j++) {
        const v = this.colliderVertices[j];
        if (r.inside[v] === 1) continue;
        const i = 3 * v;
        const d = colliderDistance(collider, x[i], x[i + 1], x[i + 2], dir, this.colliderSide[j]);
        if (this.colliderClearance[j] - d > tolerance) this.reached[count++] = v;
      }
    }
    r.join(this.reached, count);
  }

  /**
   * Normals of the skin that may have moved: the region and its ring (all of it without the active region), half on
   * the partner if any. The ring's outer neighbours, which the ring's triangles touch, keep their rest normals.
   */
  private computeNormals(): void {
    const r = this.region;
    const out = this.buffers.normals;
    if (!r.enabled) {
      computeNormals(this.buffers.positions, this.topology.triangles, out);
      return;
    }
    const count = r.shadedCount;
    zeroAt(out, r.shadedVertices, count);
    zeroAt(out, r.outer, r.outerCount);
    this.share(JOB_NORMALS, count);
    const N = this.topology.restNormals;
    for (let k = 0; k < r.outerCount; k++) {
      const i = 3 * r.outer[k];
      out[i] = N[i];
      out[i + 1] = N[i + 1];
      out[i + 2] = N[i + 2];
    }
  }

  /**
   * Takes a share of each vertex's solved move. Where the hard constraints (collisions, orientation) meet stiff
   * bending, the frame's map can hand a vertex back and forth between two shapes (a period-2 cycle: its move turns
   * back on the last one). Such a vertex takes half as much of its moves from then on (down to MIN_RELAXATION),
   * which turns the cycle into a contraction toward the shape between. A cycle repeats: a single turn (a lip bouncing
   * off a tooth as the skin sets off) halves nothing, a second within CYCLE_TURNS_WITHIN frames does (halving at the
   * first turn left such a vertex creeping at a sixteenth of its moves for 200 frames: AU12 took 192 frames to come
   * within 2 % of its shape, now 78). Shares only shrink within a motion (a new
   * input restores whole moves), so the frame's map stops changing after a few halvings instead of starting cycles
   * of its own. An under-relaxed step has the same fixed points as a whole one: the skin comes to rest in the shape
   * the constraints ask for, by convergence, not by being slowed down (the thesis's iteration has no such step).
   * A safety net remains for skin still drifting LATE_MOTION frames after an input (a few lid and lip vertices in
   * 2 of the default rig's 33 expressions, by micrometres a frame): from then on every share shrinks each frame.
   */
  private relax(): void {
    const late = this.motionFrames++ - LATE_MOTION;
    const cap = late > 0 ? LATE_SLOWING ** late : 1;
    this.share(JOB_RELAX, this.region.count, cap);
  }

  /**
   * Every LOOP_WINDOW frames: if the longest way a vertex went in the window is not clearly shorter than in the one
   * before, the skin has stalled: it circles (a smooth loop of a few dozen frames a turn, where no move turns back on
   * the one before, so `relax` does not see it) or chatters at its least share where the hard constraints take turns.
   * The vertices that went far (over STALL_PART of the longest way) and their neighbours (the loop is a mode of the
   * patch: slowing one vertex moves the loop next to it) take a quarter of their moves from then on (LOOP_SLOWING).
   * An under-relaxed step has the same fixed points, so where the constraints have one the skin converges to it;
   * where they only chatter, the patch slows until it sleeps, long before the safety net (see LATE_MOTION). Skin that
   * converges shortens its way by more than a tenth a window (a third of a per cent a frame) and is left alone: eight
   * of the rig's slowest expressions on the medium head took the same frames with the threshold at 0.9 and at 0.95.
   */
  private breakLoops(): void {
    const path = this.path;
    const mark = this.looping;
    const share = this.relaxation;
    const V = this.region.vertices;
    const count = this.region.count;
    let longest = 0;
    for (let k = 0; k < count; k++) if (path[V[k]] > longest) longest = path[V[k]];
    // Skin going less than the sleep tolerance a frame is about to sleep.
    const least = LOOP_WINDOW * this.params.sleepTolerance * this.topology.size;
    const stalled = this.motionFrames > LOOP_WINDOW && longest > least && longest > STALL * this.lastLongest;
    this.lastLongest = longest;
    const far = Math.max(least, STALL_PART * longest);
    const start = this.topology.neighbourStart;
    const nb = this.topology.neighbours;
    let marked = 0;
    for (let k = 0; k < count; k++) {
      const v = V[k];
      if (stalled && path[v] > far) {
        mark[v] = 1;
        for (let j = start[v]; j < start[v + 1]; j++) mark[nb[j]] = 1;
        marked++;
      }
      path[v] = 0;
    }
    if (marked === 0) return;
    // Only the region's shares change: a marked neighbour outside it is at rest and joins, if ever, with a whole share.
    for (let k = 0; k < count; k++) {
      const v = V[k];
      if (mark[v] === 1 && share[v] > LOOP_LEAST_SHARE) share[v] *= LOOP_SLOWING;
    }
    mark.fill(0);
  }

  /**
   * Stores where each region vertex starts the frame (skin outside the region stays at rest, and so does `previous`
   * there; see refreshLists), then carries its momentum. Heavy-ball acceleration (Polyak): each region vertex first
   * takes `beta` times its last move along the surface and `foldBeta` times its last move along its rest normal, then
   * the frame's projections. The soft position constraint lets a displaced sheet fade by only a few per cent an
   * iteration; the carried move makes the slow modes fade about as the square root of that factor per frame. A
   * carried move that overshoots turns back, and the relaxation treats that as any cycle.
   */
  private startFrame(beta: number, foldBeta: number): void {
    this.share(JOB_START_FRAME, this.region.count, beta, foldBeta);
  }

  /** Stores each vertex's move of this frame and returns the largest. */
  private recordSteps(): number {
    const mine = this.share(JOB_STEPS, this.region.count);
    return Math.sqrt(this.partner ? Math.max(mine, this.partner.board.value[0]) : mine);
  }

  /**
   * Position and muscle constraints (thesis 4.3.2 and 4.3.4; see projectPositions in solver-kernels.ts), half on the
   * partner if any.
   */
  private projectPositions(): void {
    const s = this.params.positionStiffness;
    const extra = s * (this.params.inwardResistance - 1);
    const m = this.params.muscleStiffness;
    this.share(JOB_POSITIONS, this.region.count, s, extra, m);
  }

  /**
   * `passes` passes of the length constraints (thesis 4.3.3; see projectLengths in length-kernels.ts), with the
   * partner if there is one (one job for all the passes).
   */
  private projectLengths(passes: number): void {
    this.share(JOB_LENGTHS, passes, this.params.lengthStiffness, this.params.bulge);
  }

  /**
   * Orientation constraints (see projectOrientationPart), part by part as the lengths; returns whether a triangle was
   * more than a hair under its bound.
   */
  private projectOrientation(mode: number, floor = 1): boolean {
    const blocks = this.orientationPair(PART_EVEN, PART_ODD, mode, floor);
    return this.orientationPair(PART_EVEN_SEAM, PART_ODD_SEAM, mode, floor) || blocks;
  }

  private orientationPair(mine: number, theirs: number, mode: number, floor: number): boolean {
    const partner = this.partner;
    partner?.start(JOB_ORIENTATION, theirs, mode, floor);
    const corrected = projectOrientationPart(this.parts, mine, mode, floor);
    if (partner) return partner.finish() !== 0 || corrected;
    return projectOrientationPart(this.parts, theirs, mode, floor) || corrected;
  }

  /**
   * Bending: keeps the Laplacian of the normal displacement near zero (the rest curvature), scaled per vertex by the
   * local mesh spacing so that its balance against the position constraints gives folds of `wrinkleSpacing` at every
   * mesh resolution (thesis 3.1.2 wishes for such a skin parameter). A vertex whose share exceeds MAX_BENDING_SHARE
   * is projected in several passes, one after another over the region, each of an equal part of it. Each pass goes
   * part by part as the orientation passes (see projectBendingPart): the even blocks with the odd ones, then the even
   * seams with the odd ones, each part in vertex order, so that two threads share it and one gives the same shape.
   */
  private projectBending(): void {
    if (this.params.wrinkleSpacing <= 0) return;
    for (let pass = 0; pass < this.maxBendPasses; pass++) {
      this.bendingPair(PART_EVEN, PART_ODD, pass);
      this.bendingPair(PART_EVEN_SEAM, PART_ODD_SEAM, pass);
    }
  }

  private bendingPair(mine: number, theirs: number, pass: number): void {
    const partner = this.partner;
    partner?.start(JOB_BENDING, theirs + PARTS * pass);
    projectBendingPart(this.parts, pass, mine);
    if (partner) partner.finish();
    else projectBendingPart(this.parts, pass, theirs);
  }

  /**
   * Collisions: a vertex that was outside a collider at rest keeps at least its rest clearance (capped at 1 mm).
   * Only the candidates in or next to the active region are checked (see listCandidates); half on the partner if any.
   */
  private projectCollisions(): void {
    this.share(JOB_COLLISIONS, 0);
  }

  /**
   * Runs a job that splits in two (see runShare): all of it here, or the first half here and the second on the partner
   * thread at the same time. Returns this thread's result (JOB_STEPS: its largest squared move).
   */
  private share(job: number, count: number, a = 0, b = 0, c = 0): number {
    const partner = this.partner;
    if (!partner) return runShare(this.parts, job, count, a, b, c, ALONE, null, this.direction);
    partner.start(job, count, a, b, c);
    const mine = runShare(this.parts, job, count, a, b, c, LEADER, partner.board.words, this.direction);
    partner.finish();
    return mine;
  }

  /**
   * Each vertex within COLLISION_BAND of a collider at rest, outside it, is checked against the nearest one, on the
   * side of it where it lies at rest (a lip in front of the teeth stays in front).
   */
  private collisionCandidates(colliders: Collider[]): {
    start: Uint32Array;
    vertices: Uint32Array;
    clearance: Float32Array;
    side: Int8Array;
  } {
    const X = this.topology.rest;
    const n = this.topology.vertexCount;
    const nearest = new Int32Array(n).fill(-1);
    const distance = new Float32Array(n).fill(Infinity);
    const dir = [0, 0, 0];
    colliders.forEach((c, ci) => {
      for (let v = 0; v < n; v++) {
        const d = colliderDistance(c, X[3 * v], X[3 * v + 1], X[3 * v + 2], dir);
        if (d < distance[v]) {
          distance[v] = d;
          nearest[v] = ci;
        }
      }
    });
    const start = new Uint32Array(colliders.length + 1);
    const vertices: number[] = [];
    const clearance: number[] = [];
    const side: number[] = [];
    for (let ci = 0; ci < colliders.length; ci++) {
      for (let v = 0; v < n; v++) {
        // Skin inside a collider at rest (the eye socket's lining behind the eyeball) is left alone.
        if (nearest[v] === ci && distance[v] >= 0 && distance[v] < COLLISION_BAND) {
          vertices.push(v);
          clearance.push(Math.min(distance[v], 0.001));
          side.push(slabSide(colliders[ci], X[3 * v], X[3 * v + 1], X[3 * v + 2]));
        }
      }
      start[ci + 1] = vertices.length;
    }
    return { start, vertices: Uint32Array.from(vertices), clearance: Float32Array.from(clearance), side: Int8Array.from(side) };
  }
}

/**
 * Throws an error naming the first bad muscle-target input: a vertex that is not one of `vertexCount`, a target
 * coordinate that is not finite, a weight outside 0..1. Every entry point checks with this before changing anything.
 */
export function checkMuscleTargets(
  vertexCount: number,
  vertices: ArrayLike<number>,
  targets: ArrayLike<number>,
  weight: number,
  normalWeight: number,
): void {
  const isArrayLike = (a: unknown): boolean => Array.isArray(a) || ArrayBuffer.isView(a);
  if (!isArrayLike(vertices) || !isArrayLike(targets)) throw new Error('setMuscleTargets: vertices and targets must be arrays of numbers');
  if (targets.length !== 3 * vertices.length) {
    throw new Error(`setMuscleTargets: ${vertices.length} vertices need ${3 * vertices.length} target coordinates, got ${targets.length}`);
  }
  for (const [name, w] of [
    ['weight', weight],
    ['normal weight', normalWeight],
  ] as const) {
    if (typeof w !== 'number' || !Number.isFinite(w) || w < 0 || w > 1)
      throw new Error(`setMuscleTargets: ${name} must be a finite number from 0 to 1, got ${w}`);
  }
  for (let i = 0; i < vertices.length; i++) {
    const v = vertices[i];
    if (!Number.isInteger(v) || v < 0 || v >= vertexCount)
      throw new Error(`setMuscleTargets: vertex ${i} is ${v}, not one of the ${vertexCount} skin vertices`);
    for (let k = 0; k < 3; k++) {
      const t = targets[3 * i + k];
      if (typeof t !== 'number' || !Number.isFinite(t)) {
        throw new Error(`setMuscleTargets: the target of vertex ${v} (entry ${i}) has a non-finite ${'xyz'[k]} coordinate: ${t}`);
      }
    }
  }
}

/**
 * The muscles' pull on each vertex, as the rig computes it (MuscleRig.compute) and the solver takes it: the solver's
 * buffers, the worker's control block and a batch of inputs all have this shape.
 */
export interface MuscleInputs {
  /** Muscle target of each vertex, xyz. */
  targets: Float32Array;
  /** Muscle weight along the skin's surface, per vertex, 0..1. */
  weights: Float32Array;
  /** Muscle weight along the rest normal, per vertex, 0..1. */
  normalWeights: Float32Array;
}

/** Writes checked muscle targets (see checkMuscleTargets) and both weights for some vertices into `into`. */
export function writeMuscleTargets(
  into: MuscleInputs,
  vertices: ArrayLike<number>,
  targets: ArrayLike<number>,
  weight: number,
  normalWeight: number,
): void {
  const { targets: T, weights: W, normalWeights: WN } = into;
  for (let i = 0; i < vertices.length; i++) {
    const v = vertices[i];
    T[3 * v] = targets[3 * i];
    T[3 * v + 1] = targets[3 * i + 1];
    T[3 * v + 2] = targets[3 * i + 2];
    W[v] = weight;
    WN[v] = normalWeight;
  }
}

/** Releases every vertex: targets back at rest, both weights 0. */
export function clearMuscleInputs(into: MuscleInputs, rest: Float32Array): void {
  into.targets.set(rest);
  into.weights.fill(0);
  into.normalWeights.fill(0);
}

const RANGES: Record<keyof SkinParameters, [number, number, boolean]> = {
  positionIterations: [1, 64, true],
  lengthIterations: [0, 64, true],
  positionStiffness: [0, 1, false],
  lengthStiffness: [0, 1, false],
  muscleStiffness: [0, 1, false],
  wrinkleSpacing: [0, 1, false],
  inwardResistance: [1, 100, false],
  bulge: [0, 10, false],
  sleepTolerance: [0, 1, false],
  momentum: [0, 0.9, false],
  startMomentum: [0, 0.9, false],
  foldMomentum: [0, 0.9, false],
};

/** Throws an error naming the first parameter that is not a finite number within its range. */
export function validateParameters(p: SkinParameters): void {
  for (const [name, [lo, hi, integer]] of Object.entries(RANGES) as [keyof SkinParameters, [number, number, boolean]][]) {
    const v = p[name];
    if (typeof v !== 'number' || !Number.isFinite(v)) throw new Error(`skin parameter ${name} must be a finite number, got ${v}`);
    if (v < lo || v > hi) throw new Error(`skin parameter ${name} must be between ${lo} and ${hi}, got ${v}`);
    if (integer && !Number.isInteger(v)) throw new Error(`skin parameter ${name} must be a whole number, got ${v}`);
  }
}

/** Milliseconds from a monotonic clock (performance.now exists in browsers, workers and Node). */
const now = (): number => performance.now();

/**
 * The most bending stiffness skin at a collider (and the ring around it) gets. The lids over the eyes and the lips
 * over the teeth are meshed finely, so bending there asks for whole-strength projections; those and the collider's
 * push, every outer iteration, hand the skin back and forth without end (measured: AU7, AU26, AU43 and the
 * thesis's laughing never came to rest). A quarter keeps them converging; the folds there are set by the collider.
 */
const COLLIDER_BENDING_STIFFNESS = 0.25;

/**
 * A motion's first frames, in which compressed skin chooses its fold pattern, carry at most this share of a move along
 * the normal; the frames after carry `foldMomentum` (0.85 by default). More while the folds form picks longer ones
 * than the skin's wavelength asks for (0.8 does); once formed, folds only rise, sink and slide, slowly (a fold beside
 * the eye in happiness slid one edge over some 30 frames), and the larger share moves them there sooner. The default
 * rig's 33 expressions on the medium head came within 2 % of their shapes after 1,011 frames in all (979 with the
 * length stiffness 1e-4 higher) against 1,135 (1,077) with 0.75 throughout; they sleep later, after 2,636 frames
 * against 2,392 (happiness within 2 % after 38 frames instead of 48, asleep after 135 instead of 93), measured before
 * LOOP_SLOWING was a quarter.
 */
const FOLD_CHOICE_MOMENTUM = 0.75;
/** Frames after an input or parameter change during which FOLD_CHOICE_MOMENTUM caps the fold momentum. */
const FOLD_CHOICE_FRAMES = 15;

/**
 * Frames after an input or parameter change that carry `startMomentum` along the surface instead of `momentum`. A
 * motion's first frames take the skin most of its way, and a larger carry there takes it in fewer frames; after them
 * the folds settle, slide and stop, where the larger share made patches circle and chatter (0.7 throughout: AU43 122
 * frames to 2 % instead of 54). The schedules tried, frames to 2 % over the 33 expressions: 0.7 for 8, 10 or 12
 * frames 994, 937 and 949; 0.65 or 0.75 for 10 frames 923 and 906, but 0.75 showed a triangle turned over in 95
 * frames on the way against 66. The test field's folds: 6.67 mm for 6 mm asked (6.66 with 0.5), 9.64 for 12 (9.64).
 */
export const START_MOMENTUM_FRAMES = 10;

/** Frames after an input after which still-moving skin is slowed down for good (see SkinSolver.relax). */
export const LATE_MOTION = 1000;
/** Per frame after LATE_MOTION, the cap on every vertex's share shrinks by this factor. */
const LATE_SLOWING = 0.98;

/** Frames over which the skin's ways are weighed against the window before (see SkinSolver.breakLoops). */
const LOOP_WINDOW = 32;
/** Skin whose longest way in a window is more than this share of the last window's has stalled. */
const STALL = 0.9;
/** In stalled skin, the vertices that went more than this share of the longest way are slowed, with their neighbours. */
const STALL_PART = 0.25;
/**
 * The factor on a stalled vertex's share each window (see SkinSolver.breakLoops). With a half, anger's corner loop
 * (some 80 um a frame) took seven windows to fall below the sleep tolerance: it slept after 321 frames, 3.5 s in the
 * page. A quarter: 193 frames; over the medium head's 33 expressions, 2,562 frames to sleep against 2,636, the same
 * frames to 2 % but one (AU43 slept after 329 instead of 293, AU23 161 instead of 143).
 */
const LOOP_SLOWING = 0.25;
/** The least share breakLoops leaves a vertex (a thousandth: its moves are then far below the sleep tolerance). */
const LOOP_LEAST_SHARE = 1 / 1024;

/**
 * The least share of its rest area a triangle keeps along its rest normal: a triangle tilted 75 degrees into a fold
 * still passes, one flattened to a sliver or turned over does not.
 */
export const MIN_PROJECTED_AREA = 0.25;
/**
 * At most this many orientation passes end a frame's iterations, before the relaxation (they stop once one corrects
 * nothing).
 */
const ORIENTATION_PASSES = 12;
/** After the relaxation at most this many passes follow, at ORIENTATION_SHOWN_FLOOR of the bound. */
const ORIENTATION_SHOWN_PASSES = 6;
/**
 * The share of the orientation bound the passes after the relaxation hold. A blend of two untangled shapes seldom
 * turns a triangle over but often leaves one a little under the bound; lifting it all the way back moved the fans'
 * skin by more than the relaxation let it, every frame. Half the bound: 33 expressions took 4,823 frames to sleep
 * with the whole bound, 3,042 with half, with fewer frames showing a triangle turned over (109 against 200).
 */
const ORIENTATION_SHOWN_FLOOR = 0.5;

/**
 * The neighbours' mean height above each vertex at rest, along the vertex's rest normal: what the bending constraint
 * takes away from the same height now, so that a frame reads only the current positions.
 */
function bendingAtRest(topology: SkinTopology, offsets: Uint32Array): Float64Array {
  const X = topology.rest;
  const N = topology.restNormals;
  const start = topology.neighbourStart;
  const out = new Float64Array(X.length / 3);
  for (let v = 0; v < out.length; v++) {
    const degree = start[v + 1] - start[v];
    if (degree === 0) continue;
    const i = 3 * v;
    let mean = 0;
    for (let j = start[v]; j < start[v + 1]; j++) {
      const k = offsets[j];
      mean += X[k] * N[i] + X[k + 1] * N[i + 1] + X[k + 2] * N[i + 2];
    }
    out[v] = mean / degree - (X[i] * N[i] + X[i + 1] * N[i + 1] + X[i + 2] * N[i + 2]);
  }
  return out;
}

/** 1 / each vertex's degree (0 for none), for the bending step. */
function inverseDegrees(topology: SkinTopology, memory: Memory): Float32Array {
  const start = topology.neighbourStart;
  const out = allocate(Float32Array, topology.vertexCount, memory);
  for (let v = 0; v < out.length; v++) {
    const degree = start[v + 1] - start[v];
    out[v] = degree > 0 ? 1 / degree : 0;
  }
  return out;
}

/** Each triangle's rest unit normal and twice its least projected area (MIN_PROJECTED_AREA of the rest), xyzA. */
function triangleFrames(rest: Float32Array, triangles: Uint32Array): Float32Array {
  const count = triangles.length / 3;
  const out = new Float32Array(4 * count);
  for (let t = 0; t < count; t++) {
    const a = 3 * triangles[3 * t];
    const b = 3 * triangles[3 * t + 1];
    const c = 3 * triangles[3 * t + 2];
    const ux = rest[b] - rest[a],
      uy = rest[b + 1] - rest[a + 1],
      uz = rest[b + 2] - rest[a + 2];
    const vx = rest[c] - rest[a],
      vy = rest[c + 1] - rest[a + 1],
      vz = rest[c + 2] - rest[a + 2];
    const cx = uy * vz - uz * vy,
      cy = uz * vx - ux * vz,
      cz = ux * vy - uy * vx;
    const twiceArea = Math.hypot(cx, cy, cz);
    if (twiceArea === 0) continue;
    out[4 * t] = cx / twiceArea;
    out[4 * t + 1] = cy / twiceArea;
    out[4 * t + 2] = cz / twiceArea;
    out[4 * t + 3] = MIN_PROJECTED_AREA * twiceArea;
  }
  return out;
}

/** Zeroes the xyz of the first `count` listed vertices. */
function zeroAt(out: Float32Array, vertices: Uint32Array, count: number): void {
  for (let k = 0; k < count; k++) {
    const i = 3 * vertices[k];
    out[i] = out[i + 1] = out[i + 2] = 0;
  }
}

/** A fixed hash of an integer to [0, 1). */
function hash01(i: number): number {
  let h = Math.imul(i ^ 0x9e3779b9, 0x85ebca6b);
  h ^= h >>> 13;
  h = Math.imul(h, 0xc2b2ae35);
  h ^= h >>> 16;
  return (h >>> 0) / 4294967296;
}
