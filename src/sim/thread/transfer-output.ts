import { frameSlot, type FrameSlot, type SlotLayout } from '../shared/layout';
import type { SolverHost } from '../shared/solver-host';

/**
 * The worker's side of `transfer` mode: two slot buffers go back and forth. A frame solved while both are on the
 * main thread is written as soon as one comes back, so the newest shape (and the final, sleeping one) always arrives.
 */
export class TransferOutput {
  private readonly free: FrameSlot[] = [];
  private waiting = false;
  /** Called once the frame waiting for a slot is sent. */
  private sent: (() => void) | undefined;

  constructor(
    private readonly layout: SlotLayout,
    private readonly host: SolverHost,
    private readonly post: (buffer: ArrayBuffer) => void,
  ) {
    for (let i = 0; i < 2; i++) this.free.push(frameSlot(new ArrayBuffer(4 * layout.words), 0, layout));
  }

  /** Writes the current frame into a free slot and returns its buffer, for the ready message. */
  first(): ArrayBuffer {
    const slot = this.free.pop()!;
    this.host.writeFrame(slot);
    return slot.buffer as ArrayBuffer;
  }

  /** Sends the current frame, or sends it once a slot comes back; then calls `sent`, if given. */
  publish(sent?: () => void): void {
    if (sent) this.sent = sent;
    const slot = this.free.pop();
    if (!slot) {
      this.waiting = true;
      return;
    }
    this.waiting = false;
    this.host.writeFrame(slot);
    this.post(slot.buffer as ArrayBuffer);
    const then = this.sent;
    this.sent = undefined;
    then?.();
  }

  /** Takes back a slot the main thread is done with. */
  giveBack(buffer: ArrayBuffer): void {
    this.free.push(frameSlot(buffer, 0, this.layout));
    if (this.waiting) this.publish();
  }
}
