import { describe, expect, it } from 'vitest';
import { HeldPicture } from '../src/face/held-picture';

describe('HeldPicture: whether a recording repeats its last picture', () => {
  it('draws the first picture, then repeats it while the solver sleeps and the expression holds', () => {
    const held = new HeldPicture();
    expect(held.same(40, { AU1: 0, AU12: 0.5 })).toBe(false);
    expect(held.same(40, { AU1: 0, AU12: 0.5 })).toBe(true);
    expect(held.same(40, { AU1: 0, AU12: 0.5 })).toBe(true);
  });

  it('draws again when the solver solved a frame, or when any intensity moved, however little', () => {
    const held = new HeldPicture();
    held.same(40, { AU1: 0, AU12: 0.5 });
    expect(held.same(46, { AU1: 0, AU12: 0.5 })).toBe(false);
    expect(held.same(46, { AU1: 1e-9, AU12: 0.5 })).toBe(false);
    expect(held.same(46, { AU1: 1e-9, AU12: 0.5 })).toBe(true);
    expect(held.same(46, { AU1: 1e-9 })).toBe(false);
  });

  it('draws again after something else the picture shows changed (light, camera, appearance)', () => {
    const held = new HeldPicture();
    held.same(40, { AU12: 1 });
    held.invalidate();
    expect(held.same(40, { AU12: 1 })).toBe(false);
    expect(held.same(40, { AU12: 1 })).toBe(true);
  });
});
