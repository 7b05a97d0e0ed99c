/**
 * Who a head shows: sex, age and ancestry, as MakeHuman's macro targets model them on the hm08 base mesh, and which
 * of those targets make a given identity with what weights. Pure: the targets' offsets are applied elsewhere.
 */
import { checkNumber, checkObject, refusal } from '../check';

/** Ancestry as weights (each 0..1; missing ones are 0): they are scaled to sum to 1. */
export interface Ancestry {
  /** African ancestry's weight, 0..1 (MakeHuman's `african` targets). */
  african: number;
  /** Asian ancestry's weight, 0..1 (MakeHuman's `asian` targets). */
  asian: number;
  /** European ancestry's weight, 0..1 (MakeHuman's `caucasian` targets). */
  european: number;
}

/** A person: `sex` from 0 (female) to 1 (male), `age` in years from 1 to 90, `ancestry` weights. */
export interface Identity {
  /** 0 female .. 1 male; values between blend the two (default 0.5). */
  sex: number;
  /** Age in years, 1..90 (default 25). */
  age: number;
  /** The ancestries' weights, scaled to sum to 1 (default a third each). */
  ancestry: Ancestry;
}

const ANCESTRIES = ['african', 'asian', 'european'] as const;
/** MakeHuman's names for the ancestries in its target files. */
const TARGET_ANCESTRY: Readonly<Record<keyof Ancestry, string>> = { african: 'african', asian: 'asian', european: 'caucasian' };
const AGE_RANGE = [1, 90] as const;

/** MakeHuman's average person: the base mesh's own proportions sit near it. */
export const IDENTITY_DEFAULTS: Readonly<Identity> = Object.freeze({
  sex: 0.5,
  age: 25,
  ancestry: Object.freeze({ african: 1 / 3, asian: 1 / 3, european: 1 / 3 }),
});

/**
 * Checks an identity as a caller gives it (`what` names the caller in messages): known fields only, `sex` 0..1, `age`
 * 1..90 years, ancestry weights 0..1 with a positive sum. Returns it whole, with missing fields from the defaults and
 * the ancestry scaled to sum to 1; throws `<what>: <field>: expected ..., got ...` otherwise.
 */
export function checkIdentity(value: unknown, what: string): Identity {
  const given = checkObject(what, value, 'an identity { sex, age, ancestry }');
  for (const key of Object.keys(given))
    if (!(key in IDENTITY_DEFAULTS)) throw refusal(what, '', 'one of the fields sex, age, ancestry', key);
  const sex = given.sex === undefined ? IDENTITY_DEFAULTS.sex : checkNumber(what, 'sex', given.sex, [0, 1]);
  const age = given.age === undefined ? IDENTITY_DEFAULTS.age : checkNumber(what, 'age', given.age, AGE_RANGE);
  if (given.ancestry === undefined) return { sex, age, ancestry: { ...IDENTITY_DEFAULTS.ancestry } };
  const weights = checkObject(`${what}: ancestry`, given.ancestry, 'an object of weights { african, asian, european }');
  const ancestry: Ancestry = { african: 0, asian: 0, european: 0 };
  for (const [key, w] of Object.entries(weights)) {
    if (!(ANCESTRIES as readonly string[]).includes(key))
      throw refusal(what, 'ancestry', `one of the ancestries ${ANCESTRIES.join(', ')}`, key);
    ancestry[key as keyof Ancestry] = checkNumber(what, `ancestry.${key}`, w, [0, 1]);
  }
  const sum = ancestry.african + ancestry.asian + ancestry.european;
  if (!(sum > 0)) throw refusal(what, 'ancestry', 'weights with a positive sum', sum);
  for (const key of ANCESTRIES) ancestry[key] /= sum;
  return { sex, age, ancestry };
}

/**
 * MakeHuman's age slider for an age in years: 1 year is 0, 25 years 0.5 and 90 years 1, linear on each half
 * (MakeHuman 1.x, `apps/human.py`).
 */
export function ageSlider(years: number): number {
  return years <= 25 ? (0.5 * (years - 1)) / 24 : 0.5 + (0.5 * (years - 25)) / 65;
}

/** The age groups of the target files, and the slider values at which each is whole. */
const AGE_KNOTS = [
  ['baby', 0],
  ['child', 0.1875],
  ['young', 0.5],
  ['old', 1],
] as const;

/** One macro target file (without `.target.gz`) and its weight. */
export interface TargetWeight {
  target: string;
  weight: number;
}

/**
 * The macro targets that make `identity` from the base mesh, with their weights, as MakeHuman 1.x blends them: sex
 * and age each split linearly between the two neighbouring groups (female/male; baby, child, young, old at the knots
 * 0, 0.1875, 0.5, 1 of the age slider), ancestry as given (summing to 1), and each `<ancestry>-<sex>-<age>` file
 * weighted by the product. Muscle and weight stay average, whose `universal-*-averagemuscle-averageweight` files
 * move nothing, so they are left out, as are files of weight 0. The weights sum to 1.
 */
export function macroTargetWeights(identity: Identity): TargetWeight[] {
  const sexes: [string, number][] = [
    ['female', 1 - identity.sex],
    ['male', identity.sex],
  ];
  const a = ageSlider(identity.age);
  const ages: [string, number][] = [];
  for (let k = 0; k + 1 < AGE_KNOTS.length; k++) {
    const [lowName, lo] = AGE_KNOTS[k];
    const [highName, hi] = AGE_KNOTS[k + 1];
    if (a >= lo && a <= hi) {
      const t = (a - lo) / (hi - lo);
      ages.push([lowName, 1 - t], [highName, t]);
      break;
    }
  }
  const out: TargetWeight[] = [];
  for (const ancestry of ANCESTRIES) {
    const r = identity.ancestry[ancestry];
    for (const [sex, s] of sexes)
      for (const [age, w] of ages) {
        const weight = r * s * w;
        if (weight > 0) out.push({ target: `${TARGET_ANCESTRY[ancestry]}-${sex}-${age}`, weight });
      }
  }
  return out;
}

/** A macro target: the base mesh's vertices it moves (indices into `base.obj`'s `v` lines) and their offsets. */
export interface MacroTarget {
  indices: Uint32Array;
  /** xyz per listed vertex, in the base mesh's units (decimetres). */
  offsets: Float32Array;
}

/**
 * Reads a macro target file's text (`index dx dy dz` per line; the file's gzip taken off); `source` names it in
 * messages. A line that is not four numbers, or an index outside `vertexCount`, throws naming the line.
 */
export function parseMacroTarget(text: string, vertexCount: number, source: string): MacroTarget {
  const lines = text.split('\n').filter((l) => l.trim() !== '');
  const indices = new Uint32Array(lines.length);
  const offsets = new Float32Array(3 * lines.length);
  lines.forEach((line, i) => {
    const parts = line.trim().split(/\s+/).map(Number);
    const index = parts[0];
    if (parts.length !== 4 || !parts.every(Number.isFinite) || !Number.isInteger(index) || index < 0 || index >= vertexCount)
      throw refusal(source, `line ${i + 1}`, `"index dx dy dz" with an index below ${vertexCount}`, line);
    indices[i] = index;
    offsets.set(parts.slice(1), 3 * i);
  });
  return { indices, offsets };
}

/** Adds the weighted targets' offsets to `positions` (xyz per base vertex, in place). */
export function applyMacroTargets(
  positions: Float32Array | Float64Array,
  targets: readonly { target: MacroTarget; weight: number }[],
): void {
  for (const { target, weight } of targets) {
    const { indices, offsets } = target;
    for (let i = 0; i < indices.length; i++) {
      const v = 3 * indices[i];
      positions[v] += weight * offsets[3 * i];
      positions[v + 1] += weight * offsets[3 * i + 1];
      positions[v + 2] += weight * offsets[3 * i + 2];
    }
  }
}

/** A few identities by name, for pages and studies that want repeatable faces: each sex, three ages, three ancestries. */
export const STOCK_IDENTITIES: Readonly<Record<string, Identity>> = Object.freeze(
  Object.fromEntries(
    (['woman', 'man'] as const).flatMap((person) =>
      (
        [
          ['young', 22],
          ['middle-aged', 45],
          ['old', 72],
        ] as const
      ).flatMap(([ageName, age]) =>
        ANCESTRIES.map((ancestry) => [
          `${ageName}-${ancestry}-${person}`,
          Object.freeze({
            sex: person === 'man' ? 1 : 0,
            age,
            ancestry: Object.freeze({ african: 0, asian: 0, european: 0, [ancestry]: 1 }),
          }),
        ]),
      ),
    ),
  ),
);

/** A named identity of the stock set (see `listIdentities`). */
export interface NamedIdentity {
  /**
   * The stock name, as `setIdentity` and the `identity` option take it: `<age>-<ancestry>-<woman|man>`, such as
   * `young-african-woman` (ages: `young` 22, `middle-aged` 45, `old` 72 years).
   */
  name: string;
  /** The person the name stands for (a copy). */
  identity: Identity;
}

/** The stock identities, by name, in a stable order. */
export function stockIdentities(): NamedIdentity[] {
  return Object.entries(STOCK_IDENTITIES).map(([name, identity]) => ({ name, identity: structuredClone(identity) as Identity }));
}

/**
 * Reads an identity as callers give it: a stock name, an object `{ sex, age, ancestry }` (missing fields default), or
 * null for the default head. Throws naming the field (`<what>: ...`) for anything else.
 */
export function readIdentity(value: unknown, what: string): NamedIdentity | null {
  if (value === null) return null;
  if (typeof value === 'string') {
    const stock = STOCK_IDENTITIES[value.trim()];
    if (stock) return { identity: structuredClone(stock) as Identity, name: value.trim() };
    if (!value.includes(':'))
      throw refusal(
        what,
        '',
        `a stock identity (${Object.keys(STOCK_IDENTITIES).join(', ')}) or text like "sex:1,age:30,african:1"`,
        value,
      );
    const identity = checkIdentity(parseIdentityText(value, what), what);
    return { identity, name: identityText(identity) };
  }
  const identity = checkIdentity(value, what);
  return { identity, name: identityText(identity) };
}

/** Whether two identities are the same person (within a thousandth). */
export function sameIdentity(a: Identity, b: Identity): boolean {
  const near = (x: number, y: number): boolean => Math.abs(x - y) < 1e-3;
  return (
    near(a.sex, b.sex) &&
    near(a.age, b.age) &&
    near(a.ancestry.african, b.ancestry.african) &&
    near(a.ancestry.asian, b.ancestry.asian) &&
    near(a.ancestry.european, b.ancestry.european)
  );
}

/**
 * The text form of an identity, as URL hashes and the `identity` attribute carry it: its stock name, else
 * `sex:1,age:30,african:0.5,european:0.5`.
 */
export function identityText(identity: Identity): string {
  for (const [name, stock] of Object.entries(STOCK_IDENTITIES)) if (sameIdentity(stock, identity)) return name;
  const parts = [`sex:${+identity.sex.toFixed(4)}`, `age:${+identity.age.toFixed(3)}`];
  for (const key of ANCESTRIES) if (identity.ancestry[key] > 0) parts.push(`${key}:${+identity.ancestry[key].toFixed(4)}`);
  return parts.join(',');
}

/** Reads `sex:1,age:30,african:1` into the object form; a part that is not `name:number` throws naming it. */
function parseIdentityText(text: string, what: string): Record<string, unknown> {
  const out: Record<string, unknown> = {};
  const ancestry: Record<string, number> = {};
  for (const part of text.split(',')) {
    const [key, number, ...rest] = part.split(':').map((x) => x.trim());
    const value = Number(number);
    if (!key || number === undefined || number === '' || rest.length > 0 || !Number.isFinite(value))
      throw refusal(what, '', 'parts like "sex:1", "age:30" or "african:1" separated by commas', part);
    if ((ANCESTRIES as readonly string[]).includes(key)) ancestry[key] = value;
    else out[key] = value;
  }
  if (Object.keys(ancestry).length > 0) out.ancestry = ancestry;
  return out;
}
