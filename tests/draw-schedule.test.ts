import { describe, expect, it } from 'vitest';
import { DrawSchedule } from '../src/render/draw-schedule';

/** Software WebGL: full draws hold the next frame back 190 ms, motion drawn at half resolution. */
const SLOW = 190;

describe('the view’s draw schedule (DrawSchedule)', () => {
  it('draws a head just set once, as a still, and nothing more until something changes', () => {
    const s = new DrawSchedule(0.5, 50);
    s.invalidate();
    s.headSet();
    expect(s.choose(0, false, false, false, false, true, SLOW)).toBe('still');
    // The change's frames were caught by the still.
    expect(s.choose(16, false, false, false, false, true, SLOW)).toBe('skip');
    expect(s.choose(32, false, false, false, false, true, SLOW)).toBe('skip');
  });

  it('draws a moving skin lower where draws are slow, then its still once the motion has ended', () => {
    const s = new DrawSchedule(0.5, 50);
    s.headSet();
    expect(s.choose(0, false, false, false, false, true, SLOW)).toBe('still');
    expect(s.choose(16, true, false, false, false, true, SLOW)).toBe('reduced');
    expect(s.choose(32, false, false, false, true, true, SLOW)).toBe('skip');
    expect(s.choose(200, false, false, false, true, true, SLOW)).toBe('still');
  });

  it('keeps a moving skin lower while a hook says more is coming, however long its frames take', () => {
    const s = new DrawSchedule(0.5, 50);
    s.headSet();
    expect(s.choose(0, false, false, false, false, true, SLOW)).toBe('still');
    expect(s.choose(16, true, false, false, false, true, SLOW)).toBe('reduced');
    // A loaded machine: the solver's next frame comes 400 ms later.
    expect(s.choose(200, false, false, true, true, true, SLOW)).toBe('skip');
    expect(s.choose(416, true, false, false, true, true, SLOW)).toBe('reduced');
    // That frame was the settled one: nothing more is coming.
    expect(s.choose(600, false, false, false, true, true, SLOW)).toBe('still');
  });

  it('waits while a hook holds the frame, and draws the held change after', () => {
    const s = new DrawSchedule(0.5, 50);
    s.headSet();
    expect(s.choose(0, false, false, false, false, true, SLOW)).toBe('still');
    expect(s.choose(16, true, true, false, false, true, SLOW)).toBe('skip');
    expect(s.choose(32, false, false, false, false, true, SLOW)).toBe('reduced');
  });

  it('draws the background alone once for each change, at full resolution', () => {
    const s = new DrawSchedule(0.5, 50);
    s.invalidate();
    expect(s.choose(0, false, false, false, false, false, SLOW)).toBe('full');
    expect(s.choose(16, false, false, false, false, false, SLOW)).toBe('skip');
    s.invalidate();
    expect(s.choose(32, false, false, false, false, false, SLOW)).toBe('full');
  });
});
