import { beforeAll, describe, expect, it } from 'vitest';
import { LATE_MOTION } from '../src/core/solver/solver-schedule';
import { loadDefaultRig, loadHeadSimulation, MAX_SETTLE_FRAMES, returnToRest, settleExpression } from './fixtures/head-simulation';

// Each preset at full weight on the medium head, solved as the worker solves it (SolverHost, colliders, rig).
describe('every preset at full weight on the medium head', () => {
  let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
  beforeAll(async () => {
    sim = await loadHeadSimulation('medium');
  });

  it.each(loadDefaultRig().presets.map((p) => p.name))(
    '%s comes to rest with no NaN and no triangle turned over, and back to rest after a reset',
    (name) => {
      const r = settleExpression(sim, name, MAX_SETTLE_FRAMES);
      expect(r).toMatchObject({ sleeping: true, nonFinite: 0, inverted: 0 });
      // Converged, not stopped by the safety net (anger's eye corner once circled until it).
      expect(r.frames).toBeLessThan(LATE_MOTION);
      const back = returnToRest(sim);
      expect(back).toMatchObject({ sleeping: true, offRest: 0, farthest: 0, activeVertices: 0 });
    },
  );
});
