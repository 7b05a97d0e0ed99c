/** Messages between SkinSimulation (main thread) and the skin worker. */
import type { Collider } from '../../core/solver/colliders';
import type { MouthCorners } from '../../core/solver/lip-contact';
import type { Muscle } from '../../core/rig/rig-types';
import type { SkinParameters } from '../../core/solver/skin-parameters';

/** How the solver runs: in a worker on shared memory, in a worker with transferred buffers, or on the main thread. */
export type SolverMode = 'shared' | 'transfer' | 'main';

/** Main to worker, first: the skin's render mesh, its colliders and the starting parameters. */
export interface InitMessage {
  type: 'init';
  /** The modes a worker runs in. */
  mode: Exclude<SolverMode, 'main'>;
  renderPositions: Float32Array;
  indices: Uint16Array | Uint32Array;
  colliders: Collider[];
  /** The mouth's corners, for the lips' contact (see LipContact). */
  mouth?: MouthCorners;
  parameters: SkinParameters;
  muscles: Muscle[];
  /** Threads that solve: 2 adds a partner worker (`shared` mode only). */
  workers: 1 | 2;
}

/**
 * A change of the rig's muscles: one muscle replaced in place (an editor dragging it; only its candidates and the
 * muscle targets are recomputed), or the whole list (muscles added, removed or reordered; the contractions of the
 * new list follow in the next input batch).
 */
export type RigEdit = { index: number; muscle: Muscle } | { muscles: Muscle[] };

/** Main to worker: a rig edit; `revision` counts them, and input batches name the revision they were written for. */
export interface RigMessage {
  type: 'rig';
  revision: number;
  edit: RigEdit;
}

/** Worker to main, once the topology is built and the first frame (the rest shape) is written. */
export interface ReadyMessage {
  type: 'ready';
  vertexCount: number;
  edgeCount: number;
  rest: Float32Array;
  triangles: Uint32Array;
  /** `shared` mode: the control and output blocks. */
  control?: SharedArrayBuffer;
  output?: SharedArrayBuffer;
  /** `transfer` mode: the first frame's slot. */
  frame?: ArrayBuffer;
}

/** Main to worker (`transfer` mode): one published input batch; absent parts did not change. */
export interface InputsMessage {
  type: 'inputs';
  seq: number;
  targets?: Float32Array;
  weights?: Float32Array;
  normalWeights?: Float32Array;
  parameters?: Float64Array;
  contractions?: Float32Array;
  /** The head pose (see HEAD_POSE_SLOTS in layout.ts), sent with the contractions. */
  headPose?: Float32Array;
}

/** Worker to main (`transfer` mode): a solved frame's slot. Main to worker: a slot it no longer needs. */
export interface FrameMessage {
  type: 'frame' | 'frame-buffer';
  buffer: ArrayBuffer;
}

/**
 * Main to worker: how the solver's frames are paced. `free` (the default) solves whenever the skin is awake;
 * `stepped` solves only the frames a `run` asks for, so a recorder gets the same frames however fast the machine is.
 */
export interface ClockMessage {
  type: 'clock';
  clock: SolverClock;
}

/** How the solver's frames are paced (see ClockMessage). */
export type SolverClock = 'free' | 'stepped';

/**
 * Main to worker: once input batch `seq` is applied, solve `frames` frames (fewer if the skin falls asleep, which
 * changes nothing more), publish the last and answer with a `ran` message of the same `id`.
 */
export interface RunMessage {
  type: 'run';
  id: number;
  seq: number;
  frames: number;
}

/** Worker to main: run `id` is done and its last frame published; `frames` counts the frames solved since creation. */
export interface RanMessage {
  type: 'ran';
  id: number;
  frames: number;
}

/** Worker to main: the solver failed. */
export interface ErrorMessage {
  type: 'error';
  message: string;
}

export type ToWorker = InitMessage | InputsMessage | FrameMessage | RigMessage | ClockMessage | RunMessage;
export type FromWorker = ReadyMessage | FrameMessage | ErrorMessage | RanMessage;
