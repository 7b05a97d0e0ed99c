import { describe, expect, it } from 'vitest';
import { loadHeadSimulation } from './fixtures/head-simulation';
import { startPartnerThread } from './fixtures/partner';

const FRAMES = 12;

/**
 * Solves AU12 for FRAMES frames and returns the positions: cold, after the warm-up, or (`partner`) on two threads after
 * a warm-up that the partner thread served too.
 */
async function smile(warm: 'cold' | 'warm' | 'partner') {
  const sim = await loadHeadSimulation('low', {}, { memory: warm === 'partner' ? 'shared' : 'local' });
  const framesBefore = sim.host.solver.frames;
  let pieces = 0;
  if (warm === 'warm') for (const _ of sim.host.warmUp()) pieces++;
  const partner = warm === 'partner' ? await startPartnerThread(sim.host.solver, sim.host) : null;
  const sleeping = sim.host.solver.sleeping;
  sim.expression.setActionUnit('AU12', 1);
  sim.apply();
  let threads = 0;
  try {
    for (let f = 0; f < FRAMES; f++) sim.host.step();
    threads = sim.host.solver.workers;
  } finally {
    await partner?.stop();
  }
  return {
    positions: sim.host.solver.buffers.positions.slice(),
    pieces,
    hostFramesInWarmUp: sim.host.solver.frames - FRAMES - framesBefore,
    sleeping,
    threads,
    warmUpJobs: partner?.warmUpJobs ?? 0,
    size: sim.host.topology.size,
  };
}

/** Largest difference between two shapes, and how many numbers differ at all. */
function compare(a: Float32Array, b: Float32Array): { largest: number; differing: number } {
  let largest = 0;
  let differing = 0;
  for (let i = 0; i < a.length; i++) {
    if (a[i] !== b[i]) differing++;
    largest = Math.max(largest, Math.abs(a[i] - b[i]));
  }
  return { largest, differing };
}

describe('the solver host warm-up', () => {
  it('runs in pieces and leaves the skin to the bit as it was: the next expression solves the same', async () => {
    const cold = await smile('cold');
    const warm = await smile('warm');
    // The rig's targets, then one piece per warm-up frame.
    expect(warm.pieces).toBeGreaterThanOrEqual(4);
    expect(warm.sleeping).toBe(true);
    // The host's own solver solved no frame during the warm-up.
    expect(warm.hostFramesInWarmUp).toBe(0);
    expect(compare(cold.positions, warm.positions).differing).toBe(0);
  });

  it('hands its partner thread half of its passes, and the partner then takes the host solver', async () => {
    const cold = await smile('cold');
    const partner = await smile('partner');
    // The partner finished jobs of the warm-up's frames (each frame posts dozens).
    expect(partner.warmUpJobs).toBeGreaterThan(20);
    expect(partner.hostFramesInWarmUp).toBe(0);
    expect(partner.sleeping).toBe(true);
    // Then it served the host's solver: two threads, the one-thread shape (see solver-partner.test.ts).
    expect(partner.threads).toBe(2);
    expect(compare(cold.positions, partner.positions).largest).toBeLessThanOrEqual(1e-6 * partner.size);
  });

  it('sees no skin solved in the frames of a reset at rest, and skin solved in the first frame of an expression', async () => {
    // The worker ends its warm-up at the first frame that solved skin: a script's reset of the neutral face at the
    // page's start must not end it, an expression must.
    const sim = await loadHeadSimulation('low');
    sim.expression.reset();
    sim.apply();
    const reset: boolean[] = [];
    while (sim.host.step()) reset.push(sim.host.solvedSkin);
    expect(reset.length).toBeGreaterThan(0);
    expect(reset).not.toContain(true);
    sim.expression.setActionUnit('AU12', 1);
    sim.apply();
    expect(sim.host.step()).toBe(true);
    expect(sim.host.solvedSkin).toBe(true);
  });
});
