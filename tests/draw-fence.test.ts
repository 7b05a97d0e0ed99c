import { describe, expect, it } from 'vitest';
import { DrawFence, FENCE_GIVE_UP_MS, QUIET_AFTER_SLOW_DRAW, QUIET_MAX_MS, type FenceContext } from '../src/render/draw-fence';

/** A context whose GPU finishes the fenced work when the test says so; counts the fences alive. */
class FakeGPU implements FenceContext {
  readonly SYNC_GPU_COMMANDS_COMPLETE = 0x9117;
  readonly SYNC_STATUS = 0x9114;
  readonly SIGNALED = 0x9119;
  readonly UNSIGNALED = 0x9118;
  private readonly done = new Set<object>();
  live = 0;
  flushes = 0;
  private last: object | null = null;

  fenceSync(): WebGLSync {
    this.live++;
    this.last = {};
    return this.last as WebGLSync;
  }
  getSyncParameter(sync: WebGLSync): number {
    return this.done.has(sync) ? this.SIGNALED : this.UNSIGNALED;
  }
  deleteSync(): void {
    this.live--;
  }
  flush(): void {
    this.flushes++;
  }
  /** The GPU finishes the last fenced draw. */
  finish(): void {
    if (this.last) this.done.add(this.last);
  }
}

const SLOW_MS = 50;

describe('the render loop waiting for the GPU (DrawFence)', () => {
  it('holds the loop until the GPU has done the last draw, then lets it draw at once after a fast draw', () => {
    const gpu = new FakeGPU();
    const fence = new DrawFence(gpu, SLOW_MS);
    expect(fence.busy(0, true)).toBe(false);
    fence.drawn(0, true);
    expect(gpu.flushes).toBe(1);
    expect(fence.busy(16, true)).toBe(true);
    gpu.finish();
    // Done within the slow bound: no rest, even while a solver works.
    expect(fence.busy(33, true)).toBe(false);
    expect(gpu.live).toBe(0);
  });

  it('rests after a slow draw made while a solver works, for QUIET_AFTER_SLOW_DRAW times the draw', () => {
    const gpu = new FakeGPU();
    const fence = new DrawFence(gpu, SLOW_MS);
    fence.drawn(1_000, true);
    expect(fence.busy(1_100, true)).toBe(true);
    gpu.finish();
    // Signalled by the frame at 1,150 ms: the draw took 150 ms.
    const restUntil = 1_150 + 150 * QUIET_AFTER_SLOW_DRAW;
    expect(fence.busy(1_150, true)).toBe(true);
    expect(fence.busy(restUntil - 1, true)).toBe(true);
    expect(fence.busy(restUntil, true)).toBe(false);
  });

  it('rests at most QUIET_MAX_MS after a draw of over a second (pipelines made at a first motion)', () => {
    const gpu = new FakeGPU();
    const fence = new DrawFence(gpu, SLOW_MS);
    fence.drawn(0, true);
    for (let t = 16; t < 1_200; t += 16) expect(fence.busy(t, true)).toBe(true);
    gpu.finish();
    expect(fence.busy(1_200, true)).toBe(true);
    expect(fence.busy(1_200 + QUIET_MAX_MS - 1, true)).toBe(true);
    expect(fence.busy(1_200 + QUIET_MAX_MS, true)).toBe(false);
  });

  it('does not rest when the fence was not read for a while (the view hidden, or a recorder holding the loop)', () => {
    const gpu = new FakeGPU();
    const fence = new DrawFence(gpu, SLOW_MS);
    fence.drawn(0, true);
    expect(fence.busy(16, true)).toBe(true);
    gpu.finish();
    // Read again 5 s later: the draw did not take 5 s.
    expect(fence.busy(5_016, true)).toBe(false);
  });

  it("ends the rest with the solver's last frame, which is drawn at once", () => {
    const gpu = new FakeGPU();
    const fence = new DrawFence(gpu, SLOW_MS);
    fence.drawn(0, true);
    expect(fence.busy(100, true)).toBe(true);
    gpu.finish();
    expect(fence.busy(150, true)).toBe(true);
    expect(fence.busy(166, false)).toBe(false);
  });

  it('never holds a loop with no solver at work, and does not rest after its slow draws', () => {
    const gpu = new FakeGPU();
    const fence = new DrawFence(gpu, SLOW_MS);
    fence.drawn(0, false);
    // A camera drag: the GPU still at the last draw, the next drawn all the same.
    expect(fence.busy(16, false)).toBe(false);
    gpu.finish();
    expect(fence.busy(150, true)).toBe(false);
  });

  it('gives up on a fence that never signals (a lost context) after FENCE_GIVE_UP_MS', () => {
    const gpu = new FakeGPU();
    const fence = new DrawFence(gpu, SLOW_MS);
    fence.drawn(0, true);
    expect(fence.busy(FENCE_GIVE_UP_MS - 1, true)).toBe(true);
    expect(fence.busy(FENCE_GIVE_UP_MS, true)).toBe(false);
    expect(gpu.live).toBe(0);
  });

  it('keeps one fence at a time and frees it on dispose', () => {
    const gpu = new FakeGPU();
    const fence = new DrawFence(gpu, SLOW_MS);
    fence.drawn(0, false);
    fence.drawn(10, false);
    expect(gpu.live).toBe(1);
    fence.dispose();
    expect(gpu.live).toBe(0);
  });
});
