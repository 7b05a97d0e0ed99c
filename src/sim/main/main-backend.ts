import type { SolverBackend } from './backend';
import { ControlReader } from '../shared/control-reader';
import { frameSlot, type ControlViews, type FrameSlot, type SlotLayout } from '../shared/layout';
import type { RigEdit, SolverClock } from '../shared/protocol';
import type { SolverHost } from '../shared/solver-host';

/**
 * `main` mode: the same solver host on the main thread, stepped from the render loop within a time budget. Inputs go
 * through a control block as in `shared` mode, so batches reach the solver at the same point.
 */
export class MainBackend implements SolverBackend {
  readonly mode = 'main';
  private readonly reader: ControlReader;
  private readonly slot: FrameSlot;
  private stepped = false;

  constructor(
    private readonly host: SolverHost,
    control: ControlViews,
    layout: SlotLayout,
  ) {
    this.reader = new ControlReader(control, host);
    this.slot = frameSlot(new ArrayBuffer(4 * layout.words), 0, layout);
    host.writeFrame(this.slot);
  }

  latest(): FrameSlot {
    return this.slot;
  }

  publish(): void {
    // advance() reads the control block.
  }

  editRig(revision: number, edit: RigEdit): void {
    this.host.editRig(revision, edit);
  }

  /** Applies new inputs, then solves frames until the budget is spent or the skin sleeps; at least one if awake. */
  advance(budgetMs: number): void {
    if (this.stepped) return;
    this.reader.poll();
    const start = performance.now();
    let solved = false;
    while (this.host.step()) {
      solved = true;
      if (performance.now() - start >= budgetMs) break;
    }
    if (solved) this.host.writeFrame(this.slot);
  }

  setClock(clock: SolverClock): void {
    this.stepped = clock === 'stepped';
  }

  /** Solves on this thread at once: the inputs were published just before, in this same task. */
  run(seq: number, frames: number): Promise<number> {
    this.reader.poll();
    if (this.host.appliedInput < seq) return Promise.reject(new Error(`run: input batch ${seq} was not published whole`));
    if (this.host.run(frames) > 0) this.host.writeFrame(this.slot);
    return Promise.resolve(this.host.solver.frames);
  }

  failure(): Error | undefined {
    return undefined;
  }

  dispose(): void {}
}
