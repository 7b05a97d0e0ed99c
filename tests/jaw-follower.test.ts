import { describe, expect, it } from 'vitest';
import type { Collider } from '../src/core/solver/colliders';
import { JawFollower } from '../src/core/rig/jaw-follower';
import type { Muscle } from '../src/core/rig/rig-types';

const jaw: Muscle = {
  name: 'jaw',
  side: 'mid',
  type: 'jaw',
  center: [0, 0.63, 0.12],
  rotation: [0, 0, 0],
  size: [0.13, 0.05, 0.11],
  joint: [0, 0.69, 0.065],
  maxAngle: 20,
  curve: 0.1,
  fade: 0.002,
};

function colliders(): Collider[] {
  return [
    { name: 'eye-l', a: [0.03, 0.73, 0.12], radius: 0.015 },
    { name: 'teeth-lower-0', a: [0, 0.64, 0.13], b: [0.01, 0.64, 0.125], up: [0, 0.01, 0], radius: 0.002 },
  ];
}

describe('the lower teeth follow the jaw', () => {
  it('turns the lower-teeth slabs about the jaw hinge by contraction x maxAngle and leaves other colliders alone', () => {
    const c = colliders();
    const follower = JawFollower.create([jaw], c)!;
    follower.update([0.5]);
    const [eye, teeth] = c;
    expect(eye.a).toEqual([0.03, 0.73, 0.12]);
    const angleOf = (p: number[]) => Math.atan2(p[1] - 0.69, p[2] - 0.065);
    const turned = (angleOf([0, 0.64, 0.13]) - angleOf(teeth.a)) * (180 / Math.PI);
    expect(turned).toBeCloseTo(10, 6);
    expect(Math.hypot(teeth.a[1] - 0.69, teeth.a[2] - 0.065)).toBeCloseTo(Math.hypot(0.64 - 0.69, 0.13 - 0.065), 9);
    // The slab keeps its height and stays a rectangle: `up` keeps its length and stays perpendicular to b - a.
    expect(Math.hypot(...teeth.up!)).toBeCloseTo(0.01, 9);
    const ab = [0, 1, 2].map((k) => teeth.b![k] - teeth.a[k]);
    expect(ab[0] * teeth.up![0] + ab[1] * teeth.up![1] + ab[2] * teeth.up![2]).toBeCloseTo(0, 12);
  });

  it('returns the slabs exactly to rest when the jaw relaxes', () => {
    const c = colliders();
    const follower = JawFollower.create([jaw], c)!;
    follower.update([1]);
    follower.update([0]);
    expect(c[1].a[0]).toBeCloseTo(0, 12);
    expect(c[1].a[1]).toBeCloseTo(0.64, 12);
    expect(c[1].a[2]).toBeCloseTo(0.13, 12);
  });

  it('is absent without a jaw muscle or lower teeth', () => {
    expect(JawFollower.create([], colliders())).toBeNull();
    expect(JawFollower.create([jaw], [colliders()[0]])).toBeNull();
  });
});
