import { beforeAll, describe, expect, it } from 'vitest';
import { ACTION_UNIT_MEASURES, faceLandmarks, type FaceLandmarks } from './fixtures/face-landmarks';
import { loadHeadSimulation, MAX_SETTLE_FRAMES, returnToRest, settleExpression } from './fixtures/head-simulation';

// The Action Units whose FACS target (README, "Where each Action Unit moves the face") the default rig reaches.
const FITTED = ['AU1', 'AU2', 'AU4', 'AU5', 'AU6', 'AU7', 'AU9', 'AU10', 'AU12', 'AU14', 'AU15', 'AU16', 'AU17', 'AU18', 'AU20', 'AU26', 'AU27', 'AU43'];

// Each Action Unit at full intensity on the medium head, settled, its landmark's move measured in mm against the table.
describe('each Action Unit moves its landmark by its FACS amount on the medium head', () => {
  let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
  let landmarks: FaceLandmarks;
  beforeAll(async () => {
    sim = await loadHeadSimulation('medium');
    landmarks = faceLandmarks(sim.host.topology.rest, sim.triangles);
  });

  it.each(FITTED)('%s', (id) => {
    const settled = settleExpression(sim, id, MAX_SETTLE_FRAMES);
    expect(settled).toMatchObject({ sleeping: true, inverted: 0 });
    const rest = sim.host.topology.rest;
    const x = sim.host.solver.buffers.positions;
    // An Action Unit may have more than one measure (AU4: down, and toward the midline).
    const measures = Object.entries(ACTION_UNIT_MEASURES).filter(([key]) => key === id || key.startsWith(`${id} `));
    expect(measures.length).toBeGreaterThan(0);
    for (const [key, m] of measures) {
      const mm = m.read(landmarks, rest, x);
      expect(mm, `${key}: ${m.landmark}`).toBeGreaterThanOrEqual(m.range[0]);
      expect(mm, `${key}: ${m.landmark}`).toBeLessThanOrEqual(m.range[1]);
    }
    expect(returnToRest(sim).sleeping).toBe(true);
  });
});
