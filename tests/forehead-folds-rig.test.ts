import { describe, expect, it } from 'vitest';
import { LATE_MOTION } from '../src/core/solver/solver-schedule';
import { measureForeheadFolds } from './fixtures/fold-profile';
import { loadHeadSimulation, type Resolution } from './fixtures/head-simulation';

/** The rig's AU1 + AU2 at full intensity, both sides, from rest until the skin sleeps; the folds it leaves. */
async function raiseBrows(resolution: Resolution) {
  const sim = await loadHeadSimulation(resolution);
  sim.expression.setActionUnit('AU1', 1);
  sim.expression.setActionUnit('AU2', 1);
  sim.apply();
  let frames = 0;
  while (frames < 2 * LATE_MOTION && sim.host.step()) frames++;
  const t = sim.host.topology;
  return { frames, sleeping: sim.host.solver.sleeping, ...measureForeheadFolds(t.rest, t.restNormals, sim.host.solver.buffers.positions) };
}

describe('forehead folds of the rig raising the brows (AU1 + AU2)', () => {
  it('are spaced alike on the 17k and 68k heads: the skin sets the spacing, not the mesh', async () => {
    const medium = await raiseBrows('medium');
    const high = await raiseBrows('high');
    for (const r of [medium, high]) {
      // Converged, not stopped by the late-motion safety net.
      expect(r.sleeping).toBe(true);
      expect(r.frames).toBeLessThan(LATE_MOTION);
      // Real folds: 0.1 mm root mean square after the brow's smooth lift is taken away (a visible crease is a few
      // tenths), at least two crests per line.
      expect(r.amplitude).toBeGreaterThan(0.0001);
      expect(r.crests).toBeGreaterThanOrEqual(2);
    }
    const apart = (a: number, b: number) => Math.abs(a - b) / Math.max(a, b);
    expect(apart(medium.wavelength, high.wavelength)).toBeLessThan(0.25);
    expect(apart(medium.crestSpacing, high.crestSpacing)).toBeLessThan(0.25);
  });
});
