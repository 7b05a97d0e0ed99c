import { describe, expect, it } from 'vitest';
import { planTargets, timelineTargets, timelineWeights } from '../src/core/expression/morph-export';
import type { Timeline } from '../src/core/timeline/timeline';
import { checkExportOptions, GLTF_EXPORT_DEFAULTS } from '../src/face/gltf-export-options';

const PRESETS = ['happiness', 'surprise'];

function timeline(partial: Partial<Timeline>): Timeline {
  return { format: 'softface-timeline', version: 1, tracks: {}, actions: [], ...partial };
}

describe('planTargets', () => {
  it('names each Action Unit by its id and each preset by its name, in the order asked', () => {
    expect(planTargets(['AU12', 'AU6L', 'AU17'], ['surprise'], PRESETS, null)).toEqual([
      { name: 'AU12', kind: 'actionUnit', id: 'AU12' },
      { name: 'AU6L', kind: 'actionUnit', id: 'AU6L' },
      { name: 'AU17', kind: 'actionUnit', id: 'AU17' },
      { name: 'surprise', kind: 'preset', id: 'surprise' },
    ]);
  });

  it('refuses an unknown id or preset, one listed twice, and nothing to export, naming the option', () => {
    expect(() => planTargets(['AU99'], [], PRESETS, null)).toThrow(
      /^exportGLTF: actionUnits: expected an Action Unit id like .*, got "AU99"$/,
    );
    expect(() => planTargets([], ['joy'], PRESETS, null)).toThrow(
      /^exportGLTF: presets: expected one of the presets happiness, surprise, got "joy"$/,
    );
    expect(() => planTargets(['AU12', 'AU12'], [], PRESETS, null)).toThrow(/actionUnits: AU12 is listed twice/);
    expect(() => planTargets([], [], PRESETS, null)).toThrow(/exportGLTF: actionUnits and presets are empty and there is no timeline/);
  });

  it('refuses a head position, which turns the whole head, and leaves one out of a timeline’s targets', () => {
    expect(() => planTargets(['AU12', 'AU51'], [], PRESETS, null)).toThrow(
      /^exportGLTF: actionUnits: AU51 is a head position, which turns the whole head rather than shaping the skin; a morph target cannot/,
    );
    const t = timeline({ tracks: { AU53: { keys: [{ time: 0, value: 1 }] }, AU12: { keys: [{ time: 0, value: 1 }] } }, actions: [] });
    expect(timelineTargets(t).map((x) => x.name)).toEqual(['AU12']);
  });

  it("adds the timeline's targets that were not asked for, once", () => {
    const t = timeline({
      tracks: {
        AU12: {
          keys: [
            { time: 0, value: 0 },
            { time: 1, value: 1 },
          ],
        },
      },
      actions: [{ target: 'preset:surprise', start: 0, intensity: 1, onset: 0.2, apex: 0, offset: 0.2 }],
    });
    expect(planTargets(['AU12'], [], PRESETS, t).map((x) => x.name)).toEqual(['AU12', 'surprise']);
    expect(planTargets([], [], PRESETS, t).map((x) => x.name)).toEqual(['AU12', 'surprise']);
  });
});

describe('timelineTargets', () => {
  it('keeps a unit named with both sides as one target, splits a unit named by side into its sides', () => {
    const t = timeline({
      tracks: { AU12: { keys: [{ time: 0, value: 1 }] }, AU6L: { keys: [{ time: 0, value: 1 }] }, AU17: { keys: [{ time: 0, value: 1 }] } },
      actions: [{ target: 'AU6', start: 0, intensity: 1, onset: 1, apex: 0, offset: 1 }],
    });
    expect(timelineTargets(t).map((x) => x.name)).toEqual(['AU12', 'AU6L', 'AU6R', 'AU17']);
  });
});

describe('timelineWeights', () => {
  it("samples at fps up to the duration and gives each target its side's or preset's value", () => {
    const t = timeline({
      tracks: {
        AU12L: {
          keys: [
            { time: 0, value: 0 },
            { time: 1, value: 1 },
          ],
        },
        'preset:happiness': { keys: [{ time: 0, value: 0.5 }] },
      },
    });
    const targets = planTargets(['AU12'], [], PRESETS, t);
    expect(targets.map((x) => x.name)).toEqual(['AU12', 'AU12L', 'AU12R', 'happiness']);
    const w = timelineWeights(t, targets, 4);
    expect(w.duration).toBe(1);
    expect(Array.from(w.times)).toEqual([0, 0.25, 0.5, 0.75, 1]);
    const at = (i: number): number[] => Array.from(w.weights.slice(4 * i, 4 * i + 4));
    // AU12 (both sides) is not in the timeline: it stays 0; AU12L ramps, AU12R stays 0; happiness holds 0.5.
    expect(at(0)).toEqual([0, 0, 0, 0.5]);
    expect(at(2)).toEqual([0, 0.5, 0, 0.5]);
    expect(at(4)).toEqual([0, 1, 0, 0.5]);
  });

  it('ends on the duration when it is not a whole number of frames, and refuses a bad fps', () => {
    const t = timeline({
      tracks: {
        AU17: {
          keys: [
            { time: 0, value: 0 },
            { time: 0.3, value: 1 },
          ],
        },
      },
    });
    const w = timelineWeights(t, timelineTargets(t), 10);
    expect(w.times.length).toBe(4);
    expect(w.times[3]).toBeCloseTo(0.3, 6);
    expect(w.weights[3]).toBeCloseTo(1, 6);
    expect(() => timelineWeights(t, timelineTargets(t), Number.NaN)).toThrow(/fps: expected a number above 0/);
    expect(() => timelineWeights(t, timelineTargets(t), 0)).toThrow(/fps: expected a number above 0/);
  });
});

describe('checkExportOptions', () => {
  it('fills in the defaults and refuses unknown options and bad values, naming them', () => {
    expect(checkExportOptions(undefined)).toEqual(GLTF_EXPORT_DEFAULTS);
    expect(checkExportOptions({ actionUnits: ['AU12'], fps: 24 })).toMatchObject({
      actionUnits: ['AU12'],
      presets: [],
      fps: 24,
      binary: true,
      timeline: null,
    });
    expect(() => checkExportOptions({ actionUnit: ['AU12'] })).toThrow(
      /^exportGLTF: expected one of the options actionUnits, .*, got "actionUnit"$/,
    );
    expect(() => checkExportOptions({ fps: Number.NaN })).toThrow(/exportGLTF: fps: expected a number above 0 and at most 120, got NaN/);
    expect(() => checkExportOptions({ actionUnits: 'AU12' })).toThrow(/exportGLTF: actionUnits: expected an array of strings/);
    expect(() => checkExportOptions({ binary: 'yes' })).toThrow(/exportGLTF: binary: expected true or false/);
    expect(() => checkExportOptions({ signal: {} })).toThrow(/exportGLTF: signal: expected an AbortSignal/);
  });
});
