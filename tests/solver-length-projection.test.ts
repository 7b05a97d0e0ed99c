import { describe, expect, it } from 'vitest';
import { mulberry32 } from '../src/core/random';
import { SkinSolver } from '../src/core/solver/solver';
import { buildTopology } from '../src/core/solver/topology';
import { triangleGrid } from './fixtures/grids';

// A free patch: no tissue pulling to rest, no bending, no momentum, so only the length (and orientation) projections
// move the skin.
const grid = triangleGrid(0.02, 0.02, 0.002);
const topology = buildTopology(grid.positions, grid.indices);
// Frames for either patch. A length error that pushes compressed edges apart too little (Jakobsen's, without the
// root) leaves the compressed patch 0.6 % off its lengths after these.
const FRAMES = 300;
const FREE = { positionStiffness: 0, wrinkleSpacing: 0, momentum: 0, startMomentum: 0, foldMomentum: 0 };

/** The largest relative length error over all edges. */
function worstLengthError(x: Float32Array): number {
  let worst = 0;
  for (let e = 0; e < topology.restLength.length; e++) {
    const a = 3 * topology.edges[2 * e];
    const b = 3 * topology.edges[2 * e + 1];
    const len = Math.hypot(x[b] - x[a], x[b + 1] - x[a + 1], x[b + 2] - x[a + 2]);
    worst = Math.max(worst, Math.abs(len / topology.restLength[e] - 1));
  }
  return worst;
}

describe('length projection', () => {
  it('brings every edge of a scrambled free patch back to its rest length', () => {
    const s = new SkinSolver(topology, { activeRegion: false });
    s.setParameters(FREE);
    const random = mulberry32(7);
    const x = s.buffers.positions;
    // Stretch the patch by half and shake each vertex by up to a quarter of a rest edge along each axis.
    for (let i = 0; i < x.length; i++) x[i] = 1.5 * x[i] + (random() - 0.5) * 0.001;
    const before = worstLengthError(x);
    for (let f = 0; f < FRAMES; f++) {
      s.wake();
      s.step();
    }
    expect(before).toBeGreaterThan(0.3);
    expect(worstLengthError(s.buffers.positions)).toBeLessThan(1e-3);
  });

  it('unfolds a free patch compressed to six tenths of its size back to its rest lengths', () => {
    const s = new SkinSolver(topology, { activeRegion: false });
    s.setParameters(FREE);
    const random = mulberry32(11);
    const x = s.buffers.positions;
    // Six tenths of the size with a little seeded relief, so the compressed patch is not flat.
    for (let i = 0; i < x.length; i++) x[i] = 0.6 * x[i] + (i % 3 === 2 ? (random() - 0.5) * 0.0001 : 0);
    for (let f = 0; f < FRAMES; f++) {
      s.wake();
      s.step();
    }
    expect(worstLengthError(s.buffers.positions)).toBeLessThan(1e-3);
  });

  it('with pretension, leaves edges shortened within the band as they are and brings shorter ones back to it', () => {
    const p = 0.15;
    const ratios = (x: Float32Array): number[] =>
      Array.from(topology.restLength, (r, e) => {
        const a = 3 * topology.edges[2 * e];
        const b = 3 * topology.edges[2 * e + 1];
        return Math.hypot(x[b] - x[a], x[b + 1] - x[a + 1], x[b + 2] - x[a + 2]) / r;
      });
    // Shortened by a half of the band: nothing to correct.
    const within = new SkinSolver(topology, { activeRegion: false });
    within.setParameters({ ...FREE, pretension: p });
    const x = within.buffers.positions;
    for (let i = 0; i < x.length; i++) x[i] *= 1 - p / 2;
    const before = x.slice();
    within.wake();
    within.step();
    expect(Math.max(...Array.from(x, (v, i) => Math.abs(v - before[i])))).toBeLessThan(1e-9);
    // Compressed to six tenths: each edge comes back into the band, none past its rest length.
    const under = new SkinSolver(topology, { activeRegion: false });
    under.setParameters({ ...FREE, pretension: p });
    const random = mulberry32(13);
    const y = under.buffers.positions;
    for (let i = 0; i < y.length; i++) y[i] = 0.6 * y[i] + (i % 3 === 2 ? (random() - 0.5) * 0.0001 : 0);
    for (let f = 0; f < FRAMES; f++) {
      under.wake();
      under.step();
    }
    const after = ratios(y);
    expect(Math.min(...after)).toBeGreaterThan(1 - p - 1e-3);
    expect(Math.max(...after)).toBeLessThan(1 + 1e-3);
  });
});
