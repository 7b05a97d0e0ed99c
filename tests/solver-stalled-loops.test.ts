import { describe, expect, it } from 'vitest';
import { LATE_MOTION, STILL_MOVE } from '../src/core/solver/solver-schedule';
import { loadHeadSimulation } from './fixtures/head-simulation';

// Skin that goes round instead of converging (see SkinSolver.breakLoops): the anger preset once did until the
// late-motion safety net without the stall test, then a glare (AU4 at E with AU7 and AU23 at 0.8, AU5 at 0.5), whose
// fold at the brow's head went round while AU4's share of the lid's turn dragged the brow (it converges in 40 frames
// since the lid's skin unfolds, see LidSlack). The thesis's happiness is the case now: at the tolerance the loop
// handling works to (STILL_MOVE), without the handling it goes on to the safety net (1,050 frames), with it it sleeps
// after 145 (its loop grows from frame 100 until the handling slows it at frame 132).
describe('skin that stalls instead of converging', () => {
  it('comes to rest well before the safety net, near where it was going round', async () => {
    const sim = await loadHeadSimulation('medium', { sleepTolerance: STILL_MOVE });
    sim.expression.applyPreset('thesis-happiness', 1);
    sim.apply();
    const x = sim.host.solver.buffers.positions;
    let frames = 0;
    let atLoop: Float32Array | null = null;
    while (frames < 2 * LATE_MOTION && sim.host.step()) {
      frames++;
      if (frames === 120) atLoop = x.slice();
    }
    expect(sim.host.solver.sleeping).toBe(true);
    expect(frames).toBeLessThan(LATE_MOTION / 2);
    // It came to rest about where it was going round (well within a millimetre), not somewhere new.
    expect(atLoop).not.toBeNull();
    let farthest = 0;
    for (let i = 0; i < x.length; i += 3)
      farthest = Math.max(farthest, Math.hypot(x[i] - atLoop![i], x[i + 1] - atLoop![i + 1], x[i + 2] - atLoop![i + 2]));
    expect(farthest).toBeLessThan(0.0005);
  });
});
