import { describe, expect, it } from 'vitest';
import {
  actionValue,
  createTimelineSample,
  ease,
  expandAction,
  localTime,
  sampleTimeline,
  targetSides,
  timelineDuration,
  type Timeline,
  type TimelineAction,
} from '../src/core/timeline/timeline';

function timeline(partial: Partial<Timeline>): Timeline {
  return { format: 'softface-timeline', version: 1, tracks: {}, actions: [], ...partial };
}

/** Every target's value at `seconds`, by target. */
function sampleAt(t: Timeline, seconds: number): Record<string, number> {
  const out = createTimelineSample(t);
  sampleTimeline(t, seconds, out);
  return Object.fromEntries(out.targets.map((id, i) => [id, out.values[i]]));
}

describe('easing', () => {
  it('every easing runs from 0 to 1 and clamps outside the segment', () => {
    for (const e of ['linear', 'ease-in', 'ease-out', 'ease-in-out'] as const) {
      expect(ease(e, 0)).toBe(0);
      expect(ease(e, 1)).toBe(1);
      expect(ease(e, -0.5)).toBe(0);
      expect(ease(e, 1.5)).toBe(1);
    }
  });

  it('linear is the identity; ease-in starts slow, ease-out fast; ease-in-out is symmetric about the middle', () => {
    expect(ease('linear', 0.3)).toBeCloseTo(0.3, 12);
    expect(ease('ease-in', 0.5)).toBeCloseTo(0.125, 12);
    expect(ease('ease-out', 0.5)).toBeCloseTo(0.875, 12);
    expect(ease('ease-in-out', 0.5)).toBeCloseTo(0.5, 12);
    expect(ease('ease-in-out', 0.25)).toBeCloseTo(0.0625, 12);
    for (const u of [0.1, 0.2, 0.35, 0.45]) expect(ease('ease-in-out', u) + ease('ease-in-out', 1 - u)).toBeCloseTo(1, 12);
  });

  it('every easing is monotonic', () => {
    for (const e of ['linear', 'ease-in', 'ease-out', 'ease-in-out'] as const) {
      let previous = -1;
      for (let i = 0; i <= 100; i++) {
        const v = ease(e, i / 100);
        expect(v).toBeGreaterThanOrEqual(previous);
        previous = v;
      }
    }
  });
});

describe('keyframe tracks', () => {
  const t = timeline({
    tracks: {
      AU12L: {
        keys: [
          { time: 1, value: 0.2 },
          { time: 2, value: 0.6, easing: 'ease-in' },
          { time: 4, value: 1, easing: 'ease-in-out' },
          { time: 5, value: 0 },
        ],
      },
    },
  });

  it('holds the first value before the first key and the last after the last', () => {
    expect(sampleAt(t, 0).AU12L).toBeCloseTo(0.2, 12);
    expect(sampleAt(t, 5).AU12L).toBe(0);
  });

  it('hits every key exactly', () => {
    expect(sampleAt(t, 1).AU12L).toBeCloseTo(0.2, 12);
    expect(sampleAt(t, 2).AU12L).toBeCloseTo(0.6, 12);
    expect(sampleAt(t, 4).AU12L).toBeCloseTo(1, 12);
  });

  it("uses the easing of the segment's first key (linear when it has none)", () => {
    // 1..2 linear from 0.2 to 0.6.
    expect(sampleAt(t, 1.5).AU12L).toBeCloseTo(0.4, 12);
    // 2..4 ease-in from 0.6 to 1: a quarter of the way at the middle is 0.6 + 0.4 * 0.125.
    expect(sampleAt(t, 3).AU12L).toBeCloseTo(0.6 + 0.4 * 0.125, 12);
    // 4..5 ease-in-out from 1 to 0: a quarter of the way is 1 - 4 * 0.25^3.
    expect(sampleAt(t, 4.25).AU12L).toBeCloseTo(1 - 0.0625, 12);
  });

  it('a track on a bilateral unit without a side sets both sides, and adds to a side track', () => {
    const both = timeline({
      tracks: {
        AU6: { keys: [{ time: 0, value: 0.3 }] },
        AU6L: { keys: [{ time: 0, value: 0.5 }] },
        AU17: { keys: [{ time: 0, value: 0.4 }] },
        'preset:happiness': { keys: [{ time: 0, value: 0.9 }] },
      },
    });
    const s = sampleAt(both, 0);
    expect(s).toEqual({
      AU6L: expect.closeTo(0.8, 12),
      AU6R: expect.closeTo(0.3, 12),
      AU17: expect.closeTo(0.4, 12),
      'preset:happiness': expect.closeTo(0.9, 12),
    });
    expect(targetSides('AU12')).toEqual(['AU12L', 'AU12R']);
    expect(targetSides('AU12R')).toEqual(['AU12R']);
    expect(targetSides('AU26')).toEqual(['AU26']);
    expect(targetSides('preset:anger')).toEqual(['preset:anger']);
  });

  it('clamps sums over 1', () => {
    const over = timeline({
      tracks: { AU12: { keys: [{ time: 0, value: 0.8 }] } },
      actions: [{ target: 'AU12L', start: 0, intensity: 0.9, onset: 1, apex: 1, offset: 1 }],
    });
    expect(sampleAt(over, 1.5)).toEqual({ AU12L: 1, AU12R: expect.closeTo(0.8, 12) });
  });
});

describe('onset / apex / offset actions', () => {
  const a: TimelineAction = { target: 'AU12', start: 1, intensity: 0.8, onset: 0.5, apex: 2, offset: 1 };

  it('is 0 before the start, rises over the onset, holds at the apex, falls over the offset and is 0 after', () => {
    expect(actionValue(a, 0.99)).toBe(0);
    expect(actionValue(a, 1)).toBe(0);
    expect(actionValue(a, 1.25)).toBeCloseTo(0.4, 12);
    expect(actionValue(a, 1.5)).toBeCloseTo(0.8, 12);
    expect(actionValue(a, 2.5)).toBeCloseTo(0.8, 12);
    expect(actionValue(a, 3.5)).toBeCloseTo(0.8, 12);
    expect(actionValue(a, 4)).toBeCloseTo(0.4, 12);
    expect(actionValue(a, 4.5)).toBe(0);
    expect(actionValue(a, 10)).toBe(0);
  });

  it('rises and falls smoothly (ease-in-out): slow near the ends of each ramp', () => {
    const early = actionValue(a, 1.05) - actionValue(a, 1);
    const middle = actionValue(a, 1.3) - actionValue(a, 1.25);
    expect(early).toBeLessThan(middle / 5);
    for (let t = 1; t < 1.5; t += 0.01) expect(actionValue(a, t + 0.01)).toBeGreaterThanOrEqual(actionValue(a, t));
    for (let t = 3.5; t < 4.5; t += 0.01) expect(actionValue(a, t + 0.01)).toBeLessThanOrEqual(actionValue(a, t));
  });

  it('samples the same as the keys it expands to', () => {
    for (const action of [a, { ...a, apex: 0 }]) {
      const direct = timeline({ actions: [action], duration: 6 });
      const keyed = timeline({ tracks: { AU12: { keys: expandAction(action) } }, duration: 6 });
      for (let t = 0; t <= 6; t += 0.05) expect(sampleAt(keyed, t).AU12L).toBeCloseTo(sampleAt(direct, t).AU12L, 12);
    }
    expect(expandAction(a).map((k) => [k.time, k.value])).toEqual([
      [1, 0],
      [1.5, 0.8],
      [3.5, 0.8],
      [4.5, 0],
    ]);
  });

  it('two actions on one target add up', () => {
    const t = timeline({ actions: [a, { ...a, start: 3, intensity: 0.1 }] });
    expect(sampleAt(t, 3.5).AU12L).toBeCloseTo(0.9, 12);
  });
});

describe('duration, looping and time', () => {
  const keys = {
    AU26: {
      keys: [
        { time: 0, value: 0 },
        { time: 2, value: 1 },
      ],
    },
  };

  it('the duration is the end of the last key or action unless given', () => {
    expect(timelineDuration(timeline({ tracks: keys }))).toBe(2);
    expect(
      timelineDuration(timeline({ tracks: keys, actions: [{ target: 'AU1', start: 1, intensity: 1, onset: 1, apex: 1, offset: 1.5 }] })),
    ).toBe(4.5);
    expect(timelineDuration(timeline({ tracks: keys, duration: 3 }))).toBe(3);
    expect(timelineDuration(timeline({}))).toBe(0);
  });

  it('without loop, time is clamped to 0..duration', () => {
    const t = timeline({ tracks: keys, duration: 3 });
    expect(localTime(t, -1)).toBe(0);
    expect(localTime(t, 1.5)).toBe(1.5);
    expect(localTime(t, 7)).toBe(3);
    expect(sampleAt(t, 7).AU26).toBe(1);
  });

  it('with loop, time wraps around the duration', () => {
    const t = timeline({ tracks: keys, duration: 4, loop: true });
    expect(localTime(t, 5)).toBeCloseTo(1, 12);
    expect(localTime(t, 8)).toBe(0);
    expect(localTime(t, -1)).toBeCloseTo(3, 12);
    expect(sampleAt(t, 5).AU26).toBeCloseTo(0.5, 12);
    expect(sampleAt(t, 9.5).AU26).toBeCloseTo(0.75, 12);
  });

  it('sampling reports the time it sampled, refuses a non-finite time and a sample made for another timeline', () => {
    const t = timeline({ tracks: keys, loop: true });
    const out = createTimelineSample(t);
    expect(sampleTimeline(t, 3, out)).toBeCloseTo(1, 12);
    expect(out.time).toBeCloseTo(1, 12);
    expect(() => sampleTimeline(t, Number.NaN, out)).toThrow(/finite time, got NaN/);
    const other = timeline({ tracks: keys });
    expect(() => sampleTimeline(other, 1, out)).toThrow(/another timeline/);
  });
});
