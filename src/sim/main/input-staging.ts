import type { HeadPose } from '../../core/expression/head-pose';
import { clamp01 } from '../../core/math3';
import { checkMuscleTargets, clearMuscleInputs, writeMuscleTargets } from '../../core/solver/muscle-inputs';
import { checkOptions } from '../../core/check';
import { SKIN_DEFAULTS, SKIN_INTEGERS, SKIN_PARAMETERS, SKIN_RANGES, type SkinParameters } from '../../core/solver/skin-parameters';
import {
  CONTROL_CONTRACTION_REVISION,
  CONTROL_INPUT_SEQ,
  CONTROL_MUSCLE_REVISION,
  CONTROL_PARAMETER_REVISION,
  CONTROL_RIG_REVISION,
  readParameters,
  writeHeadPose,
  writeParameters,
  type ControlViews,
} from '../shared/layout';

/** Which parts of the inputs a published batch changed. */
export interface ChangedInputs {
  /** Muscle targets and weights set directly. */
  muscles: boolean;
  parameters: boolean;
  /** The rig's muscle contractions or the head pose. */
  contractions: boolean;
}

/** Called once per published batch: its sequence number and which parts changed. */
export type PublishInputs = (seq: number, changed: ChangedInputs) => void;

/**
 * The main thread's side of the control block: checks every input at the boundary (a bad one throws and changes
 * nothing), writes it, and publishes all inputs given in one task as one batch, so that in every mode they reach
 * the solver together, before the same frame.
 */
export class InputStaging {
  private open = false;
  private musclesChanged = false;
  private parametersChanged = false;
  private contractionsChanged = false;
  private readonly current: SkinParameters;
  private readonly flushSoon = (): void => this.flush();

  constructor(
    private readonly control: ControlViews,
    private readonly rest: Float32Array,
    private readonly onPublish: PublishInputs,
    /** Muscles of the rig: `setContractions` takes one contraction each (the block may hold more). */
    private muscleCount = control.contractions.length,
  ) {
    this.current = readParameters(control.parameters, { ...SKIN_DEFAULTS });
  }

  /**
   * Counts a rig edit into the batch being written: the solver applies the batch only once it has edit `revision`.
   * A new muscle count (muscles added or removed) takes effect for the contractions set from here on.
   */
  touchRig(revision: number, muscleCount = this.muscleCount): void {
    if (muscleCount > this.control.contractions.length) {
      throw new Error(`the rig may have at most ${this.control.contractions.length} muscles, got ${muscleCount}`);
    }
    this.begin();
    this.muscleCount = muscleCount;
    Atomics.store(this.control.words, CONTROL_RIG_REVISION, revision);
  }

  /**
   * Sets muscle targets (xyz per vertex) for some simulation vertices, all with one weight along the surface and one
   * along the normal (both 0 release them; see SolverBuffers).
   */
  setMuscleTargets(vertices: ArrayLike<number>, targets: ArrayLike<number>, weight = 1, normalWeight = weight): void {
    checkMuscleTargets(this.control.weights.length, vertices, targets, weight, normalWeight);
    this.begin();
    writeMuscleTargets(this.control, vertices, targets, weight, normalWeight);
    this.touchMuscles();
  }

  /** Releases every muscle pull. */
  clearMuscleTargets(): void {
    this.begin();
    clearMuscleInputs(this.control, this.rest);
    this.touchMuscles();
  }

  /** Sets the contraction (0..1, clamped) of every rig muscle, in the rig's order; a non-finite one throws by index. */
  setContractions(values: ArrayLike<number>): void {
    const C = this.control.contractions;
    const count = this.muscleCount;
    if (!isArrayLike(values) || values.length !== count) {
      throw new Error(
        `setContractions: expected ${count} contractions (one per rig muscle), got ${isArrayLike(values) ? values.length : values}`,
      );
    }
    for (let i = 0; i < values.length; i++) {
      if (typeof values[i] !== 'number' || !Number.isFinite(values[i]))
        throw new Error(`setContractions: contraction ${i} is not a finite number: ${values[i]}`);
    }
    this.begin();
    for (let i = 0; i < values.length; i++) C[i] = clamp01(values[i]);
    C.fill(0, count);
    Atomics.add(this.control.words, CONTROL_CONTRACTION_REVISION, 1);
    this.contractionsChanged = true;
  }

  /**
   * Sets the head pose (see head-pose.ts) the neck is solved for; published with the contractions. Throws, changing
   * nothing, on a value that is not finite.
   */
  setHeadPose(pose: HeadPose): void {
    for (const key of ['yaw', 'pitch', 'roll', 'forward'] as const) {
      if (typeof pose[key] !== 'number' || !Number.isFinite(pose[key]))
        throw new Error(`setHeadPose: ${key} is not a finite number: ${pose[key]}`);
    }
    this.begin();
    writeHeadPose(pose, this.control.headPose);
    Atomics.add(this.control.words, CONTROL_CONTRACTION_REVISION, 1);
    this.contractionsChanged = true;
  }

  /** Changes some skin parameters; throws, changing nothing, if one is unknown or not a finite number in range. */
  setParameters(partial: Partial<SkinParameters>): void {
    // The current parameters passed these checks already: only the given ones need them.
    const given = checkOptions<SkinParameters>(SKIN_PARAMETERS, partial, SKIN_DEFAULTS, { ranges: SKIN_RANGES, integers: SKIN_INTEGERS });
    const next = { ...this.current, ...given };
    this.begin();
    Object.assign(this.current, next);
    writeParameters(this.current, this.control.parameters);
    Atomics.add(this.control.words, CONTROL_PARAMETER_REVISION, 1);
    this.parametersChanged = true;
  }

  /** The parameters as last set (a copy). */
  parameters(): SkinParameters {
    return { ...this.current };
  }

  /** The sequence number of the newest published batch. */
  publishedSeq(): number {
    const seq = Atomics.load(this.control.words, CONTROL_INPUT_SEQ);
    return this.open ? seq - 1 : seq;
  }

  /** Publishes the batch being written now instead of at the end of the task (settle() waits for every input). */
  flush(): void {
    if (!this.open) return;
    this.open = false;
    const seq = Atomics.add(this.control.words, CONTROL_INPUT_SEQ, 1) + 1;
    Atomics.notify(this.control.words, CONTROL_INPUT_SEQ);
    const changed = { muscles: this.musclesChanged, parameters: this.parametersChanged, contractions: this.contractionsChanged };
    this.musclesChanged = false;
    this.parametersChanged = false;
    this.contractionsChanged = false;
    this.onPublish(seq, changed);
  }

  /** Opens a batch: the odd sequence number tells the solver not to read the inputs until the batch is published. */
  private begin(): void {
    if (this.open) return;
    this.open = true;
    Atomics.add(this.control.words, CONTROL_INPUT_SEQ, 1);
    queueMicrotask(this.flushSoon);
  }

  private touchMuscles(): void {
    Atomics.add(this.control.words, CONTROL_MUSCLE_REVISION, 1);
    this.musclesChanged = true;
  }
}

function isArrayLike(a: unknown): a is ArrayLike<number> {
  return Array.isArray(a) || ArrayBuffer.isView(a);
}
