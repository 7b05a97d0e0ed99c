/**
 * Reading timeline documents (`timeline.ts`) from JSON: a valibot schema for the shape and ranges, and checks across
 * fields (known targets, keys in increasing time, a duration that holds the content), each problem named with its
 * path (`tracks.AU12L.keys[2].time: ...`), as rig documents are.
 */

import * as v from 'valibot';
import { isActionUnitId } from '../expression/facs';
import { jsonSyntaxMessage, utf8Length } from '../rig/json-text';
import { ACTION_UNIT_ID, show as showValue } from '../check';
import { pathStep, problemOf, type RigProblem } from '../rig/rig-problems';
import { EASINGS, PRESET_TARGET_PREFIX, TIMELINE_FORMAT, TIMELINE_VERSION, type Timeline } from './timeline';

/** Largest timeline document `parseTimelineText` accepts, in bytes of UTF-8. */
const MAX_TIMELINE_BYTES = 1024 * 1024;
/** Most tracks, keys per track and actions a timeline may hold. */
const MAX_TIMELINE_TRACKS = 128;
const MAX_TIMELINE_KEYS = 4096;
export const MAX_TIMELINE_ACTIONS = 4096;
/** Longest timeline, in seconds: an hour. */
const MAX_TIMELINE_SECONDS = 3600;

/** At most this many problems are spelled out in an error's message; `TimelineError.problems` has them all. */
const MAX_LISTED_PROBLEMS = 50;

/** One problem in a timeline document: where (`tracks.AU12L.keys[2].time`, or '' for the whole) and what is wrong. */
export type TimelineProblem = RigProblem;

/** A timeline document that was refused: its message has one line per problem, `source: path: what is wrong`. */
export class TimelineError extends Error {
  /**
   * The refused document's name, which starts each line of the message: the `source` given to `setTimeline` (such as
   * a file's name), or `setTimeline` when none was.
   */
  readonly source: string;
  /** Every problem found, each with its path and message (the message spells out at most the first 50). */
  readonly problems: readonly TimelineProblem[];

  constructor(source: string, problems: readonly TimelineProblem[]) {
    const lines = problems
      .slice(0, MAX_LISTED_PROBLEMS)
      .map((p) => (p.path ? `${source}: ${p.path}: ${p.message}` : `${source}: ${p.message}`));
    if (problems.length > lines.length) lines.push(`${source}: and ${problems.length - lines.length} more problems`);
    super(lines.join('\n'));
    this.name = 'TimelineError';
    this.source = source;
    this.problems = problems;
  }
}

/** What a timeline is checked against beyond its own shape. */
export interface TimelineCheckOptions {
  /** The preset names `preset:<name>` targets may use (a face's rig's); null accepts any name. */
  presets?: readonly string[] | null;
}

const TIMELINE_CHECK_DEFAULTS: Required<TimelineCheckOptions> = { presets: null };

type Obj = Record<string, unknown>;

const isObj = (x: unknown): x is Obj => typeof x === 'object' && x !== null && !Array.isArray(x);

// ---------------------------------------------------------------------------------------------------------------
// The schema. Every message starts with "expected ..."; the formatter adds what was found.

const number = v.pipe(v.number('expected a number'), v.finite('expected a finite number'));
const seconds = v.pipe(
  number,
  v.minValue(0, `expected a time from 0 to ${MAX_TIMELINE_SECONDS} s`),
  v.maxValue(MAX_TIMELINE_SECONDS, `expected a time from 0 to ${MAX_TIMELINE_SECONDS} s`),
);
const positiveSeconds = v.pipe(
  number,
  v.gtValue(0, `expected a positive number of seconds, at most ${MAX_TIMELINE_SECONDS}`),
  v.maxValue(MAX_TIMELINE_SECONDS, `expected a positive number of seconds, at most ${MAX_TIMELINE_SECONDS}`),
);
const fraction = v.pipe(number, v.minValue(0, 'expected a number from 0 to 1'), v.maxValue(1, 'expected a number from 0 to 1'));
const target = v.pipe(
  v.string('expected a target: an Action Unit id like "AU12L" or "preset:<name>"'),
  v.maxLength(220, 'expected at most 220 characters'),
);
const object = 'expected an object';

/** A strict object that is not an array (valibot takes arrays as objects, and would report missing fields). */
function plainObject<const E extends v.ObjectEntries>(entries: E, message: string) {
  return v.pipe(v.custom<Obj>(isObj, message), v.strictObject(entries, message));
}

const KeySchema = plainObject(
  {
    time: seconds,
    value: fraction,
    easing: v.optional(v.picklist(EASINGS, `expected an easing: ${EASINGS.map((e) => `"${e}"`).join(', ')}`)),
  },
  'expected a key { "time": seconds, "value": 0..1 }',
);

const TrackSchema = plainObject(
  {
    keys: v.pipe(
      v.array(KeySchema, 'expected an array of keys'),
      v.minLength(1, 'expected at least one key'),
      v.maxLength(MAX_TIMELINE_KEYS, `expected at most ${MAX_TIMELINE_KEYS} keys`),
    ),
  },
  'expected a track { "keys": [...] }',
);

const ActionSchema = plainObject(
  {
    target,
    start: seconds,
    intensity: fraction,
    onset: positiveSeconds,
    apex: seconds,
    offset: positiveSeconds,
  },
  'expected an action { "target", "start", "intensity", "onset", "apex", "offset" }',
);

/** The shape of a timeline document; `parseTimeline` adds the checks across fields. */
const TimelineSchema = plainObject(
  {
    format: v.literal(TIMELINE_FORMAT, `expected "${TIMELINE_FORMAT}"`),
    version: v.optional(v.literal(TIMELINE_VERSION, `expected version ${TIMELINE_VERSION}`), TIMELINE_VERSION),
    duration: v.optional(positiveSeconds),
    loop: v.optional(v.boolean('expected true or false')),
    tracks: v.optional(
      v.pipe(
        v.custom<Obj>(isObj, 'expected an object of tracks by target, like { "AU12": { "keys": [...] } }'),
        v.record(v.string(), TrackSchema, object),
      ),
      {},
    ),
    actions: v.optional(
      v.pipe(
        v.array(ActionSchema, 'expected an array of actions'),
        v.maxLength(MAX_TIMELINE_ACTIONS, `expected at most ${MAX_TIMELINE_ACTIONS} actions`),
      ),
      [],
    ),
  },
  'expected a timeline document (a JSON object)',
);

// ---------------------------------------------------------------------------------------------------------------
// Parsing.

/**
 * Checks a timeline document (parsed JSON) and returns it as a `Timeline` (a new object: `version`, `tracks` and
 * `actions` filled in when left out); throws a `TimelineError` listing every problem.
 */
export function parseTimeline(input: unknown, source = 'timeline', options: TimelineCheckOptions = {}): Timeline {
  const o = { ...TIMELINE_CHECK_DEFAULTS, ...options };
  // Cheap refusals before the schema walks anything: a list far over its limit is not read item by item.
  if (isObj(input)) {
    const over: TimelineProblem[] = [];
    if (Array.isArray(input.actions) && input.actions.length > MAX_TIMELINE_ACTIONS) {
      over.push({ path: 'actions', message: `expected at most ${MAX_TIMELINE_ACTIONS} actions, got ${input.actions.length}` });
    }
    if (isObj(input.tracks) && Object.keys(input.tracks).length > MAX_TIMELINE_TRACKS) {
      over.push({ path: 'tracks', message: `expected at most ${MAX_TIMELINE_TRACKS} tracks, got ${Object.keys(input.tracks).length}` });
    }
    if (over.length > 0) throw new TimelineError(source, over);
  }
  const result = v.safeParse(TimelineSchema, input, { abortPipeEarly: true });
  const problems = result.success ? [] : result.issues.map(problemOf);
  problems.push(...crossChecks(input, o.presets));
  if (!result.success || problems.length > 0) throw new TimelineError(source, problems);
  const t = result.output;
  const out: Timeline = { format: TIMELINE_FORMAT, version: TIMELINE_VERSION, tracks: {}, actions: [] };
  if (t.duration !== undefined) out.duration = t.duration;
  if (t.loop !== undefined) out.loop = t.loop;
  for (const [name, track] of Object.entries(t.tracks)) {
    out.tracks[name] = {
      keys: track.keys.map((k) =>
        k.easing === undefined ? { time: k.time, value: k.value } : { time: k.time, value: k.value, easing: k.easing },
      ),
    };
  }
  out.actions = t.actions.map((a) => ({
    target: a.target,
    start: a.start,
    intensity: a.intensity,
    onset: a.onset,
    apex: a.apex,
    offset: a.offset,
  }));
  return out;
}

/** Parses a timeline document from JSON text, refusing texts over `MAX_TIMELINE_BYTES`; throws a `TimelineError`. */
export function parseTimelineText(text: string, source = 'timeline', options: TimelineCheckOptions = {}): Timeline {
  if (typeof text !== 'string')
    throw new TimelineError(source, [{ path: '', message: `expected the text of a JSON document, got ${showValue(text)}` }]);
  const bytes = utf8Length(text);
  if (bytes > MAX_TIMELINE_BYTES) {
    throw new TimelineError(source, [
      { path: '', message: `the document is ${bytes} bytes, over the limit of ${MAX_TIMELINE_BYTES} bytes for timeline documents` },
    ]);
  }
  // Editors may save a byte-order mark, which JSON.parse refuses.
  const body = text.charCodeAt(0) === 0xfeff ? text.slice(1) : text;
  let json: unknown;
  try {
    json = JSON.parse(body);
  } catch (e) {
    throw new TimelineError(source, [{ path: '', message: jsonSyntaxMessage(body, e) }]);
  }
  return parseTimeline(json, source, options);
}

/** A timeline as compact JSON text (the form the URL hash and `getTimeline` round-trip through). */
export function timelineText(t: Timeline, indent?: number): string {
  return JSON.stringify(t, null, indent);
}

// ---------------------------------------------------------------------------------------------------------------
// Checks across fields. They read the document defensively, so that they report alongside the schema's problems;
// values the schema refused are skipped here, so nothing is reported twice.

const isNum = (x: unknown): x is number => typeof x === 'number' && Number.isFinite(x);

function crossChecks(doc: unknown, presets: readonly string[] | null): TimelineProblem[] {
  if (!isObj(doc)) return [];
  const problems: TimelineProblem[] = [];
  let end = 0;
  if (isObj(doc.tracks)) {
    for (const [name, track] of Object.entries(doc.tracks)) {
      const at = `tracks${pathStep(name, false)}`;
      const message = targetProblem(name, presets);
      if (message) problems.push({ path: at, message });
      if (!isObj(track) || !Array.isArray(track.keys)) continue;
      let previous: number | undefined;
      track.keys.forEach((key, i) => {
        if (!isObj(key) || !isNum(key.time) || key.time < 0) return;
        if (previous !== undefined && key.time <= previous) {
          const what = key.time === previous ? 'a duplicate key time' : 'keys out of order';
          problems.push({
            path: `${at}.keys[${i}].time`,
            message: `${what}: expected a time after the previous key's ${previous} s, got ${key.time}`,
          });
        }
        previous = previous === undefined ? key.time : Math.max(previous, key.time);
      });
      if (previous !== undefined) end = Math.max(end, previous);
    }
  }
  if (Array.isArray(doc.actions)) {
    doc.actions.forEach((a, i) => {
      if (!isObj(a)) return;
      if (typeof a.target === 'string') {
        const message = targetProblem(a.target, presets);
        if (message) problems.push({ path: `actions[${i}].target`, message });
      }
      const { start, onset, apex, offset } = a;
      if (isNum(start) && isNum(onset) && isNum(apex) && isNum(offset)) end = Math.max(end, start + onset + apex + offset);
    });
  }
  // A duration shorter than the content would cut keys and actions off without a word.
  if (isNum(doc.duration) && doc.duration > 0 && doc.duration < end) {
    problems.push({ path: 'duration', message: `expected at least ${end} s (the end of the last key or action), got ${doc.duration}` });
  }
  if (!('duration' in doc) && end > MAX_TIMELINE_SECONDS) {
    problems.push({ path: 'actions', message: `expected the timeline to end within ${MAX_TIMELINE_SECONDS} s, it ends at ${end} s` });
  }
  return problems;
}

/** What is wrong with a track name or action target, or undefined if it names an Action Unit side or a known preset. */
function targetProblem(name: string, presets: readonly string[] | null): string | undefined {
  if (name.startsWith(PRESET_TARGET_PREFIX)) {
    const preset = name.slice(PRESET_TARGET_PREFIX.length);
    if (preset === '') return 'expected a preset name after "preset:"';
    if (presets && !presets.includes(preset))
      return `expected one of the presets ${presets.join(', ') || '(none)'}, got ${showValue(preset)}`;
    return undefined;
  }
  if (!isActionUnitId(name)) return `expected ${ACTION_UNIT_ID} or "preset:<name>", got ${showValue(name)}`;
  return undefined;
}
