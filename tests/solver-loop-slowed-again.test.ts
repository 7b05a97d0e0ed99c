import { describe, expect, it, vi } from 'vitest';
import { Relaxation } from '../src/core/solver/relaxation';
import { LOOP_WINDOW } from '../src/core/solver/solver-schedule';
import { loadHeadSimulation, MAX_SETTLE_FRAMES, settleExpression } from './fixtures/head-simulation';

// A loop that the first slowing does not stop (anger's on the medium head: 64 vertices slowed at frame 60 go on
// circling) is found again a window later, by the two steps since the slowing, not two windows later, when the
// windows the stall test weighs no longer hold moves from before it. docs/solver-notes.md, "A sliding loop window".
describe('a loop that survives its slowing', () => {
  it('is slowed again one window after the first slowing, and the skin sleeps', async () => {
    const sim = await loadHeadSimulation('medium');
    const slowings: number[] = [];
    const breakLoops = Relaxation.prototype.breakLoops;
    const spy = vi.spyOn(Relaxation.prototype, 'breakLoops').mockImplementation(function (this: Relaxation, V, count, t) {
      const before = Float32Array.from(this.share);
      breakLoops.call(this, V, count, t);
      if (this.share.some((s, i) => s < before[i])) slowings.push(this.motionFrames);
    });
    try {
      const r = settleExpression(sim, 'anger', MAX_SETTLE_FRAMES);
      expect(r).toMatchObject({ sleeping: true, nonFinite: 0, inverted: 0 });
      expect(slowings.length).toBeGreaterThanOrEqual(2);
      expect(slowings[1] - slowings[0]).toBe(LOOP_WINDOW);
      // The second slowing is what ends it: the skin sleeps within a window of it.
      expect(r.frames).toBeLessThanOrEqual(slowings[1] + LOOP_WINDOW);
    } finally {
      spy.mockRestore();
    }
  });
});
