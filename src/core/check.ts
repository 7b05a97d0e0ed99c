/**
 * Checking what callers hand the library, with one message format for what is refused:
 * `<what>: <path>: expected <what is accepted>, got <what came>`, as in `setLight: keyAzimuth: expected a number from
 * 0 to 360, got 400`. `what` names the method, option or file; `path` where in the input (left out for the input as a
 * whole). Rig documents and timelines list their problems in the same form (RigError, TimelineError).
 */

/** A number's accepted range: [least, greatest]. */
export type Range = readonly [number, number];

/** A short description of a found value for messages: `-0.01`, `"spring"`, `an array of 2 items`, `nothing`. */
export function show(x: unknown): string {
  if (x === undefined) return 'nothing';
  if (x === null || typeof x === 'number' || typeof x === 'boolean') return String(x);
  if (typeof x === 'string') return x.length > 40 ? `${JSON.stringify(x.slice(0, 40))}...` : JSON.stringify(x);
  if (Array.isArray(x)) return `an array of ${x.length} item${x.length === 1 ? '' : 's'}`;
  return typeof x === 'object' ? 'an object' : `a ${typeof x}`;
}

/** The error for one refused value: `<what>: <path>: expected <expected>, got <shown value>`. */
export function refusal(what: string, path: string, expected: string, got: unknown): Error {
  return new Error(`${what}: ${path ? `${path}: ` : ''}expected ${expected}, got ${show(got)}`);
}

/** What a number in `range` is called in messages: `a number from 0 to 1`, `an integer from 1 to 64`. */
export function numberIn(range: Range | undefined, integer = false): string {
  const kind = integer ? 'an integer' : 'a finite number';
  return range ? `${integer ? 'an integer' : 'a number'} from ${range[0]} to ${range[1]}` : kind;
}

/** A finite number (an integer if asked) within `range` if given; otherwise throws the refusal. */
export function checkNumber(what: string, path: string, value: unknown, range?: Range, integer = false): number {
  const ok =
    typeof value === 'number' &&
    Number.isFinite(value) &&
    (!integer || Number.isInteger(value)) &&
    (!range || (value >= range[0] && value <= range[1]));
  if (!ok) throw refusal(what, path, numberIn(range, integer), value);
  return value as number;
}

/** A boolean; otherwise throws the refusal. */
export function checkBoolean(what: string, path: string, value: unknown): boolean {
  if (typeof value !== 'boolean') throw refusal(what, path, 'true or false', value);
  return value;
}

/** One of `choices`; otherwise throws the refusal, listing them. */
export function checkChoice<T extends string>(what: string, path: string, value: unknown, choices: readonly T[]): T {
  if (!choices.includes(value as T)) throw refusal(what, path, `one of ${choices.map((c) => JSON.stringify(c)).join(', ')}`, value);
  return value as T;
}

/** A plain object (not null, not an array); otherwise throws the refusal. */
export function checkObject(what: string, value: unknown, expected = 'an object of options'): Record<string, unknown> {
  if (typeof value !== 'object' || value === null || Array.isArray(value)) throw refusal(what, '', expected, value);
  return value as Record<string, unknown>;
}

const COLOUR = /^#[0-9a-f]{6}$/i;

/** How the options of an options object are checked beyond their defaults' types. */
export interface OptionRules<T> {
  /** Accepted ranges of number options. */
  ranges?: Readonly<Partial<Record<keyof T, Range>>>;
  /** Number options that must be whole. */
  integers?: readonly (keyof T)[];
  /** Accepted values of string options; a string option with none listed is a colour `#rrggbb`. */
  choices?: Readonly<Partial<Record<keyof T, readonly string[]>>>;
}

/**
 * Checks an object of options against their defaults: each key one of the defaults', each value of its default's type,
 * numbers finite and in their ranges, strings among their choices (or colours). Returns the options given (a
 * `Partial`); throws the refusal of the first bad one, so that a caller changes nothing.
 */
export function checkOptions<T extends object>(
  what: string,
  partial: unknown,
  defaults: Readonly<Required<T>>,
  rules: OptionRules<T> = {},
): Partial<T> {
  const given = checkObject(what, partial);
  for (const [key, value] of Object.entries(given)) {
    if (!Object.hasOwn(defaults, key)) throw refusal(what, '', `one of the options ${Object.keys(defaults).join(', ')}`, key);
    const k = key as keyof T;
    const type = typeof defaults[k];
    if (type === 'number') checkNumber(what, key, value, rules.ranges?.[k], rules.integers?.includes(k));
    else if (type === 'boolean') checkBoolean(what, key, value);
    else if (type === 'string') {
      const choices = rules.choices?.[k];
      if (choices) checkChoice(what, key, value, choices);
      else if (typeof value !== 'string' || !COLOUR.test(value)) throw refusal(what, key, 'a colour "#rrggbb"', value);
    } else if (typeof value !== type) throw refusal(what, key, `a ${type}`, value);
  }
  return given as Partial<T>;
}
