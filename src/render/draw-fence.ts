/** How long the GPU may take over a draw before the view takes its fence for lost (a lost context never signals). */
export const FENCE_GIVE_UP_MS = 3_000;

/**
 * After a slow draw made while a solver works, the view waits this many times the draw's time before it draws
 * again, so that the GPU takes at most a quarter of the time. In software WebGL the GPU's threads share the cores with
 * the solver's worker: the high head's happiness came within 2 % in the page after 1.58 to 1.77 s at the median with
 * three times, 1.33 to 1.78 with twice, 1.46 to 1.58 with once, 1.70 to 2.64 with the fence alone and 1.66 to 1.89
 * drawing whenever something was new (docs/page-notes.md). Three keeps about two frames a second of motion.
 */
export const QUIET_AFTER_SLOW_DRAW = 3;

/**
 * The longest rest (ms): the first draw of a head's motion can take the GPU over a second (SwiftShader making
 * pipelines), and the motion should still show within about a second.
 */
export const QUIET_MAX_MS = 1_000;

/**
 * A fence is read at every animation frame while the view is in view; read after a longer gap (the view was hidden, or
 * a recorder held the loop), the time it took says nothing of the draw, and no rest follows.
 */
const READ_GAP_MS = 500;

/** The parts of a WebGL2 context a DrawFence uses. */
export type FenceContext = Pick<
  WebGL2RenderingContext,
  'fenceSync' | 'getSyncParameter' | 'deleteSync' | 'flush' | 'SYNC_GPU_COMMANDS_COMPLETE' | 'SYNC_STATUS' | 'SIGNALED'
>;

/**
 * Tells a view's render loop whether the GPU is still at the loop's last draw, or resting after a slow one. A draw made
 * while the GPU has not done the one before waits in its queue: in software WebGL, where a draw of the high head
 * takes 100 to 300 ms of the cores the solver uses, the page queued up to three motion frames and showed each 0.4 to
 * 0.8 s after it drew it. A WebGL fence after each draw says when the GPU is done, at the first animation frame after.
 * On a GPU that keeps up, the fence has signalled by the next animation frame and nothing changes.
 */
export class DrawFence {
  private sync: WebGLSync | null = null;
  /** When the fenced draw was made, and whether a solver was at work then. */
  private drawnAt = 0;
  private solving = false;
  /** The loop draws nothing before this time (ms): the rest after a slow draw. */
  private quietUntil = 0;
  /** When `busy` was last asked (ms). */
  private readAt = -Infinity;

  /** `slowMs`: a draw the GPU takes longer over is slow. */
  constructor(
    private readonly gl: FenceContext,
    private readonly slowMs: number,
  ) {}

  /** Marks the draw just made at animation-frame time `now`; `solving` says a solver still works on what it showed. */
  drawn(now: number, solving: boolean): void {
    if (this.sync) this.gl.deleteSync(this.sync);
    this.sync = this.gl.fenceSync(this.gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    // Sent now, not at the task's end, so that the GPU starts on it and the fence can signal.
    this.gl.flush();
    this.drawnAt = now;
    this.solving = solving;
  }

  /**
   * Whether the loop should not draw at animation-frame time `now` while a solver works (`solving`): the GPU is at the
   * last draw, or resting after it. With no solver at work (a camera drag, the eyes, the solver's last frame) it never
   * is: each change is drawn at the next animation frame, as the rest of the page expects, and the solver's last frame
   * is shown at once.
   */
  busy(now: number, solving: boolean): boolean {
    const gl = this.gl;
    const continuous = now - this.readAt <= READ_GAP_MS;
    this.readAt = now;
    if (this.sync) {
      const took = now - this.drawnAt;
      const signalled = gl.getSyncParameter(this.sync, gl.SYNC_STATUS) === gl.SIGNALED;
      if (!signalled && took < FENCE_GIVE_UP_MS) return solving;
      gl.deleteSync(this.sync);
      this.sync = null;
      if (signalled && continuous && this.solving && took > this.slowMs) {
        this.quietUntil = now + Math.min(QUIET_MAX_MS, took * QUIET_AFTER_SLOW_DRAW);
      }
    }
    return solving && now < this.quietUntil;
  }

  /** Frees the fence. */
  dispose(): void {
    if (this.sync) this.gl.deleteSync(this.sync);
    this.sync = null;
  }
}
