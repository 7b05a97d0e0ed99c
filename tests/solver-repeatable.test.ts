import { describe, expect, it } from 'vitest';
import { loadHeadSimulation } from './fixtures/head-simulation';

/**
 * Skin back at rest moves the same whatever moved it before: a recorder relies on it for the same frames twice. The
 * low head, as the worker solves it: AU12 ramped in over a few inputs (new inputs every few frames, as a video
 * clock gives them), from a fresh solver and again after another expression came and went.
 */
describe('the solver from rest', () => {
  it('solves the same frames from rest after another expression came and went as from a fresh start', async () => {
    const sim = await loadHeadSimulation('low');
    const { host, expression, apply } = sim;
    const ramp = (): Float32Array => {
      for (let k = 1; k <= 8; k++) {
        expression.setActionUnit('AU12', k / 8);
        apply();
        expect(host.run(6)).toBe(6);
      }
      return host.solver.buffers.positions.slice();
    };
    const fresh = ramp();
    // Something else moves the skin (here the brows and the jaw), then everything goes back to rest.
    expression.reset();
    expression.setActionUnit('AU1', 1);
    expression.setActionUnit('AU26', 0.6);
    apply();
    host.run(150);
    expression.reset();
    apply();
    host.run(1500);
    expect(host.solver.sleeping).toBe(true);
    const again = ramp();
    let moved = 0;
    for (let i = 0; i < fresh.length; i++) moved = Math.max(moved, Math.abs(fresh[i] - host.topology.rest[i]));
    expect(moved).toBeGreaterThan(1e-3);
    let differ = 0;
    for (let i = 0; i < fresh.length; i++) if (fresh[i] !== again[i]) differ++;
    expect(differ).toBe(0);
  }, 60_000);
});
