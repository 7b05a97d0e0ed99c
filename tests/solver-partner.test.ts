import { describe, expect, it } from 'vitest';
import { loadHeadSimulation } from './fixtures/head-simulation';
import { startPartnerThread } from './fixtures/partner';

/** Frames per expression: enough for the active region to grow and the relaxation to act. */
const FRAMES = 120;

/** The low head through a smile with the jaw open, then a brow raise with a frown, on one thread or two. */
async function solve(threads: 1 | 2): Promise<{ shapes: Float32Array[]; threadsUsed: number[] }> {
  const sim = await loadHeadSimulation('low', {}, { memory: 'shared' });
  const partner = threads === 2 ? await startPartnerThread(sim.host.solver) : null;
  const shapes: Float32Array[] = [];
  const threadsUsed: number[] = [];
  try {
    for (const units of [
      { AU12: 1, AU26: 1 },
      { AU1: 1, AU2: 1, AU4: 0.6 },
    ]) {
      sim.expression.reset();
      for (const [unit, value] of Object.entries(units)) sim.expression.setActionUnit(unit, value);
      sim.apply();
      for (let f = 0; f < FRAMES; f++) sim.host.step();
      threadsUsed.push(sim.host.solver.workers);
      shapes.push(sim.host.solver.buffers.positions.slice());
    }
  } finally {
    await partner?.stop();
  }
  return { shapes, threadsUsed };
}

describe('a partner thread', () => {
  it('gives the shape one thread gives, frame for frame', async () => {
    const one = await solve(1);
    const two = await solve(2);
    expect(two.threadsUsed).toEqual([2, 2]);
    const sim = await loadHeadSimulation('low');
    const rest = sim.host.topology.rest;
    for (let k = 0; k < one.shapes.length; k++) {
      let moved = 0;
      let difference = 0;
      for (let i = 0; i < rest.length; i++) {
        moved = Math.max(moved, Math.abs(one.shapes[k][i] - rest[i]));
        difference = Math.max(difference, Math.abs(one.shapes[k][i] - two.shapes[k][i]));
      }
      // Both expressions move the skin by millimetres, so agreement is not skin left at rest.
      expect(moved).toBeGreaterThan(0.002);
      expect(difference).toBeLessThanOrEqual(1e-6 * sim.host.topology.size);
    }
  });
});
