import { beforeAll, describe, expect, it } from 'vitest';
import { ACTION_UNITS } from '../src/core/facs';
import { loadHeadSimulation, MAX_SETTLE_FRAMES, returnToRest, settleExpression } from './fixtures/head-simulation';

// Each Action Unit at full intensity on the medium head, solved as the worker solves it (SolverHost, colliders, rig).
describe('every Action Unit at full intensity on the medium head', () => {
  let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
  beforeAll(async () => {
    sim = await loadHeadSimulation('medium');
  });

  it.each(ACTION_UNITS.map((au) => au.id))('%s comes to rest with no NaN and no triangle turned over, and back to rest after a reset', (id) => {
    const r = settleExpression(sim, id, MAX_SETTLE_FRAMES);
    expect(r).toMatchObject({ sleeping: true, nonFinite: 0, inverted: 0 });
    // Every vertex within 0.01 mm of rest, the lips free of the teeth (AU26 once left them 12.8 mm off).
    const back = returnToRest(sim);
    expect(back.sleeping).toBe(true);
    expect(back.farthest).toBeLessThan(1e-5);
  });
});
