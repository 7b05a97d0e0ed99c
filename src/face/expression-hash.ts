/**
 * An expression as text, the form the app keeps in its URL hash (so that a copied link reopens the same face) and
 * embedding pages give to `createFace` and `<soft-face>`: `AU12L=0.5&AU12R=0.5&preset:happiness=0.3` (non-zero
 * values only; `URLSearchParams` writes the colon as `%3A`, and either form reads back; a leading `#` is optional).
 */
import { refusal } from '../core/check';

/** What the hash carries: Action Unit sliders by side id, and preset weights by name. */
export interface HashExpression {
  /** Action Unit intensities by id as `setActionUnit` takes them (`AU12`, `AU12L`, `AU17`); the face clamps to 0..1. */
  actionUnits: Record<string, number>;
  /** Preset weights by the preset's name in the rig (`happiness`, no `preset:` prefix); the face clamps to 0..1. */
  presets: Record<string, number>;
}

/** The same entries as the text, as an object: `{ AU12: 0.8, 'preset:happiness': 0.3 }`. */
export type ExpressionEntries = Readonly<Record<string, number>>;

const PRESET_PREFIX = 'preset:';

/** The hash entry that carries a timeline document, as compact JSON: `timeline={"format":...}`. */
const TIMELINE_HASH_KEY = 'timeline';

/**
 * Hash entries that carry the face's appearance (`appearance.browDensity=0.5`, `appearance.lashes=0`), only where it
 * differs from the defaults; they are not expression entries.
 */
const APPEARANCE_HASH_PREFIX = 'appearance.';

/** The hash entry that carries the person shown (see `identityText`): `identity=old-african-woman`. */
const IDENTITY_HASH_KEY = 'identity';

/** The hash entry that sets the expression by a FACS code (see `setFACS`), a way in for links: `facs=1+2+5B+26`. */
const FACS_HASH_KEY = 'facs';

/** Longest timeline JSON the app puts in its URL hash, in characters: longer ones make links too long to share. */
export const MAX_HASH_TIMELINE_CHARS = 1500;

/**
 * The hash (with its `#`) for an expression, and a timeline's JSON text, appearance changes and the identity's text
 * form if given; zero values are left out.
 */
export function encodeExpression(e: HashExpression, timeline?: string, appearance: HashAppearance = {}, identity?: string): string {
  const params = new URLSearchParams();
  if (identity !== undefined) params.set(IDENTITY_HASH_KEY, identity);
  for (const [id, v] of Object.entries(e.actionUnits)) if (v !== 0) params.set(id, String(round(v)));
  for (const [name, w] of Object.entries(e.presets)) if (w !== 0) params.set(PRESET_PREFIX + name, String(round(w)));
  for (const [key, value] of Object.entries(appearance)) {
    params.set(
      APPEARANCE_HASH_PREFIX + key,
      typeof value === 'boolean' ? (value ? '1' : '0') : typeof value === 'number' ? String(round(value)) : value,
    );
  }
  if (timeline !== undefined) params.set(TIMELINE_HASH_KEY, timeline);
  const text = params.toString();
  return text ? `#${text}` : '';
}

/** Reads an expression from a hash (with or without its `#`); entries that are not finite numbers are skipped. */
export function decodeExpression(hash: string): HashExpression {
  const out: HashExpression = { actionUnits: {}, presets: {} };
  for (const [key, text] of new URLSearchParams(hash.replace(/^#/, ''))) {
    if (key === TIMELINE_HASH_KEY || key === IDENTITY_HASH_KEY || key === FACS_HASH_KEY || key.startsWith(APPEARANCE_HASH_PREFIX)) continue;
    const value = Number(text);
    if (text.trim() === '' || !Number.isFinite(value)) continue;
    if (key.startsWith(PRESET_PREFIX)) out.presets[key.slice(PRESET_PREFIX.length)] = value;
    else out.actionUnits[key] = value;
  }
  return out;
}

/** Appearance options as a hash carries them: booleans, numbers and colours by option name. */
export type HashAppearance = Record<string, boolean | number | string>;

/**
 * The appearance entries of a hash, typed by the defaults (`1`/`0` for switches, numbers, `#rrggbb` colours); entries
 * of unknown options or of the wrong form are kept as given, for the face to refuse with its own message.
 */
export function decodeAppearance(hash: string, defaults: Readonly<HashAppearance>): HashAppearance {
  const out: HashAppearance = {};
  for (const [key, text] of new URLSearchParams(hash.replace(/^#/, ''))) {
    if (!key.startsWith(APPEARANCE_HASH_PREFIX)) continue;
    const name = key.slice(APPEARANCE_HASH_PREFIX.length);
    const kind = typeof defaults[name];
    if (kind === 'boolean' && (text === '1' || text === '0')) out[name] = text === '1';
    else if (kind === 'number' && text.trim() !== '' && Number.isFinite(Number(text))) out[name] = Number(text);
    else out[name] = text;
  }
  return out;
}

/** The options of `current` that differ from `defaults`: what a hash needs to carry. */
export function appearanceChanges(current: Readonly<HashAppearance>, defaults: Readonly<HashAppearance>): HashAppearance {
  const out: HashAppearance = {};
  for (const [key, value] of Object.entries(current)) {
    const same =
      typeof value === 'string' && typeof defaults[key] === 'string'
        ? value.toLowerCase() === (defaults[key] as string).toLowerCase()
        : value === defaults[key];
    if (!same) out[key] = value;
  }
  return out;
}

/** The identity text a hash carries (a stock name or `sex:1,age:30,african:1`), or null. */
export function decodeIdentity(hash: string): string | null {
  return new URLSearchParams(hash.replace(/^#/, '')).get(IDENTITY_HASH_KEY);
}

/**
 * The FACS code a hash carries (`facs=1+2+5B+26`; the query form reads its plus signs as spaces, which a code may have
 * between units), or null. The app writes the expression back as sliders: the code is a way in.
 */
export function decodeFACS(hash: string): string | null {
  return new URLSearchParams(hash.replace(/^#/, '')).get(FACS_HASH_KEY);
}

/** The timeline JSON text a hash carries (see `encodeExpression`), or null. */
export function decodeTimeline(hash: string): string | null {
  return new URLSearchParams(hash.replace(/^#/, '')).get(TIMELINE_HASH_KEY);
}

/**
 * Reads an expression given as text or as entries, strictly: an entry whose value is not a finite number throws an
 * error naming it (`what` says where it came from). Whether the ids and preset names exist is the face's to check.
 */
export function readExpression(expression: string | ExpressionEntries, what = 'expression'): HashExpression {
  const out: HashExpression = { actionUnits: {}, presets: {} };
  const add = (key: string, value: number, given: unknown): void => {
    if (!Number.isFinite(value)) throw refusal(what, key, 'a finite number', given);
    if (key.startsWith(PRESET_PREFIX)) out.presets[key.slice(PRESET_PREFIX.length)] = value;
    else out.actionUnits[key] = value;
  };
  if (typeof expression === 'string') {
    // An empty value is a mistake, not 0.
    for (const [key, text] of new URLSearchParams(expression.trim().replace(/^#/, '')))
      add(key, text.trim() === '' ? NaN : Number(text), text);
  } else if (typeof expression === 'object' && expression !== null && !Array.isArray(expression)) {
    for (const [key, value] of Object.entries(expression)) add(key, typeof value === 'number' ? value : NaN, value);
  } else {
    throw refusal(what, '', 'text like "AU12=0.8&preset:happiness=0.3" or an object like { AU12: 0.8 }', expression);
  }
  return out;
}

/** An expression as the entries of its text: `{ AU12L: 0.5, 'preset:happiness': 0.3 }`. */
export function expressionEntries(e: HashExpression): Record<string, number> {
  const out: Record<string, number> = { ...e.actionUnits };
  for (const [name, weight] of Object.entries(e.presets)) out[PRESET_PREFIX + name] = weight;
  return out;
}

/** Slider values have two decimals; four keep the link short without changing them. */
function round(x: number): number {
  return Math.round(x * 1e4) / 1e4;
}
