import { describe, expect, it } from 'vitest';
import { LATE_MOTION } from '../src/core/solver';
import { loadHeadSimulation } from './fixtures/head-simulation';

// Anger's skin has no stable resting shape the frame's map reaches by itself: without the stall test (see
// SkinSolver.breakLoops) a patch kept moving, never turning back on itself enough for the relaxation's turn test,
// until the late-motion safety net at 1,000 frames (1,252 frames to sleep).
describe('skin that stalls instead of converging', () => {
  it('comes to rest well before the safety net, near where it was going round', async () => {
    const sim = await loadHeadSimulation('medium');
    sim.expression.applyPreset('anger', 1);
    sim.apply();
    const x = sim.host.solver.buffers.positions;
    let frames = 0;
    let at150: Float32Array | null = null;
    while (frames < 2 * LATE_MOTION && sim.host.step()) {
      frames++;
      if (frames === 150) at150 = x.slice();
    }
    expect(sim.host.solver.sleeping).toBe(true);
    expect(frames).toBeLessThan(LATE_MOTION / 2);
    // It came to rest about where it was going round (well within a millimetre), not somewhere new.
    expect(at150).not.toBeNull();
    let farthest = 0;
    for (let i = 0; i < x.length; i += 3) farthest = Math.max(farthest, Math.hypot(x[i] - at150![i], x[i + 1] - at150![i + 1], x[i + 2] - at150![i + 2]));
    expect(farthest).toBeLessThan(0.0005);
  });
});
