/**
 * Reading rig documents (`rig-types.ts`) from JSON: a valibot schema for the shape and ranges, checks the schema cannot
 * express (names that must exist or be unique, sides that must match), and error messages that name every problem
 * with its path, so that a hand-edited rig can be fixed in one pass.
 */

import * as v from 'valibot';
import type { Rig } from './rig-types';

/** Largest rig document `parseRigText` accepts, in bytes of UTF-8 (the default rig is about 20 kB). */
export const MAX_RIG_BYTES = 5 * 1024 * 1024;

/** Most muscles, Action Units and presets a rig may hold (the default rig has 37, 21 and 12). */
export const MAX_RIG_MUSCLES = 256;
const MAX_RIG_ACTION_UNITS = 64;
const MAX_RIG_PRESETS = 256;
/** Longest name or note, in characters. */
const MAX_TEXT = 200;
/**
 * Farthest a muscle point may lie from the model's origin, and largest radius or box edge, in metres. The head is
 * about 0.25 m across; a point kilometres away would make the solver's targets (and the skin) run off to infinity.
 */
const MAX_RIG_DISTANCE = 10;

/** The rig document version this code writes; older documents are migrated when read (`migrateRig`). */
const RIG_VERSION = 2;
/** Most brush spheres a muscle may have, of each kind. */
const MAX_BRUSH_SPHERES = 4096;
/** Largest brush sphere radius, in metres. */
const MAX_BRUSH_RADIUS = 0.1;

/** At most this many problems are spelled out in an error's message; `RigError.problems` has them all. */
const MAX_LISTED_PROBLEMS = 50;

/** One problem in a rig document: where (`muscles[3].radii[1]`, or '' for the whole document) and what is wrong. */
export interface RigProblem {
  path: string;
  message: string;
}

/** A rig document that was refused: its message has one line per problem, `source: path: what is wrong`. */
export class RigError extends Error {
  readonly source: string;
  readonly problems: readonly RigProblem[];

  constructor(source: string, problems: readonly RigProblem[]) {
    const lines = problems
      .slice(0, MAX_LISTED_PROBLEMS)
      .map((p) => (p.path ? `${source}: ${p.path}: ${p.message}` : `${source}: ${p.message}`));
    if (problems.length > lines.length) lines.push(`${source}: and ${problems.length - lines.length} more problems`);
    super(lines.join('\n'));
    this.name = 'RigError';
    this.source = source;
    this.problems = problems;
  }
}

type Obj = Record<string, unknown>;

const isObj = (x: unknown): x is Obj => typeof x === 'object' && x !== null && !Array.isArray(x);

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

const coordinate = v.pipe(
  number,
  v.minValue(-MAX_RIG_DISTANCE, `expected a coordinate within ±${MAX_RIG_DISTANCE} m`),
  v.maxValue(MAX_RIG_DISTANCE, `expected a coordinate within ±${MAX_RIG_DISTANCE} m`),
);
/** A radius, box edge or fade: positive and at most MAX_RIG_DISTANCE. */
const extent = v.pipe(positive, v.maxValue(MAX_RIG_DISTANCE, `expected a length of at most ${MAX_RIG_DISTANCE} m`));
/** A falloff as a fraction of a linear muscle's length. */
const falloff = v.pipe(positive, v.maxValue(100, 'expected a positive number of at most 100'));
const degrees = v.pipe(
  number,
  v.minValue(-360, 'expected an angle from -360 to 360 degrees'),
  v.maxValue(360, 'expected an angle from -360 to 360 degrees'),
);
const position = vec3(coordinate);
const euler = vec3(degrees);
const brushRadius = v.pipe(positive, v.maxValue(MAX_BRUSH_RADIUS, `expected a radius of at most ${MAX_BRUSH_RADIUS} m`));
const spheres = v.pipe(
  v.array(
    v.strictTuple([coordinate, coordinate, coordinate, brushRadius], 'expected a sphere [x, y, z, radius]'),
    'expected an array of spheres',
  ),
  v.maxLength(MAX_BRUSH_SPHERES, `expected at most ${MAX_BRUSH_SPHERES} spheres`),
);
const brush = v.optional(plainObject({ add: spheres, remove: spheres }, 'expected a brush { add: [...], remove: [...] }'));
const angle = v.pipe(
  number,
  v.minValue(-90, 'expected an angle from -90 to 90 degrees'),
  v.maxValue(90, 'expected an angle from -90 to 90 degrees'),
);
const object = 'expected an object';

const LinearMuscleSchema = v.strictObject(
  {
    name,
    side,
    brush,
    type: v.literal('linear'),
    origin: position,
    insertion: position,
    angle: v.pipe(
      number,
      v.minValue(0, 'expected an angle from 0 to 90 degrees'),
      v.maxValue(90, 'expected an angle from 0 to 90 degrees'),
    ),
    falloffStart: falloff,
    falloffEnd: falloff,
    strength: fraction,
    normalWeight: fraction,
  },
  object,
);

const SphincterMuscleSchema = v.strictObject(
  {
    name,
    side,
    brush,
    type: v.literal('sphincter'),
    center: position,
    rotation: euler,
    radii: vec3(extent),
    // Positive: the pull inside the inner ellipsoid is scaled by the distance over these radii.
    innerRadii: vec3(extent),
    // Negative pushes away from the center along that axis (a pucker thrusts the lips forward).
    scale: vec3(v.pipe(number, v.minValue(-10, 'expected a number from -10 to 10'), v.maxValue(10, 'expected a number from -10 to 10'))),
    strength: fraction,
    normalWeight: fraction,
  },
  object,
);

const LidMuscleSchema = v.strictObject(
  {
    name,
    side,
    brush,
    type: v.literal('lid'),
    center: position,
    rotation: euler,
    radii: vec3(extent),
    maxAngle: angle,
    // Below 1: the fade runs from innerFraction to the surface, and must have a width.
    innerFraction: v.pipe(
      number,
      v.minValue(0, 'expected a number from 0 to below 1'),
      v.ltValue(1, 'expected a number from 0 to below 1'),
    ),
  },
  object,
);

const JawMuscleSchema = v.strictObject(
  {
    name,
    side,
    brush,
    type: v.literal('jaw'),
    center: position,
    rotation: euler,
    size: vec3(extent),
    joint: v.optional(position),
    maxAngle: angle,
    curve: fraction,
    // Positive: without a fade the turn would stop in a step at the box's faces.
    fade: extent,
    lipFade: v.optional(extent),
  },
  object,
);

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

// ---------------------------------------------------------------------------------------------------------------
// Issues to problems.

/** A valibot issue as a problem: its path and an "expected ..., got ..." message (also used for timelines). */
export function problemOf(issue: v.BaseIssue<unknown>): RigProblem {
  const path = pathOf(issue.path);
  // valibot reports a key that a strict object or tuple does not allow as expecting "never".
  if (issue.expected === 'never')
    return { path, message: issue.type === 'strict_tuple' ? 'unexpected extra item (expected 3 numbers)' : 'unknown field' };
  if (issue.input === undefined && issue.path !== undefined) return { path, message: 'missing' };
  return { path, message: `${issue.message}, got ${show(issue.input)}` };
}

function pathOf(path: readonly { key: unknown }[] | undefined): string {
  let out = '';
  for (const { key } of path ?? []) out += pathStep(key, out === '');
  return out;
}

/** One step of a problem's path: `[3]`, `.name`, or `["preset:happiness"]` for a key that is no identifier. */
export function pathStep(key: unknown, first: boolean): string {
  if (typeof key === 'number') return `[${key}]`;
  const k = String(key);
  if (/^[A-Za-z_$][\w$]*$/.test(k)) return first ? k : `.${k}`;
  return `[${JSON.stringify(k)}]`;
}

/** A short description of a found value for messages: `-0.01`, `"spring"`, `an array of 2 items`. */
export function show(x: unknown): string {
  if (x === undefined) return 'nothing';
  if (x === null || typeof x === 'number' || typeof x === 'boolean') return String(x);
  if (typeof x === 'string') return x.length > 40 ? `${JSON.stringify(x.slice(0, 40))}...` : JSON.stringify(x);
  if (Array.isArray(x)) return `an array of ${x.length} item${x.length === 1 ? '' : 's'}`;
  return typeof x === 'object' ? 'an object' : `a ${typeof x}`;
}

// ---------------------------------------------------------------------------------------------------------------
// Checks across fields. They read the document defensively, so that they can report alongside the schema's problems
// even when parts of it are malformed; values the schema refused are skipped here, so nothing is reported twice.

const list = (x: unknown): unknown[] => (Array.isArray(x) ? x : []);
const isNum = (x: unknown): x is number => typeof x === 'number' && Number.isFinite(x);
const isPositive = (x: unknown): x is number => isNum(x) && x > 0;
const isVec3 = (x: unknown): x is [number, number, number] => Array.isArray(x) && x.length === 3 && x.every(isNum);

function crossChecks(doc: unknown): RigProblem[] {
  if (!isObj(doc)) return [];
  const problems: RigProblem[] = [];
  const muscleSides = checkMuscles(list(doc.muscles), problems);
  const bilateralById = checkActionUnits(list(doc.actionUnits), muscleSides, problems);
  checkPresets(list(doc.presets), bilateralById, problems);
  return problems;
}

/** Unique names and each muscle's own geometry; returns the side of every named muscle. */
function checkMuscles(muscles: unknown[], problems: RigProblem[]): Map<string, unknown> {
  const sides = new Map<string, unknown>();
  const firstIndex = new Map<string, number>();
  muscles.forEach((m, i) => {
    if (!isObj(m)) return;
    const at = `muscles[${i}]`;
    if (typeof m.name === 'string') {
      const first = firstIndex.get(m.name);
      if (first !== undefined) problems.push({ path: `${at}.name`, message: `duplicate muscle name "${m.name}" (also muscles[${first}])` });
      else {
        firstIndex.set(m.name, i);
        sides.set(m.name, m.side);
      }
    }
    checkGeometry(m, at, problems);
  });
  return sides;
}

function checkGeometry(m: Obj, at: string, problems: RigProblem[]): void {
  if (m.type === 'linear') {
    if (isPositive(m.falloffStart) && isPositive(m.falloffEnd) && !(m.falloffStart < m.falloffEnd)) {
      problems.push({ path: `${at}.falloffEnd`, message: `expected more than falloffStart (${m.falloffStart}), got ${m.falloffEnd}` });
    }
    // The pull runs along origin -> insertion, which needs a length.
    if (isVec3(m.origin) && isVec3(m.insertion) && m.origin.every((x, k) => x === (m.insertion as number[])[k])) {
      problems.push({ path: `${at}.insertion`, message: 'expected a point apart from the origin, got the same point' });
    }
  }
  if (m.type === 'sphincter' && isVec3(m.radii) && m.radii.every(isPositive) && isVec3(m.innerRadii) && m.innerRadii.every(isPositive)) {
    const radii = m.radii;
    m.innerRadii.forEach((r, k) => {
      if (r > radii[k]) problems.push({ path: `${at}.innerRadii[${k}]`, message: `expected at most radii[${k}] (${radii[k]}), got ${r}` });
    });
  }
}

/** Unique ids, muscles that exist, and sides that fit the unit; returns whether each Action Unit id is bilateral. */
function checkActionUnits(units: unknown[], muscleSides: Map<string, unknown>, problems: RigProblem[]): Map<string, boolean> {
  const bilateralById = new Map<string, boolean>();
  units.forEach((u, i) => {
    if (!isObj(u)) return;
    const at = `actionUnits[${i}]`;
    if (typeof u.id === 'string') {
      if (bilateralById.has(u.id)) problems.push({ path: `${at}.id`, message: `duplicate Action Unit id "${u.id}"` });
      else if (typeof u.bilateral === 'boolean') bilateralById.set(u.id, u.bilateral);
    }
    if (typeof u.bilateral === 'boolean') checkActionUnitMuscles(u, at, muscleSides, problems);
  });
  return bilateralById;
}

function checkActionUnitMuscles(u: Obj, at: string, muscleSides: Map<string, unknown>, problems: RigProblem[]): void {
  const label = typeof u.id === 'string' ? u.id : 'this Action Unit';
  const seen = new Set<string>();
  const sidesPresent = new Set<unknown>();
  list(u.muscles).forEach((e, j) => {
    if (!isObj(e) || typeof e.muscle !== 'string') return;
    const here = `${at}.muscles[${j}]`;
    sidesPresent.add(e.side);
    // Only a string side can be a duplicate; anything else is the schema's to report (and String() of a deeply nested
    // array would overflow the stack).
    const key = `${e.muscle}\u0000${typeof e.side === 'string' ? e.side : '?'}`;
    if (seen.has(key)) problems.push({ path: `${here}.muscle`, message: `"${e.muscle}" is listed twice for this side` });
    seen.add(key);
    if (!muscleSides.has(e.muscle)) {
      problems.push({ path: `${here}.muscle`, message: `no muscle named "${e.muscle}" in muscles` });
      return;
    }
    const muscleSide = muscleSides.get(e.muscle);
    if (u.bilateral && e.side === 'mid') {
      problems.push({ path: `${here}.side`, message: `expected "left" or "right" for bilateral ${label}, got "mid"` });
    } else if (u.bilateral && (e.side === 'left' || e.side === 'right') && muscleSide !== e.side) {
      const where = muscleSide === 'mid' ? 'the midline' : `the ${typeof muscleSide === 'string' ? muscleSide : 'unknown'} side`;
      problems.push({ path: `${here}.side`, message: `"${e.side}" does not match muscle "${e.muscle}", which is on ${where}` });
    } else if (!u.bilateral && (e.side === 'left' || e.side === 'right')) {
      problems.push({ path: `${here}.side`, message: `expected "mid" for midline ${label}, got "${e.side}"` });
    }
  });
  if (u.bilateral && list(u.muscles).length > 0) {
    for (const s of ['left', 'right']) {
      if (!sidesPresent.has(s)) problems.push({ path: `${at}.muscles`, message: `bilateral ${label} has no muscle on the ${s} side` });
    }
  }
}

/** Unique names, and Action Unit ids that exist: `AU12`, or `AU12L` / `AU12R` for a bilateral unit. */
function checkPresets(presets: unknown[], bilateralById: Map<string, boolean>, problems: RigProblem[]): void {
  const names = new Set<string>();
  presets.forEach((p, i) => {
    if (!isObj(p)) return;
    const at = `presets[${i}]`;
    if (typeof p.name === 'string') {
      if (names.has(p.name)) problems.push({ path: `${at}.name`, message: `duplicate preset name "${p.name}"` });
      names.add(p.name);
    }
    if (!isObj(p.actionUnits)) return;
    for (const id of Object.keys(p.actionUnits)) {
      const message = presetIdProblem(id, bilateralById);
      if (message) problems.push({ path: `${at}.actionUnits${pathStep(id, false)}`, message });
    }
  });
}

function presetIdProblem(id: string, bilateralById: Map<string, boolean>): string | undefined {
  const match = /^(AU[1-9]\d*)([LR]?)$/.exec(id);
  if (!match) return 'expected an Action Unit id like "AU12", "AU12L" or "AU12R"';
  const [, base, sideLetter] = match;
  const bilateral = bilateralById.get(base);
  if (bilateral === undefined) return `no Action Unit ${base} in actionUnits`;
  if (sideLetter && !bilateral) return `${base} is a midline Action Unit and has no sides: use "${base}"`;
  return undefined;
}

// ---------------------------------------------------------------------------------------------------------------
// Text: size and JSON syntax.

/** The length of a text in bytes of UTF-8. */
export function utf8Length(s: string): number {
  let n = 0;
  for (let i = 0; i < s.length; i++) {
    const c = s.charCodeAt(i);
    if (c < 0x80) n += 1;
    else if (c < 0x800) n += 2;
    else if (c >= 0xd800 && c <= 0xdbff && i + 1 < s.length) {
      n += 4; // a surrogate pair is one 4-byte character
      i++;
    } else n += 3;
  }
  return n;
}

function megabytes(bytes: number): string {
  return `${Number((bytes / (1024 * 1024)).toFixed(2))} MiB`;
}

/**
 * Where and why JSON text is invalid. Engines word (and place) JSON.parse errors differently, and some give no
 * position, so the text is scanned here; the engine's message is the fallback should the scan find nothing.
 */
export function jsonSyntaxMessage(text: string, error: unknown): string {
  const found = findJsonError(text);
  if (!found) return `invalid JSON: ${error instanceof Error ? error.message : String(error)}`;
  const before = text.slice(0, found.offset);
  const line = before.split('\n').length;
  const column = found.offset - before.lastIndexOf('\n');
  return `invalid JSON at line ${line}, column ${column}: expected ${found.expected}, got ${showChar(text, found.offset)}`;
}

function showChar(text: string, offset: number): string {
  if (offset >= text.length) return 'the end of the text';
  const c = text.charCodeAt(offset);
  return c > 0x20 && c < 0x7f ? `'${text[offset]}'` : `U+${c.toString(16).toUpperCase().padStart(4, '0')}`;
}

interface JsonError {
  offset: number;
  expected: string;
}

const NUMBER = /-?(?:0|[1-9]\d*)(?:\.\d+)?(?:[eE][+-]?\d+)?/y;
const WHITESPACE = /[ \t\n\r]*/y;

function skipWhitespace(text: string, i: number): number {
  WHITESPACE.lastIndex = i;
  WHITESPACE.test(text);
  return WHITESPACE.lastIndex;
}

/** The first JSON syntax error in `text`, or undefined if it is valid; iterative, so deep nesting cannot overflow. */
function findJsonError(text: string): JsonError | undefined {
  const open: string[] = [];
  let want: 'value' | 'value or ]' | 'key' | 'key or }' | 'colon' | 'next' = 'value';
  let i = skipWhitespace(text, 0);
  for (;;) {
    const c = text[i];
    if (want === 'next') {
      const top = open[open.length - 1];
      if (top === undefined) return i === text.length ? undefined : { offset: i, expected: 'the end of the text after the document' };
      if (c === ',') want = top === '{' ? 'key' : 'value';
      else if (c === (top === '{' ? '}' : ']')) open.pop();
      else return { offset: i, expected: top === '{' ? "',' or '}' after a property value" : "',' or ']' after an array item" };
      i++;
    } else if (want === 'colon') {
      if (c !== ':') return { offset: i, expected: "':' after a property name" };
      want = 'value';
      i++;
    } else if (want === 'key' || want === 'key or }') {
      if (want === 'key or }' && c === '}') {
        open.pop();
        want = 'next';
        i++;
      } else if (c === '"') {
        const end = scanString(text, i);
        if (typeof end !== 'number') return end;
        want = 'colon';
        i = end;
      } else
        return { offset: i, expected: want === 'key' ? 'a property name in double quotes' : "a property name in double quotes or '}'" };
    } else {
      const step = scanValueStart(text, i, want === 'value or ]');
      if ('expected' in step) return step;
      if (step.opened) open.push(step.opened);
      else if (step.closed) open.pop();
      want = step.opened === '{' ? 'key or }' : step.opened === '[' ? 'value or ]' : 'next';
      i = step.end;
    }
    i = skipWhitespace(text, i);
  }
}

/** Where a value that starts at `i` ends (strings, numbers, literals), or the container it opens or closes. */
function scanValueStart(text: string, i: number, mayClose: boolean): JsonError | { end: number; opened?: string; closed?: boolean } {
  const c = text[i];
  if (c === '{' || c === '[') return { end: i + 1, opened: c };
  if (mayClose && c === ']') return { end: i + 1, closed: true };
  if (c === '"') {
    const end = scanString(text, i);
    return typeof end === 'number' ? { end } : end;
  }
  for (const word of ['true', 'false', 'null']) if (text.startsWith(word, i)) return { end: i + word.length };
  NUMBER.lastIndex = i;
  if (NUMBER.test(text)) return { end: NUMBER.lastIndex };
  return { offset: i, expected: mayClose ? "a value or ']'" : 'a value' };
}

/** The offset after the string that opens at `i`, or where it goes wrong. */
function scanString(text: string, i: number): number | JsonError {
  for (let k = i + 1; k < text.length; k++) {
    const c = text.charCodeAt(k);
    if (c === 0x22) return k + 1;
    if (c < 0x20) return { offset: k, expected: "a closing '\"' (control characters in strings must be escaped)" };
    if (c === 0x5c) {
      const e = text[k + 1];
      if (e === 'u') {
        if (!/^[0-9a-fA-F]{4}$/.test(text.slice(k + 2, k + 6))) return { offset: k, expected: 'an escape \\u followed by 4 hex digits' };
        k += 5;
      } else if (e !== undefined && '"\\/bfnrt'.includes(e)) k++;
      else return { offset: k, expected: 'an escape: \\" \\\\ \\/ \\b \\f \\n \\r \\t or \\uXXXX' };
    }
  }
  return { offset: text.length, expected: "a closing '\"' for the string" };
}
