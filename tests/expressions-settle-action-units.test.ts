import { beforeAll, describe, expect, it } from 'vitest';
import { ACTION_UNITS } from '../src/core/expression/facs';
import { LATE_MOTION } from '../src/core/solver/solver-schedule';
import { ACTION_UNIT_MEASURES, faceLandmarks, type FaceLandmarks } from './fixtures/face-landmarks';
import { loadHeadSimulation, MAX_SETTLE_FRAMES, returnToRest, settleExpression } from './fixtures/head-simulation';

// Each Action Unit at full intensity on the medium head, solved as the worker solves it (SolverHost, colliders, rig).
// One settle per unit serves both checks: the medium head's settles are most of the unit tests' time.
describe('every Action Unit at full intensity on the medium head', () => {
  let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
  let landmarks: FaceLandmarks;
  beforeAll(async () => {
    sim = await loadHeadSimulation('medium');
    landmarks = faceLandmarks(sim.host.topology.rest, sim.triangles);
  });

  it.each(ACTION_UNITS.map((au) => au.id))(
    '%s comes to rest with no NaN and no triangle turned over, moves its landmark by its FACS amount, and goes back to rest after a reset',
    (id) => {
      const r = settleExpression(sim, id, MAX_SETTLE_FRAMES);
      expect(r).toMatchObject({ sleeping: true, nonFinite: 0, inverted: 0 });
      // Converged, not stopped by the safety net.
      expect(r.frames).toBeLessThan(LATE_MOTION);
      // Its FACS amount (docs/features.md, "How far each Action Unit moves the face"); a unit may have more than one measure
      // (AU4: down, and toward the midline).
      const rest = sim.host.topology.rest;
      const x = sim.host.solver.buffers.positions;
      const measures = Object.entries(ACTION_UNIT_MEASURES).filter(([key]) => key === id || key.startsWith(`${id} `));
      expect(measures.length).toBeGreaterThan(0);
      for (const [key, m] of measures) {
        const mm = m.read(landmarks, rest, x);
        expect(mm, `${key}: ${m.landmark}`).toBeGreaterThanOrEqual(m.range[0]);
        expect(mm, `${key}: ${m.landmark}`).toBeLessThanOrEqual(m.range[1]);
      }
      // Every vertex exactly at rest and the active region empty, the lips free of the teeth (AU26 once left them
      // 12.8 mm off).
      const back = returnToRest(sim);
      expect(back).toMatchObject({ sleeping: true, offRest: 0, farthest: 0, activeVertices: 0 });
    },
  );
});
