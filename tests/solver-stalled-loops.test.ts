import { describe, expect, it } from 'vitest';
import { LATE_MOTION } from '../src/core/solver';
import { loadHeadSimulation } from './fixtures/head-simulation';

// The lids' muscles half on (AU5 at 0.5 with AU7 at 0.6, as in anger) once left a few vertices at the left eye's
// outer corner circling 0.5 mm wide, about 40 frames a turn, with no move turning back on the one before: the
// turn test of the relaxation never saw it and it ran until the late-motion safety net. The stall test must.
describe('skin caught in a smooth loop', () => {
  it('converges well before the safety net, without drifting from where the loop was', async () => {
    const sim = await loadHeadSimulation('medium');
    sim.expression.setActionUnit('AU5', 0.5);
    sim.expression.setActionUnit('AU7', 0.6);
    sim.apply();
    const x = sim.host.solver.buffers.positions;
    let frames = 0;
    let at200: Float32Array | null = null;
    while (frames < 2 * LATE_MOTION && sim.host.step()) {
      frames++;
      if (frames === 200) at200 = x.slice();
    }
    expect(sim.host.solver.sleeping).toBe(true);
    expect(frames).toBeLessThan(LATE_MOTION / 2);
    // It came to rest where it was circling (the loop is 0.5 mm across), not somewhere new.
    let farthest = 0;
    for (let i = 0; i < x.length; i += 3) farthest = Math.max(farthest, Math.hypot(x[i] - at200![i], x[i + 1] - at200![i + 1], x[i + 2] - at200![i + 2]));
    expect(farthest).toBeLessThan(0.0005);
  });
});
