import { describe, expect, it } from 'vitest';
import { fitIdentityWarp, spreadVertices } from '../src/core/head/identity-warp';
import { warpPoint } from '../src/core/head/thin-plate';
import { mulberry32 } from '../src/core/random';

/** Points on an ellipsoid about a head's size (metres), seeded. */
function headCloud(count: number, seed: number): Float64Array {
  const random = mulberry32(seed);
  const p = new Float64Array(3 * count);
  for (let i = 0; i < count; i++) {
    const u = 2 * random() - 1;
    const phi = 2 * Math.PI * random();
    const r = Math.sqrt(1 - u * u);
    p.set([0.08 * r * Math.cos(phi), 0.12 * u, 0.1 * r * Math.sin(phi)], 3 * i);
  }
  return p;
}

/** A smooth change of shape like an identity's: wider, a little longer, a bump where a nose would be. */
function reshape(p: Float64Array): Float64Array {
  const out = new Float64Array(p.length);
  for (let i = 0; i < p.length; i += 3) {
    const [x, y, z] = [p[i], p[i + 1], p[i + 2]];
    const bump = 0.01 * Math.exp(-((x / 0.04) ** 2 + (y / 0.04) ** 2)) * Math.max(0, z / 0.1);
    out.set([1.06 * x, 1.03 * y + 0.002, z + bump], i);
  }
  return out;
}

describe('identity warp', () => {
  it('spreads its picks over the whole point set: every point lies within 3 cm of one of 240', () => {
    const p = headCloud(4000, 5);
    const picks = spreadVertices(p, 240);
    expect(new Set(picks).size).toBe(240);
    let worst = 0;
    for (let v = 0; v < 4000; v++) {
      let nearest = Infinity;
      for (const k of picks)
        nearest = Math.min(nearest, Math.hypot(p[3 * v] - p[3 * k], p[3 * v + 1] - p[3 * k + 1], p[3 * v + 2] - p[3 * k + 2]));
      worst = Math.max(worst, nearest);
    }
    expect(worst).toBeLessThan(0.03);
  });

  it('carries points that were not fitted onto the new shape within 0.5 mm', () => {
    const base = headCloud(4000, 6);
    const moved = reshape(base);
    const warp = fitIdentityWarp(base, moved);
    const probe = headCloud(300, 7);
    const expected = reshape(probe);
    let worst = 0;
    for (let i = 0; i < 300; i++) {
      const got = warpPoint(warp, [probe[3 * i], probe[3 * i + 1], probe[3 * i + 2]]);
      worst = Math.max(worst, Math.hypot(got[0] - expected[3 * i], got[1] - expected[3 * i + 1], got[2] - expected[3 * i + 2]));
    }
    expect(worst).toBeLessThan(0.0005);
  });

  it('takes every matching vertex exactly onto its place, fitted or not', () => {
    const base = headCloud(2000, 8);
    const moved = reshape(base);
    const warp = fitIdentityWarp(base, moved, 60);
    let worst = 0;
    for (let v = 0; v < 2000; v++) {
      const got = warpPoint(warp, [base[3 * v], base[3 * v + 1], base[3 * v + 2]]);
      worst = Math.max(worst, Math.hypot(got[0] - moved[3 * v], got[1] - moved[3 * v + 1], got[2] - moved[3 * v + 2]));
    }
    expect(worst).toBeLessThan(1e-12);
  });

  it('refuses two heads of different vertex counts', () => {
    expect(() => fitIdentityWarp(new Float64Array(30), new Float64Array(33))).toThrow(/default head has 10 vertices but the identity's 11/);
  });
});
