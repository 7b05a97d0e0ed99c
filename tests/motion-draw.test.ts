import { describe, expect, it } from 'vitest';
import { MOTION_END_MS, motionDraw, type MotionDrawState } from '../src/render/motion-draw';

/** Software WebGL: a full draw held the next animation frame back 190 ms, the motion drawn at half resolution. */
const slow = (changes: Partial<MotionDrawState>): MotionDrawState => ({
  changed: false,
  reduced: false,
  sinceChangeMs: 0,
  fullDrawMs: 190,
  motionResolution: 0.5,
  slowDrawMs: 50,
  ...changes,
});

describe('the render loop choosing a resolution (motionDraw)', () => {
  it('draws a changing picture lower where full draws are slow, and at full where they keep up or the option is 1', () => {
    expect(motionDraw(slow({ changed: true }))).toBe('reduced');
    expect(motionDraw(slow({ changed: true, reduced: true }))).toBe('reduced');
    expect(motionDraw(slow({ changed: true, fullDrawMs: 16 }))).toBe('full');
    expect(motionDraw(slow({ changed: true, motionResolution: 1 }))).toBe('full');
  });

  it('draws nothing when nothing is new and the picture is at full resolution', () => {
    expect(motionDraw(slow({ sinceChangeMs: 5_000 }))).toBe('skip');
  });

  it('keeps the lower resolution through an animation frame that comes before the next solver frame', () => {
    // Two animation frames 4 ms apart while the skin moves: the second has nothing new.
    expect(motionDraw(slow({ reduced: true, sinceChangeMs: 4 }))).toBe('skip');
    expect(motionDraw(slow({ reduced: true, sinceChangeMs: MOTION_END_MS - 1 }))).toBe('skip');
  });

  it('draws the picture again at full resolution once nothing new has come for MOTION_END_MS', () => {
    expect(motionDraw(slow({ reduced: true, sinceChangeMs: MOTION_END_MS }))).toBe('full');
  });
});
