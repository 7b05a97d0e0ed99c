import { describe, expect, it } from 'vitest';
import { compressGrid, dominantWavelength, foldAmplitude, shortWavePowerFraction } from './fixtures/compression';

// An 80 x 40 mm patch of skin compressed by 10 % along x, at 2 mm and 1 mm spacing (the ratio of the 17k and 68k
// heads), flat and curved like a forehead (5 cm radius).
const W = 0.08;
const H = 0.04;
const STRAIN = 0.1;

describe.each([
  { shape: 'flat', radius: 0 },
  { shape: 'curved', radius: 0.05 },
])('a compressed $shape patch', ({ radius }) => {
  const coarse = compressGrid(W, H, 0.002, STRAIN, { wrinkleSpacing: 0.008 }, radius);
  const fine = compressGrid(W, H, 0.001, STRAIN, { wrinkleSpacing: 0.008 }, radius);

  it('converges and goes to sleep', () => {
    expect(coarse.solver.sleeping).toBe(true);
    expect(fine.solver.sleeping).toBe(true);
  });

  it('buckles out of plane instead of compressing flat', () => {
    // 10 % of excess length folded at wavelength lambda needs folds of amplitude about (lambda / pi) sqrt(0.1), about
    // 0.8 mm for 8 mm folds; we ask for a third of that as root mean square, far above float noise (1e-8 m).
    expect(foldAmplitude(coarse)).toBeGreaterThan(0.00025);
    expect(foldAmplitude(fine)).toBeGreaterThan(0.00025);
  });

  it('bulges outward on average (folds rise rather than sink)', () => {
    const mean = (r: typeof coarse) => r.normalDisplacement.reduce((a, b) => a + b, 0) / r.normalDisplacement.length;
    expect(mean(coarse)).toBeGreaterThan(0);
    expect(mean(fine)).toBeGreaterThan(0);
  });

  it('folds at the skin wavelength, within 25 % between the two resolutions and near the 8 mm asked for', () => {
    const a = dominantWavelength(coarse);
    const b = dominantWavelength(fine);
    expect(Math.abs(a - b) / Math.max(a, b)).toBeLessThan(0.25);
    for (const l of [a, b]) {
      expect(l).toBeGreaterThan(0.005);
      expect(l).toBeLessThan(0.011);
    }
  });
});

describe('bending resistance', () => {
  it('keeps folds off the mesh scale: without it, a third or more of the fold power at 1 mm spacing sits below 4 mm', () => {
    const without = compressGrid(W, H, 0.001, STRAIN, { wrinkleSpacing: 0 });
    const withBending = compressGrid(W, H, 0.001, STRAIN, { wrinkleSpacing: 0.008 });
    expect(shortWavePowerFraction(without, 0.004)).toBeGreaterThan(0.3);
    expect(shortWavePowerFraction(withBending, 0.004)).toBeLessThan(0.1);
  });

  it('gives longer folds for a longer skin wavelength', () => {
    const short = dominantWavelength(compressGrid(W, H, 0.001, STRAIN, { wrinkleSpacing: 0.006 }));
    const long = dominantWavelength(compressGrid(W, H, 0.001, STRAIN, { wrinkleSpacing: 0.012 }));
    expect(long / short).toBeGreaterThan(1.4);
  });
});
