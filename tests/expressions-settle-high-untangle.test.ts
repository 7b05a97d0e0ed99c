import { beforeAll, describe, expect, it, vi } from 'vitest';
import { FramePasses } from '../src/core/solver/solver-passes';
import { LATE_MOTION } from '../src/core/solver/solver-schedule';
import { loadHeadSimulation, MAX_SETTLE_FRAMES, settleExpression } from './fixtures/head-simulation';

// Anger on the high head comes to stillness with one sliver turned over where the pressed lips meet. Untangled at half
// the orientation bound, 76 tries in 77 still frames failed and the lift then moved the skin 0.165 mm (the preset slept
// after 290 frames); held to a tenth of the bound (UNTANGLE_FLOOR), the first try turns it back with a move of 0.015 mm
// (214 frames; 153 since the loop test looks every half window). docs/solver-notes.md, "Untangling to a tenth of the
// bound".
describe('untangling still skin on the high head', () => {
  let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
  beforeAll(async () => {
    sim = await loadHeadSimulation('high');
  });

  it('anger comes to rest by converging, its sliver turned back at the first try by a move under 0.05 mm', () => {
    const untangle = FramePasses.prototype.untangle;
    const tries: number[] = [];
    const spy = vi.spyOn(FramePasses.prototype, 'untangle').mockImplementation(function (this: FramePasses, count, keep) {
      const x = sim.host.solver.buffers.positions;
      const before = Float32Array.from(x);
      untangle.call(this, count, keep);
      let moved = 0;
      for (let i = 0; i < x.length; i += 3)
        moved = Math.max(moved, Math.hypot(x[i] - before[i], x[i + 1] - before[i + 1], x[i + 2] - before[i + 2]));
      tries.push(moved);
    });
    try {
      const r = settleExpression(sim, 'anger', MAX_SETTLE_FRAMES);
      expect(r).toMatchObject({ sleeping: true, nonFinite: 0, inverted: 0 });
      expect(r.frames).toBeLessThan(LATE_MOTION);
      // A try that fails puts the skin back (a move of 0); anger's skin does stand still with a sliver turned over.
      expect(tries.length).toBeGreaterThan(0);
      expect(tries.filter((m) => m === 0)).toEqual([]);
      expect(Math.max(...tries)).toBeLessThan(0.05e-3);
    } finally {
      spy.mockRestore();
    }
  });
});
