import type { SolverBackend } from './backend';
import {
  OUTPUT_COMPLETED_SLOT,
  OUTPUT_FRAME_SEQ,
  frameSlot,
  outputHeader,
  slotByteOffset,
  type FrameSlot,
  type SlotLayout,
} from '../shared/layout';
import type { RigEdit, SolverClock } from '../shared/protocol';
import type { WorkerConnection } from './worker-connection';

/** Tries to copy a frame this many times when the worker keeps publishing during the copy, then keeps the last. */
const COPY_ATTEMPTS = 3;

/**
 * `shared` mode, main thread side: the worker reads inputs from the shared control block by itself; frames are read
 * from the shared output block with a seqlock into one of two private copies, so a torn copy never replaces a whole
 * one.
 */
export class SharedBackend implements SolverBackend {
  readonly mode = 'shared';
  private readonly header: Int32Array;
  private readonly slots: [FrameSlot, FrameSlot];
  private readonly copies: [FrameSlot, FrameSlot];
  private current = 0;
  private copiedSeq = -1;

  constructor(
    private readonly connection: WorkerConnection,
    output: SharedArrayBuffer,
    layout: SlotLayout,
  ) {
    this.header = outputHeader(output);
    this.slots = [frameSlot(output, slotByteOffset(layout, 0), layout), frameSlot(output, slotByteOffset(layout, 1), layout)];
    const copy = (): FrameSlot => frameSlot(new ArrayBuffer(4 * layout.words), 0, layout);
    this.copies = [copy(), copy()];
    // The worker sleeps on its rest shape when it reports ready, so this copies at once; never start from zeros.
    while (this.copiedSeq < 0) this.copyNewest();
  }

  latest(): FrameSlot {
    if (Atomics.load(this.header, OUTPUT_FRAME_SEQ) !== this.copiedSeq) this.copyNewest();
    return this.copies[this.current];
  }

  publish(): void {
    // The worker watches the control block's input sequence number itself.
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

  private copyNewest(): void {
    for (let attempt = 0; attempt < COPY_ATTEMPTS; attempt++) {
      const seq = Atomics.load(this.header, OUTPUT_FRAME_SEQ);
      const completed = Atomics.load(this.header, OUTPUT_COMPLETED_SLOT);
      const spare = this.copies[1 - this.current];
      spare.all.set(this.slots[completed].all);
      if (Atomics.load(this.header, OUTPUT_FRAME_SEQ) === seq) {
        this.current = 1 - this.current;
        this.copiedSeq = seq;
        return;
      }
    }
  }
}
