import { describe, expect, it } from 'vitest';
import { reachableBuffers, touchPages } from '../src/core/solver/memory';
import { mulberry32 } from '../src/core/random';
import { loadHeadSimulation } from './fixtures/head-simulation';

// Mapping pages ahead of the first input (SolverHost.warmUp's first pieces) must change nothing the solver reads.
describe('touching the pages of the solver arrays', () => {
  it('finds each reachable buffer once, within the depth asked for', () => {
    const shared = new SharedArrayBuffer(3 * 4096 + 12);
    const a = new Float32Array(shared);
    const b = new Uint32Array(20_000);
    const deep = new Float64Array(100);
    // Two views of one buffer, an array of views, a nested object, and an array four objects down.
    const root = { a, again: new Uint8Array(shared, 8, 16), list: [b], nested: { plain: 3, more: { evenMore: { deep } } } };
    expect(reachableBuffers(root)).toEqual([shared, b.buffer]);
    expect(reachableBuffers(root, 4)).toEqual([shared, b.buffer, deep.buffer]);
  });

  it('leaves every value of a buffer as it was, shared or not', () => {
    const random = mulberry32(7);
    const a = new Float32Array(new SharedArrayBuffer(4 * 5000));
    for (let i = 0; i < a.length; i++) a[i] = random() - 0.5;
    const b = new Uint32Array(20_000).map(() => Math.floor(random() * 2 ** 32));
    const before = [a.slice(), b.slice()];
    touchPages(a.buffer);
    touchPages(b.buffer);
    touchPages(new ArrayBuffer(0));
    expect(a).toEqual(before[0]);
    expect(b).toEqual(before[1]);
  });

  it('leaves a solve exactly as it was without the touch', async () => {
    const solve = async (touch: boolean): Promise<Float32Array> => {
      const sim = await loadHeadSimulation('low');
      if (touch) {
        const buffers = reachableBuffers(sim.host.solver);
        expect(buffers.reduce((sum, buffer) => sum + buffer.byteLength, 0)).toBeGreaterThan(1_000_000);
        for (const buffer of buffers) touchPages(buffer);
      }
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
