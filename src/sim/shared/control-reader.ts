import {
  CONTROL_CONTRACTION_REVISION,
  CONTROL_INPUT_SEQ,
  CONTROL_MUSCLE_REVISION,
  CONTROL_PARAMETER_REVISION,
  CONTROL_RIG_REVISION,
  PARAMETER_COUNT,
  type ControlViews,
} from './layout';
import type { SolverHost } from './solver-host';

/** Atomics.waitAsync (ES2024), typed here because the project's lib is ES2022. */
type WaitAsync = (
  typed: Int32Array,
  index: number,
  value: number,
  timeout?: number,
) => { async: true; value: Promise<string> } | { async: false; value: string };

/** How often a solver without Atomics.waitAsync looks for new inputs while it sleeps. */
const POLL_MS = 4;

/**
 * Reads published input batches from a control block into a solver host, between frames. The main thread may be
 * writing the next batch meanwhile, so the batch is copied to scratch first and applied only if the input sequence
 * number did not move during the copy (a seqlock); otherwise it is read again on the next turn.
 */
export class ControlReader {
  private appliedSeq = 0;
  private muscleRevision = 0;
  private parameterRevision = 0;
  private contractionRevision = 0;
  private readonly contractions: Float32Array;
  private readonly headPose: Float32Array;
  private readonly targets: Float32Array;
  private readonly weights: Float32Array;
  private readonly normalWeights: Float32Array;
  private readonly parameters = new Float64Array(PARAMETER_COUNT);

  constructor(
    private readonly control: ControlViews,
    private readonly host: SolverHost,
  ) {
    this.targets = new Float32Array(control.targets.length);
    this.weights = new Float32Array(control.weights.length);
    this.normalWeights = new Float32Array(control.normalWeights.length);
    this.contractions = new Float32Array(control.contractions.length);
    this.headPose = new Float32Array(control.headPose.length);
  }

  /** True if a batch was published that is not applied yet. */
  hasPending(): boolean {
    return this.pendingAt(Atomics.load(this.control.words, CONTROL_INPUT_SEQ));
  }

  /** True if input sequence number `seq` is a published batch that is not applied yet. */
  private pendingAt(seq: number): boolean {
    return (seq & 1) === 0 && seq !== this.appliedSeq;
  }

  /**
   * Calls `then` once the input sequence number moves (at once if a batch is already waiting). Uses Atomics.waitAsync
   * so the worker's event loop stays free; where that is missing, it polls.
   */
  waitForInput(then: () => void): void {
    // One load for the check and the wait: with two, a batch published between them was never waited for (the wait
    // was on its own number), and the skin slept through it until the next input.
    const words = this.control.words;
    const seq = Atomics.load(words, CONTROL_INPUT_SEQ);
    if (this.pendingAt(seq)) {
      then();
      return;
    }
    const waitAsync = (Atomics as unknown as { waitAsync?: WaitAsync }).waitAsync;
    if (!waitAsync) {
      setTimeout(then, POLL_MS);
      return;
    }
    const result = waitAsync(words, CONTROL_INPUT_SEQ, seq);
    if (result.async) void result.value.then(then);
    else then();
  }

  /** Applies the newest published batch, if there is one and it was read whole. Returns whether it applied one. */
  poll(): boolean {
    const words = this.control.words;
    const seq = Atomics.load(words, CONTROL_INPUT_SEQ);
    if ((seq & 1) === 1 || seq === this.appliedSeq) return false;
    // Written for a rig edit whose message has not arrived yet: wait for it (the worker's next turns poll again).
    if (Atomics.load(words, CONTROL_RIG_REVISION) !== this.host.rigRevision) return false;
    const muscleRevision = Atomics.load(words, CONTROL_MUSCLE_REVISION);
    const parameterRevision = Atomics.load(words, CONTROL_PARAMETER_REVISION);
    const contractionRevision = Atomics.load(words, CONTROL_CONTRACTION_REVISION);
    const contractions = contractionRevision !== this.contractionRevision;
    const muscles = muscleRevision !== this.muscleRevision;
    const parameters = parameterRevision !== this.parameterRevision;
    if (muscles) {
      this.targets.set(this.control.targets);
      this.weights.set(this.control.weights);
      this.normalWeights.set(this.control.normalWeights);
    }
    if (parameters) this.parameters.set(this.control.parameters);
    if (contractions) {
      this.contractions.set(this.control.contractions);
      this.headPose.set(this.control.headPose);
    }
    if (Atomics.load(words, CONTROL_INPUT_SEQ) !== seq) return false;
    this.appliedSeq = seq;
    this.muscleRevision = muscleRevision;
    this.parameterRevision = parameterRevision;
    this.contractionRevision = contractionRevision;
    const muscleInput = muscles ? { targets: this.targets, weights: this.weights, normalWeights: this.normalWeights } : null;
    this.host.apply(
      seq,
      muscleInput,
      parameters ? this.parameters : null,
      contractions ? this.contractions : null,
      contractions ? this.headPose : null,
    );
    return true;
  }
}
