import { describe, expect, it } from 'vitest';
import { MOTION_END_MS, MOTION_STALL_MS, motionDraw, type MotionDrawState } from '../src/render/motion-draw';

/** Software WebGL: a full draw held the next animation frame back 190 ms, the motion drawn at half resolution. */
const slow = (changes: Partial<MotionDrawState>): MotionDrawState => ({
  changed: false,
  reduced: false,
  sinceChangeMs: 0,
  moving: false,
  fullDrawMs: 190,
  motionResolution: 0.5,
  slowDrawMs: 50,
  empty: false,
  drawnSinceChange: false,
  fresh: false,
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

  it('keeps the lower resolution while more of the motion is coming, however slowly, and gives up on a stalled solver', () => {
    expect(motionDraw(slow({ reduced: true, moving: true, sinceChangeMs: MOTION_END_MS }))).toBe('skip');
    expect(motionDraw(slow({ reduced: true, moving: true, sinceChangeMs: MOTION_STALL_MS - 1 }))).toBe('skip');
    expect(motionDraw(slow({ reduced: true, moving: true, sinceChangeMs: MOTION_STALL_MS }))).toBe('full');
  });

  it('draws a head just set once, as the finished picture, whatever the changes around it', () => {
    expect(motionDraw(slow({ fresh: true, changed: true }))).toBe('still');
    expect(motionDraw(slow({ fresh: true, changed: true, fullDrawMs: 16 }))).toBe('still');
    expect(motionDraw(slow({ fresh: true, reduced: true, sinceChangeMs: 4 }))).toBe('still');
  });

  it('draws the background alone once for each change, at full resolution, where draws are slow', () => {
    expect(motionDraw(slow({ empty: true, changed: true }))).toBe('full');
    expect(motionDraw(slow({ empty: true, changed: true, drawnSinceChange: true }))).toBe('skip');
    expect(motionDraw(slow({ empty: true, reduced: true, sinceChangeMs: MOTION_END_MS }))).toBe('skip');
  });
});
