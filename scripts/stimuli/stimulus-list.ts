/**
 * Stimulus lists for `npm run stimuli`: a JSON file naming expressions (or timelines) and the intensities, lights,
 * cameras and resolutions to render each at. The list is checked whole first (every problem named with its path,
 * `stimuli[2].intensity[1]: ...`), then expanded into one stimulus per combination, each with a file name made from
 * its parameters, so that a rerun, or another shard, finds the same names.
 */

import * as v from 'valibot';
import { isActionUnitId } from '../../src/core/expression/facs';
import { emotionVariants } from '../../src/core/expression/emfacs';
import { facsIntensities } from '../../src/core/expression/facs-code';
import { pathStep, problemOf, type RigProblem } from '../../src/core/rig/rig-problems';
import { parseTimeline, TimelineError } from '../../src/core/timeline/timeline-schema';
import { PRESET_TARGET_PREFIX, type Timeline } from '../../src/core/timeline/timeline';
import {
  CAMERA_DEFAULTS,
  CAMERA_RANGES,
  LIGHT_DEFAULTS,
  LIGHT_RANGES,
  type CameraOptions,
  type LightOptions,
} from '../../src/render/view-options';
import { checkOptions } from '../../src/core/check';
import { identityText, readIdentity } from '../../src/core/head/identity';

export const STIMULI_FORMAT = 'softface-stimuli';
export const STIMULI_VERSION = 1;
export const RESOLUTIONS = ['low', 'medium', 'high'] as const;
export type Resolution = (typeof RESOLUTIONS)[number];
/** Most stimuli one list may expand to. */
export const MAX_STIMULI = 100_000;

/** One stimulus to render: a PNG of a settled expression, or a WebM of a timeline. */
export interface Stimulus {
  /** File name in the output folder: the entry's name and the combination's parameters. */
  file: string;
  name: string;
  format: 'png' | 'webm';
  /** Action Unit ids and `preset:<name>` weights, already scaled by the intensity (PNG). */
  expression: Record<string, number> | null;
  /** The EMFACS face the expression is (its name and FACS code), or null for an expression or timeline given whole. */
  emotion: { name: string; code: string } | null;
  /** The timeline with every value scaled by the intensity (WebM). */
  timeline: Timeline | null;
  intensity: number;
  light: Partial<LightOptions>;
  camera: Partial<CameraOptions>;
  resolution: Resolution;
  /** The person shown, as text (a stock name or `sex:1,age:30,african:1`; see `setIdentity`), or null for the default head. */
  identity: string | null;
  width: number;
  height: number;
  fps: number;
}

/** A stimulus list that was refused: one line per problem, `source: path: what is wrong`. */
export class StimulusListError extends Error {
  constructor(
    readonly source: string,
    readonly problems: readonly RigProblem[],
  ) {
    super(problems.map((p) => (p.path ? `${source}: ${p.path}: ${p.message}` : `${source}: ${p.message}`)).join('\n'));
    this.name = 'StimulusListError';
  }
}

/** A value, or a list of them: a single value is read as a list of one (its problems then sit at `[0]`). */
const oneOrMore = <T extends v.GenericSchema>(item: T) =>
  v.pipe(
    v.unknown(),
    v.transform((x) => (Array.isArray(x) ? x : [x])),
    v.array(item),
    v.minLength(1, 'expected at least one value'),
  );
const name = v.pipe(
  v.string('expected a name'),
  v.regex(/^[A-Za-z0-9][A-Za-z0-9_-]{0,63}$/, 'expected a name of letters, digits, "-" and "_" (up to 64)'),
);
const intensity = v.pipe(
  v.number('expected a number'),
  v.finite('expected a finite number'),
  v.minValue(0, 'expected 0..1'),
  v.maxValue(1, 'expected 0..1'),
);
const size = v.pipe(
  v.number('expected a number of pixels'),
  v.integer('expected a whole number of pixels'),
  v.minValue(16, 'expected 16..4096 pixels'),
  v.maxValue(4096, 'expected 16..4096 pixels'),
);
const options = v.record(v.string(), v.unknown(), 'expected an object of options');

const Settings = {
  intensity: v.optional(oneOrMore(intensity)),
  light: v.optional(oneOrMore(options)),
  camera: v.optional(oneOrMore(options)),
  resolution: v.optional(oneOrMore(v.picklist(RESOLUTIONS, `expected one of ${RESOLUTIONS.join(', ')}`))),
  identity: v.optional(
    oneOrMore(v.union([v.string(), options, v.null()], 'expected a stock identity, identity text or { sex, age, ancestry }')),
  ),
  width: v.optional(size),
  height: v.optional(size),
  fps: v.optional(
    v.pipe(
      v.number('expected frames per second'),
      v.finite('expected a finite number'),
      v.minValue(1, 'expected 1..60 frames per second'),
      v.maxValue(60, 'expected 1..60 frames per second'),
    ),
  ),
};

const Entry = v.strictObject(
  {
    name,
    expression: v.optional(
      v.record(
        v.string(),
        v.pipe(
          v.number('expected a number'),
          v.finite('expected a finite number'),
          v.minValue(0, 'expected 0..1'),
          v.maxValue(1, 'expected 0..1'),
        ),
        'expected an object of Action Unit ids and preset weights',
      ),
    ),
    timeline: v.optional(v.unknown()),
    emotion: v.optional(oneOrMore(v.string('expected an emotion, an emotion and kind, or a face of the EMFACS table'))),
    ...Settings,
  },
  'unknown field',
);

const ListSchema = v.strictObject({
  format: v.literal(STIMULI_FORMAT, `expected "${STIMULI_FORMAT}"`),
  version: v.literal(STIMULI_VERSION, `expected ${STIMULI_VERSION}`),
  defaults: v.optional(v.strictObject(Settings)),
  stimuli: v.pipe(v.array(Entry, 'expected a list of stimuli'), v.minLength(1, 'expected at least one stimulus')),
});

type Settings = {
  intensity?: number[];
  light?: object[];
  camera?: object[];
  resolution?: Resolution[];
  identity?: unknown[];
  width?: number;
  height?: number;
  fps?: number;
};
const list = <T>(x: T[] | undefined, fallback: T[]): T[] => x ?? fallback;

/** Checks a parsed stimulus list and expands it into stimuli; throws StimulusListError naming every problem. */
export function expandStimulusList(json: unknown, source = 'stimuli'): Stimulus[] {
  const parsed = v.safeParse(ListSchema, json, { abortEarly: false });
  if (!parsed.success) throw new StimulusListError(source, parsed.issues.map(problemOf));
  const doc = parsed.output;
  const problems: RigProblem[] = [];
  const defaults: Settings = doc.defaults ?? {};
  const out: Stimulus[] = [];
  const seen = new Set<string>();
  doc.stimuli.forEach((entry, e) => {
    const at = (...keys: (string | number)[]): string => ['stimuli', e, ...keys].map((k, i) => pathStep(k, i === 0)).join('');
    const given = [entry.expression, entry.timeline, entry.emotion].filter((x) => x !== undefined).length;
    if (given !== 1) {
      problems.push({ path: at(), message: 'expected one of an expression or an emotion (PNGs) or a timeline (a WebM)' });
      return;
    }
    // The EMFACS faces the entry names, each an expression of its own (one PNG per face and combination).
    const faces: ({ name: string; code: string; expression: Record<string, number> } | null)[] = [];
    (entry.emotion ?? []).forEach((selector, k) => {
      try {
        for (const f of emotionVariants(selector, 'emotion'))
          if (!faces.some((g) => g?.name === f.name)) faces.push({ name: f.name, code: f.code, expression: facsIntensities(f.code) });
      } catch (error) {
        problems.push({ path: at('emotion', k), message: (error as Error).message.replace(/^emotion: /, '') });
      }
    });
    if (faces.length === 0) faces.push(null);
    for (const id of Object.keys(entry.expression ?? {})) {
      const known = id.startsWith(PRESET_TARGET_PREFIX) ? id.length > PRESET_TARGET_PREFIX.length : isActionUnitId(id);
      if (!known) problems.push({ path: at('expression', id), message: `expected an Action Unit or a preset, got ${JSON.stringify(id)}` });
    }
    let timeline: Timeline | null = null;
    if (entry.timeline !== undefined) {
      try {
        timeline = parseTimeline(entry.timeline, at('timeline'));
      } catch (error) {
        if (!(error instanceof TimelineError)) throw error;
        for (const p of error.problems)
          problems.push({
            path: p.path ? `${at('timeline')}${p.path.startsWith('[') ? '' : '.'}${p.path}` : at('timeline'),
            message: p.message,
          });
      }
    }
    const merged: Settings = { ...defaults, ...(entry as Settings) };
    const lights = list(merged.light, [{}]);
    const cameras = list(merged.camera, [{}]);
    lights.forEach((l, k) => {
      try {
        checkOptions<LightOptions>('light', l, LIGHT_DEFAULTS, { ranges: LIGHT_RANGES });
      } catch (error) {
        problems.push({ path: at('light', k), message: (error as Error).message.replace(/^light: /, '') });
      }
    });
    cameras.forEach((c, k) => {
      try {
        checkOptions<CameraOptions>('camera', c, CAMERA_DEFAULTS, { ranges: CAMERA_RANGES });
      } catch (error) {
        problems.push({ path: at('camera', k), message: (error as Error).message.replace(/^camera: /, '') });
      }
    });
    // The people: each read as `setIdentity` reads it, and written as the text the app's URL hash takes.
    const people = list<unknown>(merged.identity, [null]).map((given, k) => {
      try {
        const named = readIdentity(given, 'identity');
        return named && identityText(named.identity);
      } catch (error) {
        problems.push({ path: at('identity', k), message: (error as Error).message.replace(/^identity: /, '') });
        return null;
      }
    });
    if (seen.has(entry.name)) problems.push({ path: at('name'), message: `a second stimulus named ${JSON.stringify(entry.name)}` });
    seen.add(entry.name);
    const format = timeline ? 'webm' : 'png';
    // Video frames are whole 2 x 2 blocks of colour samples (4:2:0).
    for (const side of ['width', 'height'] as const) {
      if (timeline && (merged[side] ?? 512) % 2 === 1)
        problems.push({ path: at(side), message: `a video needs an even ${side}, got ${merged[side]}` });
    }
    for (const face of faces)
      for (const i of list(merged.intensity, [1])) {
        for (let l = 0; l < lights.length; l++) {
          for (let c = 0; c < cameras.length; c++) {
            for (const resolution of list<Resolution>(merged.resolution, ['medium'])) {
              for (let p = 0; p < people.length; p++) {
                if (out.length >= MAX_STIMULI) continue;
                // Named by the person's place in the list only where a list of people was given.
                const person = merged.identity === undefined ? '' : `_p${p}`;
                const expression = face?.expression ?? entry.expression;
                out.push({
                  file: `${entry.name}${face ? `_${face.name}` : ''}_i${i}_l${l}_c${c}_${resolution}${person}.${format}`,
                  name: entry.name,
                  format,
                  expression: expression ? Object.fromEntries(Object.entries(expression).map(([id, x]) => [id, x * i])) : null,
                  emotion: face && { name: face.name, code: face.code },
                  timeline: timeline ? scaleTimeline(timeline, i) : null,
                  intensity: i,
                  light: lights[l] as Partial<LightOptions>,
                  camera: cameras[c] as Partial<CameraOptions>,
                  resolution,
                  identity: people[p],
                  width: merged.width ?? 512,
                  height: merged.height ?? 512,
                  fps: merged.fps ?? 25,
                });
              }
            }
          }
        }
      }
  });
  if (out.length >= MAX_STIMULI) problems.push({ path: 'stimuli', message: `expands to more than ${MAX_STIMULI} stimuli` });
  if (problems.length > 0) throw new StimulusListError(source, problems);
  return out;
}

/** The timeline with every key value and action intensity multiplied by `k` (0..1, so they stay in range). */
export function scaleTimeline(t: Timeline, k: number): Timeline {
  const tracks: Timeline['tracks'] = {};
  for (const [id, track] of Object.entries(t.tracks)) tracks[id] = { keys: track.keys.map((key) => ({ ...key, value: key.value * k })) };
  return { ...t, tracks, actions: t.actions.map((a) => ({ ...a, intensity: a.intensity * k })) };
}

const CSV_COLUMNS = [
  'file',
  'name',
  'format',
  'expression',
  'emotion',
  'timeline',
  'intensity',
  'light',
  'camera',
  'resolution',
  'identity',
  'width',
  'height',
  'fps',
] as const;

/** The manifest: one CSV row per stimulus with everything it was rendered from (JSON in the object columns). */
export function stimulusManifest(stimuli: readonly Stimulus[]): string {
  const cell = (x: unknown): string => {
    const text = x === null ? '' : typeof x === 'object' ? JSON.stringify(x) : String(x);
    return /[",\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
  };
  const value = (s: Stimulus, c: (typeof CSV_COLUMNS)[number]): unknown =>
    c === 'timeline' ? (s.timeline ? 'yes' : 'no') : c === 'emotion' ? (s.emotion ? `${s.emotion.name} (${s.emotion.code})` : null) : s[c];
  const rows = stimuli.map((s) => CSV_COLUMNS.map((c) => cell(value(s, c))).join(','));
  return `${CSV_COLUMNS.join(',')}\n${rows.join('\n')}\n`;
}
