import {
  OUTPUT_COMPLETED_SLOT,
  OUTPUT_FRAME_SEQ,
  frameSlot,
  outputByteLength,
  outputHeader,
  slotByteOffset,
  type FrameSlot,
  type SlotLayout,
} from '../shared/layout';
import type { SolverHost } from '../shared/solver-host';

/**
 * The worker's side of the shared output block: writes each frame into the slot the reader is not pointed at, then
 * points it there and bumps the frame sequence number. A reader copying the completed slot is safe until the next
 * publication, because only the one after it writes that slot again.
 */
export class SharedOutput {
  readonly buffer: SharedArrayBuffer;
  private readonly header: Int32Array;
  private readonly slots: [FrameSlot, FrameSlot];

  constructor(layout: SlotLayout) {
    this.buffer = new SharedArrayBuffer(outputByteLength(layout));
    this.header = outputHeader(this.buffer);
    this.slots = [frameSlot(this.buffer, slotByteOffset(layout, 0), layout), frameSlot(this.buffer, slotByteOffset(layout, 1), layout)];
    // The first publication then writes slot 0.
    Atomics.store(this.header, OUTPUT_COMPLETED_SLOT, 1);
  }

  /** Writes the host's current frame and publishes it. Allocates nothing. */
  publish(host: SolverHost): void {
    const next = 1 - Atomics.load(this.header, OUTPUT_COMPLETED_SLOT);
    host.writeFrame(this.slots[next]);
    Atomics.store(this.header, OUTPUT_COMPLETED_SLOT, next);
    Atomics.add(this.header, OUTPUT_FRAME_SEQ, 1);
    Atomics.notify(this.header, OUTPUT_FRAME_SEQ);
  }
}
