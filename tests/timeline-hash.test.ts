import { describe, expect, it } from 'vitest';
import { ExpressionState } from '../src/core/expression/facs';
import { createTimelineSample, sampleTimeline, type Timeline } from '../src/core/timeline/timeline';
import { decodeExpression, decodeTimeline, encodeExpression } from '../src/face/expression-hash';

const TIMELINE: Timeline = {
  format: 'softface-timeline',
  version: 1,
  loop: true,
  tracks: {
    AU12: {
      keys: [
        { time: 0, value: 0 },
        { time: 1, value: 0.5, easing: 'ease-in-out' },
      ],
    },
  },
  actions: [{ target: 'preset:happiness', start: 0.2, intensity: 0.7, onset: 0.3, apex: 0, offset: 0.3 }],
};

describe('a timeline in the URL hash', () => {
  it('goes in beside the expression and comes back as the same text; the expression reads as before', () => {
    const text = JSON.stringify(TIMELINE);
    const hash = encodeExpression({ actionUnits: { AU6L: 0.25, AU1R: 0 }, presets: { happiness: 0.5 } }, text);
    expect(hash.startsWith('#AU6L=0.25&preset%3Ahappiness=0.5&timeline=')).toBe(true);
    expect(decodeTimeline(hash)).toBe(text);
    expect(JSON.parse(decodeTimeline(hash)!)).toEqual(TIMELINE);
    expect(decodeExpression(hash)).toEqual({ actionUnits: { AU6L: 0.25 }, presets: { happiness: 0.5 } });
  });

  it('a hash without one has none', () => {
    expect(decodeTimeline('#AU12L=0.5')).toBeNull();
    expect(encodeExpression({ actionUnits: { AU12L: 0.5 }, presets: {} })).toBe('#AU12L=0.5');
  });
});

describe("a timeline frame on the face's expression", () => {
  const presets = [{ name: 'happiness', source: 'test', actionUnits: { AU6: 0.6, AU12: 0.8 } }];

  it('sets the sampled sides and preset weights, and says whether anything changed', () => {
    const state = new ExpressionState(presets);
    state.setActionUnit('AU26', 0.4);
    const sample = createTimelineSample(TIMELINE);
    sampleTimeline(TIMELINE, 0.5, sample);
    const ids = sample.targets.filter((t) => !t.startsWith('preset:'));
    const values = ids.map((id) => sample.values[sample.targets.indexOf(id)]);
    const weight = sample.values[sample.targets.indexOf('preset:happiness')];
    expect(ids).toEqual(['AU12L', 'AU12R']);
    expect(state.setFrame(ids, values, ['happiness'], [weight])).toBe(true);
    expect(state.getActionUnits()).toMatchObject({ AU12L: 0.25, AU12R: 0.25, AU26: 0.4 });
    expect(state.listPresets()[0].weight).toBeCloseTo(0.7, 12);
    // The same frame again changes nothing.
    expect(state.setFrame(ids, values, ['happiness'], [weight])).toBe(false);
    expect(state.effective().AU12L).toBeCloseTo(Math.min(1, 0.25 + 0.7 * 0.8), 12);
  });

  it('skips presets and ids the face does not have, and non-finite values', () => {
    const state = new ExpressionState(presets);
    expect(state.setFrame(['AU99', 'AU12L'], [1, Number.NaN], ['joy'], [1])).toBe(false);
    expect(Object.values(state.getActionUnits()).every((v) => v === 0)).toBe(true);
    expect(state.setFrame(['AU17'], [1.5], [], [])).toBe(true);
    expect(state.getActionUnits().AU17).toBe(1);
  });
});
