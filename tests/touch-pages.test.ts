import { describe, expect, it } from 'vitest';
import { touchPages, touchReachablePages } from '../src/core/solver/memory';
import { mulberry32 } from '../src/core/random';
import { loadHeadSimulation } from './fixtures/head-simulation';

// Mapping pages ahead of the first input (SolverHost.warmUp's first piece) must change nothing the solver reads.
describe('touching the pages of the solver arrays', () => {
  it('leaves every value as it was and counts each buffer once', () => {
    const random = mulberry32(7);
    const shared = new SharedArrayBuffer(3 * 4096 + 12);
    const a = new Float32Array(shared);
    for (let i = 0; i < a.length; i++) a[i] = random() - 0.5;
    const b = new Uint32Array(20_000).map(() => Math.floor(random() * 2 ** 32));
    const deep = new Float64Array(100);
    // Two views of one buffer, an array of views, a nested object, and an array four objects down.
    const root = { a, again: new Uint8Array(shared, 8, 16), list: [b], nested: { plain: 3, more: { evenMore: { deep } } } };
    const before = [a.slice(), b.slice()];
    expect(touchReachablePages(root)).toBe(shared.byteLength + b.byteLength);
    expect(a).toEqual(before[0]);
    expect(b).toEqual(before[1]);
    expect(touchReachablePages(root, 4)).toBe(shared.byteLength + b.byteLength + deep.byteLength);
    touchPages(new ArrayBuffer(0));
  });

  it('leaves a solve exactly as it was without the touch', async () => {
    const solve = async (touch: boolean): Promise<Float32Array> => {
      const sim = await loadHeadSimulation('low');
      if (touch) expect(touchReachablePages(sim.host.solver)).toBeGreaterThan(1_000_000);
      sim.expression.applyPreset('happiness', 1);
      sim.apply();
      for (let f = 0; f < 12 && sim.host.step(); f++);
      return sim.host.solver.buffers.positions.slice();
    };
    const plain = await solve(false);
    const touched = await solve(true);
    expect(touched).toEqual(plain);
    let moved = 0;
    const sim = await loadHeadSimulation('low');
    const rest = sim.host.topology.rest;
    for (let i = 0; i < rest.length; i++) moved = Math.max(moved, Math.abs(plain[i] - rest[i]));
    expect(moved).toBeGreaterThan(0.001);
  });
});
