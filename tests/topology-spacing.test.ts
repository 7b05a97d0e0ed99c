import { describe, expect, it } from 'vitest';
import { buildTopology } from '../src/core/solver/topology';
import { triangleGrid } from './fixtures/grids';

describe('the mesh spacing the bending is scaled by', () => {
  it('is the spacing across the finest direction: stretching a grid along x leaves it as it was', () => {
    const h = 0.002;
    const square = triangleGrid(0.02, 0.02, h);
    const stretched = Float32Array.from(square.positions, (p, i) => (i % 3 === 0 ? 2.5 * p : p));
    const a = buildTopology(square.positions, square.indices);
    const b = buildTopology(stretched, square.indices);
    let interior = 0;
    for (let r = 0; r < square.nx * square.ny; r++) {
      const i = r % square.nx;
      const j = Math.floor(r / square.nx);
      if (i === 0 || j === 0 || i === square.nx - 1 || j === square.ny - 1) continue;
      interior++;
      const va = a.renderToSim[r];
      const vb = b.renderToSim[r];
      // Four neighbours along the axes: the edge length; eight (with diagonals): sqrt(3/2) of it.
      const degree = a.neighbourStart[va + 1] - a.neighbourStart[va];
      expect(a.spacing[va]).toBeCloseTo(degree === 4 ? h : Math.sqrt(1.5) * h, 8);
      expect(b.spacing[vb]).toBeCloseTo(a.spacing[va], 8);
    }
    expect(interior).toBeGreaterThan(50);
  });
});
