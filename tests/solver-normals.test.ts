import { describe, expect, it } from 'vitest';
import { computeNormals } from '../src/core/solver/topology';
import { loadHeadSimulation } from './fixtures/head-simulation';
import { startPartnerThread } from './fixtures/partner';

/** The low head after 40 frames of a smile with the jaw open, on one thread or two: its positions and normals. */
async function solve(threads: 1 | 2) {
  const sim = await loadHeadSimulation('low', {}, { memory: 'shared' });
  const partner = threads === 2 ? await startPartnerThread(sim.host.solver) : null;
  try {
    sim.expression.setActionUnit('AU12', 1);
    sim.expression.setActionUnit('AU26', 1);
    sim.apply();
    for (let f = 0; f < 40; f++) sim.host.step();
    const s = sim.host.solver;
    return { topology: s.topology, workers: s.workers, positions: s.buffers.positions.slice(), normals: s.buffers.normals.slice() };
  } finally {
    await partner?.stop();
  }
}

describe('the normals of a solved frame', () => {
  it('are those of the whole mesh where the skin moved, and the rest normals elsewhere', async () => {
    const { topology: t, positions, normals } = await solve(1);
    const whole = new Float32Array(positions.length);
    computeNormals(positions, t.triangles, whole);
    let moved = 0;
    let worst = 0;
    for (let v = 0; v < t.vertexCount; v++) {
      const i = 3 * v;
      const shifted = Math.hypot(positions[i] - t.rest[i], positions[i + 1] - t.rest[i + 1], positions[i + 2] - t.rest[i + 2]);
      if (shifted > 1e-4) moved++;
      const same = (a: Float32Array) => Math.hypot(normals[i] - a[i], normals[i + 1] - a[i + 1], normals[i + 2] - a[i + 2]);
      // Skin at rest with all its neighbours keeps its rest normal; all other skin has its true normal.
      const wholeOff = same(whole);
      const restOff = same(t.restNormals);
      worst = Math.max(worst, Math.min(wholeOff, restOff));
      if (shifted > 1e-4) expect(wholeOff).toBeLessThan(1e-5);
    }
    expect(moved).toBeGreaterThan(100);
    expect(worst).toBeLessThan(1e-5);
  });

  it('are the same to the bit on two threads as on one', async () => {
    const one = await solve(1);
    const two = await solve(2);
    expect(two.workers).toBe(2);
    expect(two.positions).toEqual(one.positions);
    expect(two.normals).toEqual(one.normals);
  });
});
