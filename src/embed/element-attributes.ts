import { refusal } from '../core/check';
import { facsIntensities } from '../core/expression/facs-code';
import { readIdentity } from '../core/head/identity';
import { readExpression, type HashExpression } from '../face/expression-hash';
import { checkFaceOption, type Resolution, type SolverChoice } from '../face/face-options';

/** The attributes `<soft-face>` reads. */
export const FACE_ATTRIBUTES = [
  'resolution',
  'expression',
  'facs',
  'preset',
  'solver',
  'panels',
  'eye-simulation',
  'background',
  'identity',
] as const;
export type FaceAttribute = (typeof FACE_ATTRIBUTES)[number];

/** What the attributes ask for, read and checked. */
export interface FaceAttributeValues {
  resolution: Resolution;
  solver: SolverChoice;
  panels: boolean;
  eyeSimulation: boolean;
  background: string;
  /** The expression and preset attributes together (presets named in both take the preset attribute's weight). */
  expression: HashExpression;
  preset: HashExpression;
  /** The facs attribute's Action Units (`1+2+5B+26`, see `setFACS`), under the expression attribute's. */
  facs: Record<string, number>;
  /** The person shown (a stock name or `sex:1,age:30,african:1`), null for the default head. */
  identity: string | null;
}

/** Each attribute as it reads when absent. */
const ABSENT: Readonly<Record<FaceAttribute, string>> = Object.freeze({
  resolution: 'medium',
  expression: '',
  facs: '',
  preset: '',
  solver: 'auto',
  panels: 'false',
  'eye-simulation': 'false',
  background: '#1d2024',
  identity: '',
});

/** How messages about attributes start: `<soft-face>: resolution: expected ...`. */
const WHAT = '<soft-face>';

/**
 * A boolean attribute: present (empty, or its own name) or `"true"` is on, absent or `"false"` is off; anything else
 * is a mistake rather than silently on.
 */
function readBoolean(name: string, value: string): boolean {
  const v = value.trim().toLowerCase();
  if (v === '' || v === 'true' || v === name) return true;
  if (v === 'false') return false;
  throw refusal(WHAT, name, 'present (on), "true" or "false"', value);
}

/** `happiness:1`, or several: `happiness:0.5, surprise:0.3` (a name alone means weight 1). */
export function readPresets(value: string): HashExpression {
  const out: HashExpression = { actionUnits: {}, presets: {} };
  for (const entry of value.split(/[\s,]+/).filter((e) => e !== '')) {
    const colon = entry.lastIndexOf(':');
    const preset = colon < 0 ? entry : entry.slice(0, colon);
    const text = colon < 0 ? '1' : entry.slice(colon + 1);
    const weight = text.trim() === '' ? NaN : Number(text);
    if (preset === '' || !Number.isFinite(weight)) throw refusal(WHAT, 'preset', 'a preset name and a weight, like "happiness:0.5"', entry);
    out.presets[preset] = weight;
  }
  return out;
}

/**
 * Reads the attributes (`get` gives each one's value, null when absent) into the options they ask for; a bad value
 * throws an error that names the attribute and says what it must be. Only `only` is read when given; the rest keep
 * the values in `current`. Preset names and Action Unit ids are checked against the face's rig when applied.
 */
export function readAttributes(
  get: (attribute: FaceAttribute) => string | null,
  current: FaceAttributeValues,
  only?: FaceAttribute,
): FaceAttributeValues {
  const out = { ...current };
  const read = (attribute: FaceAttribute): string => get(attribute) ?? ABSENT[attribute];
  const wanted = (attribute: FaceAttribute): boolean => only === undefined || only === attribute;
  if (wanted('resolution')) out.resolution = checkFaceOption('resolution', read('resolution').trim(), WHAT);
  if (wanted('solver')) out.solver = checkFaceOption('solver', read('solver').trim(), WHAT);
  if (wanted('background')) out.background = checkFaceOption('background', read('background').trim(), WHAT);
  if (wanted('panels')) out.panels = readBoolean('panels', read('panels'));
  if (wanted('eye-simulation')) out.eyeSimulation = readBoolean('eye-simulation', read('eye-simulation'));
  if (wanted('expression')) out.expression = readExpression(read('expression'), `${WHAT} expression`);
  if (wanted('preset')) out.preset = readPresets(read('preset'));
  if (wanted('facs')) out.facs = facsIntensities(read('facs'), `${WHAT} facs`);
  if (wanted('identity')) {
    const text = read('identity').trim();
    out.identity = text === '' ? null : text;
    readIdentity(out.identity, `${WHAT} identity`);
  }
  return out;
}

/** What the attributes ask for when none is given. */
export const ATTRIBUTE_DEFAULTS: Readonly<FaceAttributeValues> = Object.freeze(readAttributes(() => null, {} as FaceAttributeValues));
