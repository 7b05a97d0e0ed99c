/**
 * Reading rig documents (`rig-types.ts`) from JSON: a valibot schema for the shape and ranges, then the checks the
 * schema cannot express (rig-cross-checks.ts), with error messages that name every problem with its path
 * (rig-problems.ts), so that a hand-edited rig can be fixed in one pass.
 */

import * as v from 'valibot';
import { jsonSyntaxMessage, megabytes, utf8Length } from './json-text';
import { accepts, BRUSH_RANGES, type FieldRange, MUSCLE_RANGES } from './muscle-ranges';
import { crossChecks, isObj, type Obj } from './rig-cross-checks';
import { show } from '../check';
import { problemOf, RigError } from './rig-problems';
import type { Muscle, Rig } from './rig-types';

/** Largest rig document `parseRigText` accepts, in bytes of UTF-8 (the default rig is about 20 kB). */
export const MAX_RIG_BYTES = 5 * 1024 * 1024;

/** Most muscles, Action Units and presets a rig may hold (the default rig has 37, 21 and 12). */
export const MAX_RIG_MUSCLES = 256;
const MAX_RIG_ACTION_UNITS = 64;
const MAX_RIG_PRESETS = 256;
/** Longest name or note, in characters. */
const MAX_TEXT = 200;

/** The rig document version this code writes; older documents are migrated when read (`migrateRig`). */
const RIG_VERSION = 2;
/** Most brush spheres a muscle may have, of each kind. */
const MAX_BRUSH_SPHERES = 4096;

// ---------------------------------------------------------------------------------------------------------------
// The schema. Every message starts with "expected ..."; the formatter adds what was found.

const number = v.pipe(v.number('expected a number'), v.finite('expected a finite number'));
const positive = v.pipe(number, v.gtValue(0, 'expected a positive number'));
const fraction = v.pipe(number, v.minValue(0, 'expected a number from 0 to 1'), v.maxValue(1, 'expected a number from 0 to 1'));
const text = v.pipe(v.string('expected a string'), v.maxLength(MAX_TEXT, `expected at most ${MAX_TEXT} characters`));
const name = v.pipe(text, v.nonEmpty('expected a non-empty name'));
const side = v.picklist(['left', 'right', 'mid'], 'expected "left", "right" or "mid"');

/** A 3-vector of the given numbers; `strictTuple` so that a fourth number is reported rather than dropped. */
function vec3<T extends v.GenericSchema<number, number>>(item: T) {
  return v.strictTuple([item, item, item], 'expected 3 numbers [x, y, z]');
}

/**
 * A strict object that is not an array: valibot's object schemas take arrays as objects, which would report an array
 * as a list of missing fields.
 */
function plainObject<const E extends v.ObjectEntries>(entries: E, message: string) {
  return v.pipe(v.custom<Obj>(isObj, message), v.strictObject(entries, message));
}

/** A number that `field` (muscle-ranges.ts) accepts. */
function ranged(field: FieldRange) {
  return v.pipe(
    number,
    v.check((x) => accepts(field, x), `expected ${field.expected}`),
  );
}

/**
 * The number fields of muscle type `type`, from MUSCLE_RANGES in its order: each a number, or an [x, y, z] of them,
 * optional where the table says so. The cast gives them the types rig-types.ts declares, which the table's type ties
 * to the same fields.
 */
function rangedEntries<T extends Muscle['type']>(type: T) {
  const entries: v.ObjectEntries = {};
  for (const [key, field] of Object.entries(MUSCLE_RANGES[type]) as [string, FieldRange][]) {
    const one = field.vector ? vec3(ranged(field)) : ranged(field);
    entries[key] = field.optional ? v.optional(one) : one;
  }
  type M = Extract<Muscle, { type: T }>;
  return entries as { [K in keyof (typeof MUSCLE_RANGES)[T]]: v.GenericSchema<M[K & keyof M]> };
}

const spheres = v.pipe(
  v.array(
    v.strictTuple(
      [ranged(BRUSH_RANGES.coordinate), ranged(BRUSH_RANGES.coordinate), ranged(BRUSH_RANGES.coordinate), ranged(BRUSH_RANGES.radius)],
      'expected a sphere [x, y, z, radius]',
    ),
    'expected an array of spheres',
  ),
  v.maxLength(MAX_BRUSH_SPHERES, `expected at most ${MAX_BRUSH_SPHERES} spheres`),
);
const brush = v.optional(plainObject({ add: spheres, remove: spheres }, 'expected a brush { add: [...], remove: [...] }'));
const object = 'expected an object';

const LinearMuscleSchema = v.strictObject({ name, side, brush, type: v.literal('linear'), ...rangedEntries('linear') }, object);
const SphincterMuscleSchema = v.strictObject({ name, side, brush, type: v.literal('sphincter'), ...rangedEntries('sphincter') }, object);
const LidMuscleSchema = v.strictObject({ name, side, brush, type: v.literal('lid'), ...rangedEntries('lid') }, object);
const JawMuscleSchema = v.strictObject({ name, side, brush, type: v.literal('jaw'), ...rangedEntries('jaw') }, object);

const MuscleSchema = v.variant('type', [LinearMuscleSchema, SphincterMuscleSchema, LidMuscleSchema, JawMuscleSchema], (issue) =>
  issue.expected === 'Object'
    ? 'expected a muscle (an object with a "type")'
    : 'expected a muscle type: "linear", "sphincter", "lid" or "jaw"',
);

const ActionUnitSchema = plainObject(
  {
    id: v.pipe(text, v.regex(/^AU[1-9]\d*$/, 'expected an Action Unit id like "AU12"')),
    name,
    bilateral: v.boolean('expected true or false'),
    muscles: v.pipe(
      v.array(
        plainObject({ muscle: name, side, weight: v.pipe(positive, v.maxValue(10, 'expected a weight of at most 10')) }, object),
        'expected an array',
      ),
      v.minLength(1, 'expected at least one muscle'),
      v.maxLength(MAX_RIG_MUSCLES, `expected at most ${MAX_RIG_MUSCLES} muscles`),
    ),
  },
  object,
);

const PresetSchema = plainObject(
  {
    name,
    source: text,
    actionUnits: v.record(v.string(), fraction, 'expected an object of Action Unit intensities, like { "AU12": 0.5 }'),
    note: v.optional(v.pipe(v.string('expected a string'), v.maxLength(10 * MAX_TEXT, `expected at most ${10 * MAX_TEXT} characters`))),
  },
  object,
);

/** The shape of a rig document; `parseRig` adds the checks across fields. */
const RigSchema = plainObject(
  {
    format: v.literal('softface-rig', 'expected "softface-rig"'),
    version: v.literal(RIG_VERSION, `expected version ${RIG_VERSION}`),
    muscles: v.pipe(
      v.array(MuscleSchema, 'expected an array of muscles'),
      v.maxLength(MAX_RIG_MUSCLES, `expected at most ${MAX_RIG_MUSCLES} muscles`),
    ),
    actionUnits: v.pipe(
      v.array(ActionUnitSchema, 'expected an array of Action Units'),
      v.maxLength(MAX_RIG_ACTION_UNITS, `expected at most ${MAX_RIG_ACTION_UNITS} Action Units`),
    ),
    presets: v.pipe(
      v.array(PresetSchema, 'expected an array of presets'),
      v.maxLength(MAX_RIG_PRESETS, `expected at most ${MAX_RIG_PRESETS} presets`),
    ),
  },
  'expected a rig document (a JSON object)',
);

// ---------------------------------------------------------------------------------------------------------------
// Parsing.

/**
 * Brings an older rig document up to `RIG_VERSION` (a shallow copy; the input is not changed). A document without a
 * `version` is taken as version 1, the first one; anything else is left for the schema to judge.
 */
function migrateRig(json: unknown): unknown {
  if (!isObj(json)) return json;
  let version = 'version' in json ? json.version : 1;
  // Version 2 added the muscles' optional `brush`: a version 1 document is a version 2 one as it is.
  if (version === 1) version = 2;
  return version === json.version ? json : { ...json, version };
}

/**
 * Checks a rig document (parsed JSON) and returns it as a `Rig`; throws a `RigError` listing every problem. Older
 * versions are migrated first (`migrateRig`).
 */
export function parseRig(input: unknown, source = 'rig'): Rig {
  const json = migrateRig(input);
  // Cheap refusals before the schema walks anything: a list far over its limit is not read item by item.
  if (isObj(json)) {
    const limits: [string, number][] = [
      ['muscles', MAX_RIG_MUSCLES],
      ['actionUnits', MAX_RIG_ACTION_UNITS],
      ['presets', MAX_RIG_PRESETS],
    ];
    const over = limits.filter(([key, max]) => Array.isArray(json[key]) && (json[key] as unknown[]).length > max);
    if (over.length > 0)
      throw new RigError(
        source,
        over.map(([key, max]) => ({ path: key, message: `expected at most ${max} items, got ${(json[key] as unknown[]).length}` })),
      );
  }
  const result = v.safeParse(RigSchema, json, { abortPipeEarly: true });
  const problems = result.success ? [] : result.issues.map(problemOf);
  problems.push(...crossChecks(json));
  if (!result.success || problems.length > 0) throw new RigError(source, problems);
  return result.output;
}

/** Parses a rig document from JSON text, refusing texts over `MAX_RIG_BYTES`; throws a `RigError` on any problem. */
export function parseRigText(text: string, source = 'rig'): Rig {
  if (typeof text !== 'string')
    throw new RigError(source, [{ path: '', message: `expected the text of a JSON document, got ${show(text)}` }]);
  const bytes = utf8Length(text);
  if (bytes > MAX_RIG_BYTES) {
    const message =
      `the document is ${bytes} bytes (${megabytes(bytes)}), over the limit of ` +
      `${MAX_RIG_BYTES} bytes (${megabytes(MAX_RIG_BYTES)}) for rig documents`;
    throw new RigError(source, [{ path: '', message }]);
  }
  // Editors may save a byte-order mark, which JSON.parse refuses.
  const body = text.charCodeAt(0) === 0xfeff ? text.slice(1) : text;
  let json: unknown;
  try {
    json = JSON.parse(body);
  } catch (e) {
    throw new RigError(source, [{ path: '', message: jsonSyntaxMessage(body, e) }]);
  }
  return parseRig(json, source);
}
