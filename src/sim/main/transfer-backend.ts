import type { SolverBackend } from './backend';
import type { ChangedInputs } from './input-staging';
import { frameSlot, type ControlViews, type FrameSlot, type SlotLayout } from '../shared/layout';
import type { RigEdit, SolverClock } from '../shared/protocol';
import type { WorkerConnection } from './worker-connection';

/**
 * `transfer` mode, main thread side (pages that are not cross-origin isolated have no SharedArrayBuffer): input
 * batches go to the worker as messages, and each frame arrives in a buffer that goes back once a newer one is here.
 */
export class TransferBackend implements SolverBackend {
  readonly mode = 'transfer';
  private current: FrameSlot;

  constructor(
    private readonly connection: WorkerConnection,
    private readonly control: ControlViews,
    firstFrame: ArrayBuffer,
    private readonly layout: SlotLayout,
  ) {
    this.current = frameSlot(firstFrame, 0, layout);
    connection.onFrame = (buffer) => this.receive(buffer);
  }

  latest(): FrameSlot {
    return this.current;
  }

  publish(seq: number, { muscles, parameters, contractions }: ChangedInputs): void {
    const targets = muscles ? this.control.targets.slice() : undefined;
    const weights = muscles ? this.control.weights.slice() : undefined;
    const normalWeights = muscles ? this.control.normalWeights.slice() : undefined;
    const params = parameters ? this.control.parameters.slice() : undefined;
    const muscleContractions = contractions ? this.control.contractions.slice() : undefined;
    const headPose = contractions ? this.control.headPose.slice() : undefined;
    const transfer = [
      targets?.buffer,
      weights?.buffer,
      normalWeights?.buffer,
      params?.buffer,
      muscleContractions?.buffer,
      headPose?.buffer,
    ].filter((b): b is ArrayBuffer => b !== undefined);
    this.connection.post(
      { type: 'inputs', seq, targets, weights, normalWeights, parameters: params, contractions: muscleContractions, headPose },
      transfer,
    );
  }

  editRig(revision: number, edit: RigEdit): void {
    this.connection.post({ type: 'rig', revision, edit });
  }

  advance(): void {}

  setClock(clock: SolverClock): void {
    this.connection.post({ type: 'clock', clock });
  }

  run(seq: number, frames: number): Promise<number> {
    return this.connection.run(seq, frames);
  }

  failure(): Error | undefined {
    return this.connection.failure();
  }

  dispose(): void {
    this.connection.dispose();
  }

  private receive(buffer: ArrayBuffer): void {
    const previous = this.current.buffer as ArrayBuffer;
    this.current = frameSlot(buffer, 0, this.layout);
    this.connection.post({ type: 'frame-buffer', buffer: previous }, [previous]);
  }
}
