import { describe, expect, it } from 'vitest';
import { colliderBendingCap } from '../src/core/solver/bending-setup';

// Skin at a collider bends at most a quarter where it is fine (the high head's lips and lids) and more where it is
// coarse (the medium head's skin under the lower lip), going over linearly between 0.8 and 1.2 mm.
describe('the bending cap at the colliders by spacing', () => {
  it('is a quarter for fine skin and 0.4 for coarse skin', () => {
    expect(colliderBendingCap(0.0004)).toBe(0.25);
    expect(colliderBendingCap(0.0008)).toBe(0.25);
    expect(colliderBendingCap(0.0012)).toBeCloseTo(0.4, 12);
    expect(colliderBendingCap(0.003)).toBeCloseTo(0.4, 12);
  });

  it('rises without a step between', () => {
    let last = colliderBendingCap(0.0008);
    for (let h = 0.00081; h <= 0.0012; h += 0.00001) {
      const cap = colliderBendingCap(h);
      expect(cap).toBeGreaterThan(last);
      expect(cap - last).toBeLessThan(0.005);
      last = cap;
    }
    expect(colliderBendingCap(0.001)).toBeCloseTo(0.325, 12);
  });
});
