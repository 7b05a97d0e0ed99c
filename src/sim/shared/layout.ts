/**
 * Memory layouts shared by the main thread and the skin worker: named word offsets plus small accessors, so both
 * sides agree on where every value lives (the style of three-mesh-bvh's buffer layouts).
 *
 * Control block (main thread writes, solver reads): an Int32 header, the skin parameters as Float64 (so a parameter
 * reaches the solver exactly as given, as it does in `main` mode), then the muscle targets and weights (along the surface and along the
 * normal) as Float32
 * (the solver's own precision), the rig's contractions and the head pose (HEAD_POSE_SLOTS floats).
 *
 * Output block (solver writes, main thread reads): an Int32 header, then two frame slots. Each slot has its own
 * header (frame number, sleep state, solve time, bounds...) so that metadata always matches the vertices beside it.
 */
import type { HeadPose } from '../../core/expression/head-pose';
import { MAX_RIG_MUSCLES } from '../../core/rig/rig-schema';
import type { SkinParameters } from '../../core/solver/skin-parameters';
import type { ConstraintCounts } from '../../core/solver/solver-buffers';

// ---- control block -------------------------------------------------------------------------------------------

/** Input sequence: odd while the main thread writes a batch of inputs, even once the batch is published. */
export const CONTROL_INPUT_SEQ = 0;
/** Bumped whenever the muscle targets or weights change. */
export const CONTROL_MUSCLE_REVISION = 1;
/** Bumped whenever the skin parameters change. */
export const CONTROL_PARAMETER_REVISION = 2;
/** Bumped whenever the rig's muscle contractions change. */
export const CONTROL_CONTRACTION_REVISION = 3;
/**
 * The rig edit the batch belongs to: a batch is applied only once the solver has the rig edits up to it (they come
 * as messages, which may arrive after the batch is published).
 */
export const CONTROL_RIG_REVISION = 4;
const CONTROL_HEADER_BYTES = 64;

/** Where each skin parameter sits in the control block's Float64 parameter array. Exhaustive by type. */
const PARAMETER_INDEX: Readonly<Record<keyof SkinParameters, number>> = {
  positionIterations: 0,
  lengthIterations: 1,
  positionStiffness: 2,
  lengthStiffness: 3,
  muscleStiffness: 4,
  wrinkleSpacing: 5,
  inwardResistance: 6,
  bulge: 7,
  sleepTolerance: 8,
  momentum: 9,
  foldMomentum: 10,
  startMomentum: 11,
  pretension: 12,
};
const PARAMETER_NAMES = Object.keys(PARAMETER_INDEX) as (keyof SkinParameters)[];
export const PARAMETER_COUNT = PARAMETER_NAMES.length;

/** Byte offsets of the control block's parts for a skin of `vertexCount` simulation vertices. */
export interface ControlLayout {
  vertexCount: number;
  parametersByteOffset: number;
  targetsByteOffset: number;
  weightsByteOffset: number;
  normalWeightsByteOffset: number;
  muscleCount: number;
  contractionsByteOffset: number;
  headPoseByteOffset: number;
  byteLength: number;
}

/**
 * Room for contractions in the control block: a rig being edited may grow up to the schema's limit, and the block
 * (shared with the worker) cannot grow, so it holds that many from the start.
 */
export function contractionCapacity(muscleCount: number): number {
  return Math.max(muscleCount, MAX_RIG_MUSCLES);
}

/** Floats of the head pose in the control block: yaw, pitch, roll (degrees) and forward (metres); see head-pose.ts. */
export const HEAD_POSE_SLOTS = 4;

/** Writes a head pose into its control-block view (HEAD_POSE_SLOTS floats). */
export function writeHeadPose(pose: HeadPose, into: Float32Array): void {
  into[0] = pose.yaw;
  into[1] = pose.pitch;
  into[2] = pose.roll;
  into[3] = pose.forward;
}

/** Reads a head pose from its control-block view into `out`, and returns it. */
export function readHeadPose(from: ArrayLike<number>, out: HeadPose): HeadPose {
  out.yaw = from[0];
  out.pitch = from[1];
  out.roll = from[2];
  out.forward = from[3];
  return out;
}

export function controlLayout(vertexCount: number, muscleCount = 0): ControlLayout {
  const parametersByteOffset = CONTROL_HEADER_BYTES;
  const targetsByteOffset = align(parametersByteOffset + 8 * PARAMETER_COUNT, 16);
  const weightsByteOffset = targetsByteOffset + 4 * 3 * vertexCount;
  const normalWeightsByteOffset = weightsByteOffset + 4 * vertexCount;
  return {
    vertexCount,
    parametersByteOffset,
    targetsByteOffset,
    weightsByteOffset,
    normalWeightsByteOffset,
    muscleCount,
    contractionsByteOffset: normalWeightsByteOffset + 4 * vertexCount,
    headPoseByteOffset: normalWeightsByteOffset + 4 * vertexCount + 4 * muscleCount,
    byteLength: align(normalWeightsByteOffset + 4 * vertexCount + 4 * (muscleCount + HEAD_POSE_SLOTS), 16),
  };
}

/** Typed views of a control block. */
export interface ControlViews {
  words: Int32Array;
  parameters: Float64Array;
  targets: Float32Array;
  weights: Float32Array;
  normalWeights: Float32Array;
  /** Contraction of each rig muscle, 0..1, in the rig's muscle order (the rig may use fewer than there are). */
  contractions: Float32Array;
  /** The head pose (see HEAD_POSE_SLOTS), changed with the contractions' revision. */
  headPose: Float32Array;
}

export function controlViews(buffer: ArrayBufferLike, layout: ControlLayout): ControlViews {
  const n = layout.vertexCount;
  return {
    words: new Int32Array(buffer, 0, CONTROL_HEADER_BYTES / 4),
    parameters: new Float64Array(buffer, layout.parametersByteOffset, PARAMETER_COUNT),
    targets: new Float32Array(buffer, layout.targetsByteOffset, 3 * n),
    weights: new Float32Array(buffer, layout.weightsByteOffset, n),
    normalWeights: new Float32Array(buffer, layout.normalWeightsByteOffset, n),
    contractions: new Float32Array(buffer, layout.contractionsByteOffset, layout.muscleCount),
    headPose: new Float32Array(buffer, layout.headPoseByteOffset, HEAD_POSE_SLOTS),
  };
}

/** Fills a new control block: no muscle pulls (targets at rest, weights 0) and the given parameters. */
export function initControl(views: ControlViews, rest: Float32Array, parameters: SkinParameters): void {
  views.words.fill(0);
  views.targets.set(rest);
  views.weights.fill(0);
  views.normalWeights.fill(0);
  views.contractions.fill(0);
  views.headPose.fill(0);
  writeParameters(parameters, views.parameters);
}

export function writeParameters(p: SkinParameters, into: Float64Array): void {
  for (const name of PARAMETER_NAMES) into[PARAMETER_INDEX[name]] = p[name];
}

/** Reads parameters into an existing object (the solver side reuses one). */
export function readParameters(from: Float64Array, out: SkinParameters): SkinParameters {
  for (const name of PARAMETER_NAMES) out[name] = from[PARAMETER_INDEX[name]];
  return out;
}

// ---- output block --------------------------------------------------------------------------------------------

/** Frames published so far; a reader's copy is whole only if this did not change while it copied. */
export const OUTPUT_FRAME_SEQ = 0;
/** Index (0 or 1) of the slot last completed; the writer rewrites that slot only after its next publication. */
export const OUTPUT_COMPLETED_SLOT = 1;
const OUTPUT_HEADER_BYTES = 64;

// Slot header: words 0-7 are Int32, words 8-15 Float32, over the same memory.
const SLOT_FRAMES = 0;
const SLOT_SLEEPING = 1;
const SLOT_APPLIED_INPUT = 2;
const SLOT_CONSTRAINTS = 3; // five words, in CONSTRAINT_INDEX order
const SLOT_SOLVE_MS = 8;
const SLOT_BOX = 9; // min xyz, max xyz
const SLOT_WORKERS = 15;
const SLOT_HEADER_WORDS = 16;

/** Word offsets of a slot's arrays for a skin of `renderCount` render and `vertexCount` simulation vertices. */
export interface SlotLayout {
  renderCount: number;
  vertexCount: number;
  renderPositions: number;
  renderNormals: number;
  positions: number;
  normals: number;
  /** Length of one slot in 4-byte words. */
  words: number;
}

export function slotLayout(renderCount: number, vertexCount: number): SlotLayout {
  const renderPositions = SLOT_HEADER_WORDS;
  const renderNormals = renderPositions + 3 * renderCount;
  const positions = renderNormals + 3 * renderCount;
  const normals = positions + 3 * vertexCount;
  return { renderCount, vertexCount, renderPositions, renderNormals, positions, normals, words: align(normals + 3 * vertexCount, 4) };
}

export const outputByteLength = (layout: SlotLayout): number => OUTPUT_HEADER_BYTES + 8 * layout.words;
export const slotByteOffset = (layout: SlotLayout, slot: number): number => OUTPUT_HEADER_BYTES + 4 * slot * layout.words;
export const outputHeader = (buffer: ArrayBufferLike): Int32Array => new Int32Array(buffer, 0, OUTPUT_HEADER_BYTES / 4);

/** Views of one frame slot, made once per buffer so that copying frames allocates nothing. */
export interface FrameSlot {
  readonly buffer: ArrayBufferLike;
  /** The whole slot, to copy it in one call. */
  readonly all: Float32Array;
  readonly words: Int32Array;
  readonly values: Float32Array;
  /** xyz per render vertex (the mesh's own vertex order, seams included). */
  readonly renderPositions: Float32Array;
  readonly renderNormals: Float32Array;
  /** xyz per simulation vertex (topology order). */
  readonly positions: Float32Array;
  readonly normals: Float32Array;
}

export function frameSlot(buffer: ArrayBufferLike, byteOffset: number, layout: SlotLayout): FrameSlot {
  const all = new Float32Array(buffer, byteOffset, layout.words);
  const view = (start: number, length: number): Float32Array => all.subarray(start, start + length);
  return {
    buffer,
    all,
    words: new Int32Array(buffer, byteOffset, SLOT_HEADER_WORDS),
    values: view(0, SLOT_HEADER_WORDS),
    renderPositions: view(layout.renderPositions, 3 * layout.renderCount),
    renderNormals: view(layout.renderNormals, 3 * layout.renderCount),
    positions: view(layout.positions, 3 * layout.vertexCount),
    normals: view(layout.normals, 3 * layout.vertexCount),
  };
}

/** What the writer records beside each frame's vertices. */
export interface FrameHeader {
  frames: number;
  sleeping: boolean;
  appliedInput: number;
  solveMs: number;
  /** Threads that solved the frame (1, or 2 with a partner worker). */
  workers: number;
}

/** Where each constraint count sits among a slot's constraint words (and in a host's count array). */
export const CONSTRAINT_INDEX: Readonly<Record<keyof ConstraintCounts, number>> = {
  position: 0,
  length: 1,
  muscle: 2,
  bending: 3,
  collision: 4,
};
export const CONSTRAINT_KINDS = Object.keys(CONSTRAINT_INDEX) as (keyof ConstraintCounts)[];

export function writeFrameHeader(slot: FrameSlot, h: FrameHeader, constraints: Int32Array): void {
  slot.words[SLOT_FRAMES] = h.frames;
  slot.words[SLOT_SLEEPING] = h.sleeping ? 1 : 0;
  slot.words[SLOT_APPLIED_INPUT] = h.appliedInput;
  slot.words.set(constraints, SLOT_CONSTRAINTS);
  slot.values[SLOT_SOLVE_MS] = h.solveMs;
  slot.values[SLOT_WORKERS] = h.workers;
}

/** Frames the solver had solved when it wrote this slot. */
export const slotFrames = (slot: FrameSlot): number => slot.words[SLOT_FRAMES];
export const slotSleeping = (slot: FrameSlot): boolean => slot.words[SLOT_SLEEPING] === 1;
/** The input sequence number of the last input batch applied before this frame was solved. */
export const slotAppliedInput = (slot: FrameSlot): number => slot.words[SLOT_APPLIED_INPUT];
export const slotSolveMs = (slot: FrameSlot): number => slot.values[SLOT_SOLVE_MS];
export const slotWorkers = (slot: FrameSlot): number => slot.values[SLOT_WORKERS];

/** The constraint counts of this frame (a new object: for stats, not for per-frame code). */
export function slotConstraints(slot: FrameSlot): ConstraintCounts {
  const at = (kind: keyof ConstraintCounts): number => slot.words[SLOT_CONSTRAINTS + CONSTRAINT_INDEX[kind]];
  return { position: at('position'), length: at('length'), muscle: at('muscle'), bending: at('bending'), collision: at('collision') };
}

/** The bounds of the skin in this slot: min xyz, then max xyz. */
export function writeSlotBounds(slot: FrameSlot, positions: Float32Array): void {
  let x0 = Infinity,
    y0 = Infinity,
    z0 = Infinity,
    x1 = -Infinity,
    y1 = -Infinity,
    z1 = -Infinity;
  for (let i = 0; i < positions.length; i += 3) {
    const x = positions[i],
      y = positions[i + 1],
      z = positions[i + 2];
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
    if (z < z0) z0 = z;
    if (z > z1) z1 = z;
  }
  const v = slot.values;
  v[SLOT_BOX] = x0;
  v[SLOT_BOX + 1] = y0;
  v[SLOT_BOX + 2] = z0;
  v[SLOT_BOX + 3] = x1;
  v[SLOT_BOX + 4] = y1;
  v[SLOT_BOX + 5] = z1;
}

export function readSlotBounds(slot: FrameSlot, out: Float32Array): void {
  for (let k = 0; k < 6; k++) out[k] = slot.values[SLOT_BOX + k];
}

function align(n: number, to: number): number {
  return Math.ceil(n / to) * to;
}
