import { describe, expect, it } from 'vitest';
import { loadHeadSimulation } from './fixtures/head-simulation';

const FRAMES = 12;

/** Solves AU12 for FRAMES frames and returns the positions. */
async function smile(warm: boolean): Promise<{ positions: Float32Array; pieces: number; hostFramesInWarmUp: number; sleeping: boolean }> {
  const sim = await loadHeadSimulation('low');
  const framesBefore = sim.host.solver.frames;
  let pieces = 0;
  if (warm) for (const _ of sim.host.warmUp()) pieces++;
  const sleeping = sim.host.solver.sleeping;
  sim.expression.setActionUnit('AU12', 1);
  sim.apply();
  for (let f = 0; f < FRAMES; f++) sim.host.step();
  return {
    positions: sim.host.solver.buffers.positions.slice(),
    pieces,
    hostFramesInWarmUp: sim.host.solver.frames - FRAMES - framesBefore,
    sleeping,
  };
}

describe('the solver host warm-up', () => {
  it('runs in pieces and leaves the skin to the bit as it was: the next expression solves the same', async () => {
    const cold = await smile(false);
    const warm = await smile(true);
    // The rig's targets, then one piece per warm-up frame.
    expect(warm.pieces).toBeGreaterThanOrEqual(4);
    expect(warm.sleeping).toBe(true);
    // The host's own solver solved no frame during the warm-up.
    expect(warm.hostFramesInWarmUp).toBe(0);
    let moved = 0;
    for (let i = 0; i < cold.positions.length; i++) if (cold.positions[i] !== warm.positions[i]) moved++;
    expect(moved).toBe(0);
  });
});
