import { describe, expect, it } from 'vitest';
import { LATE_MOTION, STILL_MOVE } from '../src/core/solver/solver-schedule';
import { loadHeadSimulation } from './fixtures/head-simulation';

// Skin that goes round instead of converging (see SkinSolver.breakLoops): the anger preset once did until the
// late-motion safety net without the stall test; it converges now, and a glare (AU4 at E with AU7 and AU23 at 0.8,
// AU5 at 0.5) is the case instead: a fold at the brow's head goes round for a hundred frames (105 to within 2 %).
// The default sleep tolerance stops it at about 95 frames, before the loop shows; at the tolerance the loop handling
// works to (STILL_MOVE) it goes round until the handling slows it.
describe('skin that stalls instead of converging', () => {
  it('comes to rest well before the safety net, near where it was going round', async () => {
    const sim = await loadHeadSimulation('medium', { sleepTolerance: STILL_MOVE });
    for (const [id, value] of [
      ['AU4', 1],
      ['AU5', 0.5],
      ['AU7', 0.8],
      ['AU23', 0.8],
    ] as const)
      sim.expression.setActionUnit(id, value);
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
    for (let i = 0; i < x.length; i += 3)
      farthest = Math.max(farthest, Math.hypot(x[i] - at150![i], x[i + 1] - at150![i + 1], x[i + 2] - at150![i + 2]));
    expect(farthest).toBeLessThan(0.0005);
  });
});
