import { describe, expect, it } from 'vitest';
import { createBoard, PartnerTimeoutError } from '../src/core/solver/partner-board';
import { PartnerLink } from '../src/core/solver/partner-link';
import { loadHeadSimulation } from './fixtures/head-simulation';

describe('a partner thread that stops answering', () => {
  it('makes the frame throw a PartnerTimeoutError instead of hanging, and the solver goes on alone from there', async () => {
    const sim = await loadHeadSimulation('low', {}, { memory: 'shared' });
    const solver = sim.host.solver;
    // A board no thread serves: a partner that died before its first job.
    solver.attachPartner(new PartnerLink(createBoard(), 50));
    sim.expression.setActionUnit('AU12', 1);
    sim.apply();
    expect(() => sim.host.step()).toThrow(PartnerTimeoutError);

    // Detached, the same solver finishes the expression on its own thread: it sleeps, with a finite, moved skin.
    solver.attachPartner(null);
    expect(solver.workers).toBe(1);
    let frames = 0;
    while (frames < 1500 && sim.host.step()) frames++;
    expect(solver.sleeping).toBe(true);
    const x = solver.buffers.positions;
    const rest = sim.host.topology.rest;
    let moved = 0;
    for (let i = 0; i < x.length; i++) {
      expect(Number.isFinite(x[i])).toBe(true);
      moved = Math.max(moved, Math.abs(x[i] - rest[i]));
    }
    expect(moved).toBeGreaterThan(0.002);
  });
});
