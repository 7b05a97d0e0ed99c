import { describe, expect, it } from 'vitest';
import { compressGrid, dominantWavelength } from './fixtures/compression';

// The 80 x 40 mm test field at 1 mm spacing, compressed by 10 %, folding at 6 mm (see solver-wrinkles.test.ts).
const run = (foldMomentum: number) => compressGrid(0.08, 0.04, 0.001, 0.1, { wrinkleSpacing: 0.006, momentum: 0.5, foldMomentum });

describe('fold momentum (the carried move along the rest normal)', () => {
  const even = run(0.5);
  const folds = run(0.75);

  it('settles the folds in fewer frames than the surface momentum alone', () => {
    expect(even.solver.sleeping).toBe(true);
    expect(folds.solver.sleeping).toBe(true);
    // Measured: 91 frames against 50.
    expect(folds.frames).toBeLessThan(0.75 * even.frames);
  });

  it('keeps the fold spacing the skin asks for', () => {
    const a = dominantWavelength(even);
    const b = dominantWavelength(folds);
    expect(Math.abs(a - b) / a).toBeLessThan(0.1);
  });
});
