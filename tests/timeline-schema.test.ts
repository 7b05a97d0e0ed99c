import { describe, expect, it } from 'vitest';
import { MAX_TIMELINE_ACTIONS, parseTimeline, parseTimelineText, TimelineError, timelineText } from '../src/core/timeline/timeline-schema';

// biome-ignore lint/suspicious/noExplicitAny: the tests spoil fields at any depth, with any value
type Doc = Record<string, any>;

/** A valid document with a track per kind of target and an action; tests spoil one field of a fresh copy. */
function doc(): Doc {
  return {
    format: 'softface-timeline',
    version: 1,
    duration: 6,
    loop: true,
    tracks: {
      AU12L: {
        keys: [
          { time: 0, value: 0 },
          { time: 1, value: 0.8, easing: 'ease-in-out' },
          { time: 2, value: 0.2 },
        ],
      },
      AU26: { keys: [{ time: 0.5, value: 0.3 }] },
      'preset:happiness': {
        keys: [
          { time: 0, value: 0 },
          { time: 3, value: 1, easing: 'ease-out' },
        ],
      },
    },
    actions: [{ target: 'AU6', start: 1, intensity: 0.6, onset: 0.4, apex: 1, offset: 0.8 }],
  };
}

const PRESETS = ['happiness', 'sadness'];

function rejection(mutate: (d: Doc) => void, presets: readonly string[] | null = PRESETS): TimelineError {
  const d = doc();
  mutate(d);
  try {
    parseTimeline(d, 'test', { presets });
  } catch (e) {
    expect(e).toBeInstanceOf(TimelineError);
    return e as TimelineError;
  }
  throw new Error('the document was accepted');
}

describe('a valid timeline', () => {
  it('parses to the same document, and round-trips through its text', () => {
    const t = parseTimeline(doc(), 'test', { presets: PRESETS });
    expect(t).toEqual(doc());
    expect(parseTimelineText(timelineText(t), 'text', { presets: PRESETS })).toEqual(t);
  });

  it('fills in the version, tracks and actions when left out; duration and loop stay unset', () => {
    const t = parseTimeline({ format: 'softface-timeline' });
    expect(t).toEqual({ format: 'softface-timeline', version: 1, tracks: {}, actions: [] });
  });

  it('accepts any preset name when no presets are given', () => {
    expect(() =>
      parseTimeline({ format: 'softface-timeline', tracks: { 'preset:whatever': { keys: [{ time: 0, value: 1 }] } } }),
    ).not.toThrow();
  });
});

describe('refusals name the path of what is wrong', () => {
  it('an unknown Action Unit id as a track or action target', () => {
    expect(rejection((d) => (d.tracks.AU99 = { keys: [{ time: 0, value: 1 }] })).message).toMatch(
      /^test: tracks\.AU99: expected an Action Unit id like .* or "preset:<name>", got "AU99"/,
    );
    expect(rejection((d) => (d.tracks.AU17L = { keys: [{ time: 0, value: 1 }] })).message).toMatch(
      /tracks\.AU17L: expected an Action Unit id like .*, got "AU17L"/,
    );
    expect(rejection((d) => (d.actions[0].target = 'smile')).message).toMatch(
      /^test: actions\[0\]\.target: expected an Action Unit id like .*, got "smile"/,
    );
  });

  it('an unknown preset, with the names the face has', () => {
    const e = rejection((d) => (d.tracks['preset:joy'] = { keys: [{ time: 0, value: 1 }] }));
    expect(e.message).toBe('test: tracks["preset:joy"]: expected one of the presets happiness, sadness, got "joy"');
    expect(e.problems).toEqual([{ path: 'tracks["preset:joy"]', message: 'expected one of the presets happiness, sadness, got "joy"' }]);
  });

  it('NaN, infinite and non-number values', () => {
    expect(rejection((d) => (d.tracks.AU12L.keys[1].value = Number.NaN)).message).toMatch(
      /tracks\.AU12L\.keys\[1\]\.value: expected a number, got NaN/,
    );
    expect(rejection((d) => (d.actions[0].start = Number.POSITIVE_INFINITY)).message).toMatch(
      /actions\[0\]\.start: expected a finite number, got Infinity/,
    );
    expect(rejection((d) => (d.tracks.AU26.keys[0].time = '1')).message).toMatch(
      /tracks\.AU26\.keys\[0\]\.time: expected a number, got "1"/,
    );
  });

  it('values out of 0..1', () => {
    expect(rejection((d) => (d.tracks.AU12L.keys[2].value = 1.2)).message).toMatch(
      /tracks\.AU12L\.keys\[2\]\.value: expected a number from 0 to 1, got 1\.2/,
    );
    expect(rejection((d) => (d.actions[0].intensity = -0.1)).message).toMatch(
      /actions\[0\]\.intensity: expected a number from 0 to 1, got -0\.1/,
    );
  });

  it('negative times and durations, and a zero onset or offset', () => {
    expect(rejection((d) => (d.tracks.AU12L.keys[0].time = -1)).message).toMatch(
      /tracks\.AU12L\.keys\[0\]\.time: expected a time from 0 to 3600 s, got -1/,
    );
    expect(rejection((d) => (d.actions[0].apex = -0.5)).message).toMatch(/actions\[0\]\.apex: expected a time from 0 to 3600 s, got -0\.5/);
    expect(rejection((d) => (d.actions[0].onset = 0)).message).toMatch(/actions\[0\]\.onset: expected a positive number of seconds/);
    expect(rejection((d) => (d.actions[0].offset = -2)).message).toMatch(/actions\[0\]\.offset: expected a positive number of seconds/);
    expect(rejection((d) => (d.duration = -3)).message).toMatch(/^test: duration: expected a positive number of seconds/);
  });

  it('key times out of order or duplicated', () => {
    const unsorted = rejection((d) => (d.tracks.AU12L.keys[2].time = 0.5));
    expect(unsorted.message).toBe(
      "test: tracks.AU12L.keys[2].time: keys out of order: expected a time after the previous key's 1 s, got 0.5",
    );
    const duplicate = rejection((d) => (d.tracks['preset:happiness'].keys[1].time = 0));
    expect(duplicate.message).toBe(
      'test: tracks["preset:happiness"].keys[1].time: a duplicate key time: expected a time after the previous key\'s 0 s, got 0',
    );
  });

  it('a duration shorter than the content', () => {
    expect(rejection((d) => (d.duration = 2.5)).message).toBe(
      'test: duration: expected at least 3.2 s (the end of the last key or action), got 2.5',
    );
  });

  it('unknown fields, wrong kinds and missing parts', () => {
    expect(rejection((d) => (d.tracks.AU12L.keys[0].ease = 'linear')).message).toMatch(/tracks\.AU12L\.keys\[0\]\.ease: unknown field/);
    expect(rejection((d) => (d.tracks.AU12L.keys[0].easing = 'bounce')).message).toMatch(
      /keys\[0\]\.easing: expected an easing: "linear", "ease-in", "ease-out", "ease-in-out", got "bounce"/,
    );
    expect(rejection((d) => (d.tracks.AU26.keys = [])).message).toMatch(/tracks\.AU26\.keys: expected at least one key/);
    expect(rejection((d) => delete d.actions[0].apex).message).toMatch(/actions\[0\]\.apex: missing/);
    expect(rejection((d) => (d.loop = 'yes')).message).toMatch(/loop: expected true or false, got "yes"/);
    expect(rejection((d) => (d.format = 'softface-rig')).message).toMatch(/format: expected "softface-timeline", got "softface-rig"/);
    expect(rejection((d) => (d.tracks = [])).message).toMatch(/tracks: expected an object of tracks/);
  });

  it('lists every problem at once', () => {
    const e = rejection((d) => {
      d.tracks.AU99 = { keys: [{ time: 0, value: 1 }] };
      d.tracks.AU12L.keys[1].value = 2;
      d.actions[0].onset = -1;
    });
    expect(e.problems.map((p) => p.path).sort()).toEqual(['actions[0].onset', 'tracks.AU12L.keys[1].value', 'tracks.AU99']);
  });

  it('too many actions, before the schema reads them', () => {
    const action = { target: 'AU1', start: 0, intensity: 1, onset: 1, apex: 0, offset: 1 };
    const e = rejection((d) => (d.actions = Array.from({ length: MAX_TIMELINE_ACTIONS + 1 }, () => action)));
    expect(e.message).toBe(`test: actions: expected at most ${MAX_TIMELINE_ACTIONS} actions, got ${MAX_TIMELINE_ACTIONS + 1}`);
  });
});

describe('timeline text', () => {
  it('a JSON syntax error says where', () => {
    expect(() => parseTimelineText('{"format": "softface-timeline",}', 'file.json')).toThrow(
      /^file\.json: invalid JSON at line 1, column 32: expected a property name in double quotes, got '}'$/,
    );
  });

  it('text that is not a document is refused', () => {
    expect(() => parseTimelineText(42 as unknown as string, 'x')).toThrow(/x: expected the text of a JSON document, got 42/);
    expect(() => parseTimelineText('[1, 2]', 'x')).toThrow(/x: expected a timeline document \(a JSON object\), got \[1,2\]/);
  });
});
