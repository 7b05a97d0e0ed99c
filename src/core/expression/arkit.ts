/**
 * ARKit's 52 face blendshapes (Apple's ARFaceAnchor.BlendShapeLocation; MediaPipe's face landmarker and Live Link
 * give the same names) as FACS Action Units with sides. Each row of `ARKIT_MAPPING` says which unit a blendshape
 * drives and why, from Apple's description of the blendshape and the FACS manual's description of the unit (Ekman,
 * Friesen & Hager 2002). `Left` is the subject's left, as in ARKit. Blendshapes with no unit on this face (jaw thrust
 * and sideways, lip rolls, cheek puff, the tongue) are taken and show nothing. Pure: no DOM, no three.js.
 */
import { refusal, show } from '../check';

/** The 52 ARKit blendshape names, in Apple's order. */
export const ARKIT_BLENDSHAPES = Object.freeze([
  'eyeBlinkLeft',
  'eyeLookDownLeft',
  'eyeLookInLeft',
  'eyeLookOutLeft',
  'eyeLookUpLeft',
  'eyeSquintLeft',
  'eyeWideLeft',
  'eyeBlinkRight',
  'eyeLookDownRight',
  'eyeLookInRight',
  'eyeLookOutRight',
  'eyeLookUpRight',
  'eyeSquintRight',
  'eyeWideRight',
  'jawForward',
  'jawLeft',
  'jawRight',
  'jawOpen',
  'mouthClose',
  'mouthFunnel',
  'mouthPucker',
  'mouthLeft',
  'mouthRight',
  'mouthSmileLeft',
  'mouthSmileRight',
  'mouthFrownLeft',
  'mouthFrownRight',
  'mouthDimpleLeft',
  'mouthDimpleRight',
  'mouthStretchLeft',
  'mouthStretchRight',
  'mouthRollLower',
  'mouthRollUpper',
  'mouthShrugLower',
  'mouthShrugUpper',
  'mouthPressLeft',
  'mouthPressRight',
  'mouthLowerDownLeft',
  'mouthLowerDownRight',
  'mouthUpperUpLeft',
  'mouthUpperUpRight',
  'browDownLeft',
  'browDownRight',
  'browInnerUp',
  'browOuterUpLeft',
  'browOuterUpRight',
  'cheekPuff',
  'cheekSquintLeft',
  'cheekSquintRight',
  'noseSneerLeft',
  'noseSneerRight',
  'tongueOut',
] as const);

/** One of the 52 ARKit blendshape names. */
export type ARKitBlendshape = (typeof ARKIT_BLENDSHAPES)[number];

/** How a blendshape drives the face: the Action Unit sides it sets, and why. */
export interface BlendshapeMapping {
  blendshape: ARKitBlendshape;
  /** The Action Unit sides it drives (`AU12L`, `AU17`), none where the face has no such unit. */
  units: string[];
  /** Why: what the blendshape does and what the unit is. */
  why: string;
}

/** One row of the table: units a blendshape drives. */
const row = (blendshape: ARKitBlendshape, units: string[], why: string): BlendshapeMapping => ({ blendshape, units, why });

/**
 * The mapping, a row per blendshape in Apple's order. Where two blendshapes drive one midline unit (the nose's
 * sides, the lips' press) the unit takes the larger; the gaze's four directions per eye become the eye positions
 * (mean of the two eyes) and their vergence (the smaller of the two eyes' in or out).
 */
export const ARKIT_MAPPING: readonly BlendshapeMapping[] = Object.freeze([
  row('eyeBlinkLeft', ['AU43L'], 'the left lid closes: eyes closed (43), held as long as the tracker says'),
  row('eyeLookDownLeft', ['AU64'], 'the left eye looks down: eyes down (64), with the right eye’s'),
  row(
    'eyeLookInLeft',
    ['AU62', 'AU66'],
    'the left eye looks toward the nose: eyes right (62) with the right eye’s out, cross-eye (66) with its in',
  ),
  row('eyeLookOutLeft', ['AU61', 'AU65'], 'the left eye looks out: eyes left (61) with the right eye’s in, walleye (65) with its out'),
  row('eyeLookUpLeft', ['AU63'], 'the left eye looks up: eyes up (63), with the right eye’s'),
  row('eyeSquintLeft', ['AU7L'], 'the skin around the left eye tightens: lid tightener (7)'),
  row('eyeWideLeft', ['AU5L'], 'the left lids widen: upper lid raiser (5)'),
  row('eyeBlinkRight', ['AU43R'], 'as eyeBlinkLeft, the right eye'),
  row('eyeLookDownRight', ['AU64'], 'as eyeLookDownLeft'),
  row('eyeLookInRight', ['AU61', 'AU66'], 'the right eye looks toward the nose: eyes left (61), cross-eye (66)'),
  row('eyeLookOutRight', ['AU62', 'AU65'], 'the right eye looks out: eyes right (62), walleye (65)'),
  row('eyeLookUpRight', ['AU63'], 'as eyeLookUpLeft'),
  row('eyeSquintRight', ['AU7R'], 'as eyeSquintLeft, the right eye'),
  row('eyeWideRight', ['AU5R'], 'as eyeWideLeft, the right eye'),
  row('jawForward', [], 'the jaw thrusts forward: jaw thrust (29), which this face has not'),
  row('jawLeft', [], 'the jaw moves to the left: jaw sideways (30), which this face has not'),
  row('jawRight', [], 'the jaw moves to the right: jaw sideways (30), which this face has not'),
  row(
    'jawOpen',
    ['AU26', 'AU27', 'AU25'],
    'the jaw opens: jaw drop (26) over its first half, mouth stretch (27) over the second; ' +
      'the lips part (25) with it unless mouthClose holds them',
  ),
  row('mouthClose', ['AU25'], 'the lips close with the jaw open: takes its value off lips part (25)'),
  row('mouthFunnel', ['AU22'], 'the lips funnel: lip funneler (22)'),
  row('mouthPucker', ['AU18'], 'the lips pucker: lip pucker (18)'),
  row('mouthLeft', [], 'both lips move to the left: no FACS unit (the mouth’s sideways shift)'),
  row('mouthRight', [], 'both lips move to the right: no FACS unit'),
  row('mouthSmileLeft', ['AU12L'], 'the left corner rises and draws back: lip corner puller (12)'),
  row('mouthSmileRight', ['AU12R'], 'as mouthSmileLeft, the right corner'),
  row('mouthFrownLeft', ['AU15L'], 'the left corner goes down: lip corner depressor (15)'),
  row('mouthFrownRight', ['AU15R'], 'as mouthFrownLeft, the right corner'),
  row('mouthDimpleLeft', ['AU14L'], 'the left corner draws back and in: dimpler (14)'),
  row('mouthDimpleRight', ['AU14R'], 'as mouthDimpleLeft, the right corner'),
  row('mouthStretchLeft', ['AU20L'], 'the left corner stretches sideways: lip stretcher (20)'),
  row('mouthStretchRight', ['AU20R'], 'as mouthStretchLeft, the right corner'),
  row('mouthRollLower', [], 'the lower lip rolls in: lip suck (28), which this face has not'),
  row('mouthRollUpper', [], 'the upper lip rolls in: lip suck (28), which this face has not'),
  row('mouthShrugLower', ['AU17'], 'the lower lip and chin push up: chin raiser (17)'),
  row('mouthShrugUpper', ['AU10L', 'AU10R'], 'the upper lip pushes up: upper lip raiser (10)'),
  row('mouthPressLeft', ['AU24'], 'the lips press together: lip pressor (24), the larger of both sides'),
  row('mouthPressRight', ['AU24'], 'as mouthPressLeft'),
  row('mouthLowerDownLeft', ['AU16L'], 'the lower lip’s left side goes down: lower lip depressor (16)'),
  row('mouthLowerDownRight', ['AU16R'], 'as mouthLowerDownLeft, the right side'),
  row('mouthUpperUpLeft', ['AU10L'], 'the upper lip’s left side rises: upper lip raiser (10)'),
  row('mouthUpperUpRight', ['AU10R'], 'as mouthUpperUpLeft, the right side'),
  row('browDownLeft', ['AU4L'], 'the left brow lowers: brow lowerer (4)'),
  row('browDownRight', ['AU4R'], 'as browDownLeft, the right brow'),
  row('browInnerUp', ['AU1L', 'AU1R'], 'the inner brows rise: inner brow raiser (1), both sides'),
  row('browOuterUpLeft', ['AU2L'], 'the left brow’s outer part rises: outer brow raiser (2)'),
  row('browOuterUpRight', ['AU2R'], 'as browOuterUpLeft, the right brow'),
  row('cheekPuff', [], 'the cheeks puff out: cheek puff (34), which this face has not'),
  row('cheekSquintLeft', ['AU6L'], 'the left cheek rises under the eye: cheek raiser (6)'),
  row('cheekSquintRight', ['AU6R'], 'as cheekSquintLeft, the right cheek'),
  row('noseSneerLeft', ['AU9'], 'the nose wrinkles on the left: nose wrinkler (9), the larger of both sides'),
  row('noseSneerRight', ['AU9'], 'as noseSneerLeft'),
  row('tongueOut', [], 'the tongue shows: tongue show (19), which this face has not'),
]);

/** The Action Unit sides the blendshapes drive, in the order `blendshapeUnits` writes them. */
export const BLENDSHAPE_UNIT_IDS: readonly string[] = Object.freeze(
  [...new Set(ARKIT_MAPPING.flatMap((m) => m.units))].sort((a, b) => unitOrder(a) - unitOrder(b)),
);

function unitOrder(id: string): number {
  const m = /^AU(\d+)([LR]?)$/.exec(id)!;
  return 10 * Number(m[1]) + (m[2] === 'R' ? 2 : m[2] === 'L' ? 1 : 0);
}

const INDEX: ReadonlyMap<string, number> = new Map(ARKIT_BLENDSHAPES.map((name, i) => [name, i]));
const UNIT: ReadonlyMap<string, number> = new Map(BLENDSHAPE_UNIT_IDS.map((id, i) => [id, i]));

/**
 * Checks blendshape values (a record of names to numbers) and writes them, clamped to 0..1, into `into` (52 values
 * in Apple's order); names not given keep their values. Throws, starting with `what` and changing nothing, on a name
 * that is not one of the 52 or a value that is not a finite number.
 */
export function readBlendshapes(values: unknown, into: Float64Array, what = 'setBlendshapes'): void {
  if (typeof values !== 'object' || values === null || Array.isArray(values))
    throw refusal(what, '', 'an object of ARKit blendshape names and values 0..1', values);
  // Two passes over the keys (all checked before any is written), with no array of entries: a tracker calls this
  // every frame.
  const record = values as Record<string, unknown>;
  for (const name in record) {
    if (!Object.hasOwn(record, name)) continue;
    const value = record[name];
    if (!INDEX.has(name))
      throw new Error(`${what}: expected one of the 52 ARKit blendshape names (eyeBlinkLeft, jawOpen, ...), got ${show(name)}`);
    if (typeof value !== 'number' || !Number.isFinite(value)) throw refusal(what, name, 'a finite number', value);
  }
  for (const name in record) {
    if (Object.hasOwn(record, name)) into[INDEX.get(name)!] = Math.min(1, Math.max(0, record[name] as number));
  }
}

/** Blendshape `name`'s value in `b` (Apple's order). */
function val(b: Float64Array, name: ARKitBlendshape): number {
  return b[INDEX.get(name)!];
}

/** Writes Action Unit side `id`'s intensity, clamped to 0..1, into `out` (BLENDSHAPE_UNIT_IDS' order). */
function put(out: Float64Array, id: string, x: number): void {
  out[UNIT.get(id)!] = Math.min(1, Math.max(0, x));
}

/**
 * Writes the Action Unit intensities of blendshape values `b` (52, Apple's order) into `out` (BLENDSHAPE_UNIT_IDS'
 * order), as `ARKIT_MAPPING` says. Allocates nothing.
 */
export function blendshapeUnits(b: Float64Array, out: Float64Array): Float64Array {
  out.fill(0);
  put(out, 'AU1L', val(b, 'browInnerUp'));
  put(out, 'AU1R', val(b, 'browInnerUp'));
  put(out, 'AU2L', val(b, 'browOuterUpLeft'));
  put(out, 'AU2R', val(b, 'browOuterUpRight'));
  put(out, 'AU4L', val(b, 'browDownLeft'));
  put(out, 'AU4R', val(b, 'browDownRight'));
  put(out, 'AU5L', val(b, 'eyeWideLeft'));
  put(out, 'AU5R', val(b, 'eyeWideRight'));
  put(out, 'AU6L', val(b, 'cheekSquintLeft'));
  put(out, 'AU6R', val(b, 'cheekSquintRight'));
  put(out, 'AU7L', val(b, 'eyeSquintLeft'));
  put(out, 'AU7R', val(b, 'eyeSquintRight'));
  put(out, 'AU9', Math.max(val(b, 'noseSneerLeft'), val(b, 'noseSneerRight')));
  put(out, 'AU10L', Math.max(val(b, 'mouthUpperUpLeft'), val(b, 'mouthShrugUpper')));
  put(out, 'AU10R', Math.max(val(b, 'mouthUpperUpRight'), val(b, 'mouthShrugUpper')));
  put(out, 'AU12L', val(b, 'mouthSmileLeft'));
  put(out, 'AU12R', val(b, 'mouthSmileRight'));
  put(out, 'AU14L', val(b, 'mouthDimpleLeft'));
  put(out, 'AU14R', val(b, 'mouthDimpleRight'));
  put(out, 'AU15L', val(b, 'mouthFrownLeft'));
  put(out, 'AU15R', val(b, 'mouthFrownRight'));
  put(out, 'AU16L', val(b, 'mouthLowerDownLeft'));
  put(out, 'AU16R', val(b, 'mouthLowerDownRight'));
  put(out, 'AU17', val(b, 'mouthShrugLower'));
  put(out, 'AU18', val(b, 'mouthPucker'));
  put(out, 'AU20L', val(b, 'mouthStretchLeft'));
  put(out, 'AU20R', val(b, 'mouthStretchRight'));
  put(out, 'AU22', val(b, 'mouthFunnel'));
  put(out, 'AU24', Math.max(val(b, 'mouthPressLeft'), val(b, 'mouthPressRight')));
  const open = val(b, 'jawOpen');
  put(out, 'AU25', open - val(b, 'mouthClose'));
  put(out, 'AU26', 2 * open);
  put(out, 'AU27', 2 * open - 1);
  put(out, 'AU43L', val(b, 'eyeBlinkLeft'));
  put(out, 'AU43R', val(b, 'eyeBlinkRight'));
  // The gaze: each eye's four directions, the two eyes' mean for the eye positions, the smaller for vergence.
  put(out, 'AU61', (val(b, 'eyeLookOutLeft') + val(b, 'eyeLookInRight')) / 2);
  put(out, 'AU62', (val(b, 'eyeLookInLeft') + val(b, 'eyeLookOutRight')) / 2);
  put(out, 'AU63', (val(b, 'eyeLookUpLeft') + val(b, 'eyeLookUpRight')) / 2);
  put(out, 'AU64', (val(b, 'eyeLookDownLeft') + val(b, 'eyeLookDownRight')) / 2);
  put(out, 'AU65', Math.min(val(b, 'eyeLookOutLeft'), val(b, 'eyeLookOutRight')));
  put(out, 'AU66', Math.min(val(b, 'eyeLookInLeft'), val(b, 'eyeLookInRight')));
  return out;
}
