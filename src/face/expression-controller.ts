import { EMFACS, emotionVariants, type EmotionVariant } from '../core/expression/emfacs';
import type { HeadPose } from '../core/expression/head-pose';
import { checkNumber, refusal } from '../core/check';
import { isActionUnitId, type ActionUnitListing, type PresetListing } from '../core/expression/facs';
import { facsCode, parseFACSCode } from '../core/expression/facs-code';
import { readExpression, type ExpressionEntries, type HashExpression } from './expression-hash';
import type { FaceParts } from './face-parts';

/** The face's expression: Action Unit sliders per side, preset weights, and the page's overlay on top of them. */
export class ExpressionController {
  constructor(private readonly parts: FaceParts) {}

  /**
   * Sets an Action Unit's intensity, 0..1 (clamped): `AU12` drives both sides, `AU12L` and `AU12R` one (the subject's
   * left is +x). An unknown id or a non-finite value throws an error naming it and changes nothing.
   */
  setActionUnit(id: string, value: number): void {
    this.parts.expressed().setActionUnit(id, value);
    this.parts.emit('expression');
  }

  /** The Action Unit sliders, per side: `{ AU1L: 0, AU1R: 0, ..., AU17: 0, ... }`. */
  getActionUnits(): Record<string, number> {
    return this.parts.expressed().getActionUnits();
  }

  /**
   * Replaces the whole expression: the Action Units and preset weights given are set, every other one goes to 0. As
   * text in the URL-hash form (`"AU12=0.8&AU6L=0.5&preset:happiness=0.3"`) or as an object of the same entries
   * (`{ AU12: 0.8, 'preset:happiness': 0.3 }`). An unknown id or preset, or a value that is not a finite number,
   * throws naming it and changes nothing.
   */
  setExpression(expression: string | ExpressionEntries): void {
    this.parts.expressed().set(readExpression(expression, 'setExpression'), 'setExpression');
    this.parts.emit('expression');
  }

  /**
   * Replaces the whole expression by a FACS code: units joined by `+` (`"1+2+5B+26"`), each an Action Unit number
   * with an optional side (`L`, `R`, or `U`: one side not coded, taken as the left) and intensity letter (A 0.1, B 0.2,
   * C 0.4, D 0.7, E 1; none is E); `""` or `"0"` is neutral. Presets go to 0. A unit the face does not have, a side on
   * a midline unit, a side given twice or a stray `+` throws naming the unit and its place
   * (`setFACS: at 5 of "1+2+99": expected an Action Unit the face has (...), got "99"`) and changes nothing.
   */
  setFACS(code: string): void {
    const terms = parseFACSCode(code, 'setFACS');
    const actionUnits: Record<string, number> = {};
    for (const t of terms) actionUnits[t.id] = t.intensity;
    this.parts.expressed().set({ actionUnits, presets: {} }, 'setFACS');
    this.parts.emit('expression');
  }

  /**
   * The expression as a FACS code: the Action Units the sliders and presets add up to (not the eye simulation's
   * lids), each with the letter of its grade, both sides as one unit where they share a grade (`"1E+2E+5B+26D"`,
   * `"L12C+R12A"`); `""` for the neutral face. `setFACS` of it gives back the same code.
   */
  getFACS(): string {
    return facsCode(this.parts.expressed().expressionIntensities());
  }

  /**
   * The faces of the EMFACS table (see `setEmotion`) a selector names: an emotion (`"fear"`: its prototypes, then its
   * major variants), an emotion and a kind (`"fear:prototype"`), or one face (`"fear-prototype-2"`); all of them
   * without a selector. Each has its name, emotion, kind, FACS code and source. A selector it does not know throws.
   */
  listEmotionVariants(selector?: string): EmotionVariant[] {
    return selector === undefined ? [...EMFACS] : emotionVariants(selector, 'listEmotionVariants');
  }

  /**
   * Sets the face to an emotion's face from the EMFACS table, as `setFACS` sets its code: one face by name
   * (`"fear-prototype-2"`, `"anger-variant-3"`), or an emotion's first prototype (`"fear"`, `"fear:variant"` for its
   * first variant). A selector it does not know throws, naming it, and changes nothing.
   */
  setEmotion(selector: string): void {
    const [face] = emotionVariants(selector, 'setEmotion');
    if (!face) throw refusal('setEmotion', '', 'an emotion with faces of that kind', selector);
    this.setFACS(face.code);
  }

  /**
   * The head pose the head positions (AU51 to AU58) ask for now: `yaw` toward the subject's left, `pitch` up, `roll`
   * toward the left shoulder (degrees) and `forward` (metres). The view turns the whole head by it about the neck's
   * pivot; `getSkin` gives the skin in the head's own frame, before this turn.
   */
  getHeadPose(): HeadPose {
    return this.parts.expressed().headPose();
  }

  /**
   * What each Action Unit side adds up to with the presets and the overlay (the eye simulation's lids), clamped to
   * 0..1, by side id like `getActionUnits`.
   */
  getEffectiveActionUnits(): Record<string, number> {
    return this.parts.expressed().effective();
  }

  /** Every Action Unit: id, FACS number, name and sides (`L`, `R` or `M`). */
  listActionUnits(): ActionUnitListing[] {
    return this.parts.expressed().listActionUnits();
  }

  /** Sets a preset's weight, 0..1 (clamped); presets and Action Units add up (and clamp) per side. */
  applyPreset(name: string, weight = 1): void {
    this.parts.expressed().applyPreset(name, weight);
    this.parts.emit('expression');
  }

  /** The rig's presets with their current weights. */
  listPresets(): PresetListing[] {
    return this.parts.expressed().listPresets();
  }

  /** Zeroes every Action Unit and preset: the neutral face. */
  reset(): void {
    this.parts.expressed().reset();
    this.parts.emit('expression');
  }

  /**
   * Sets the page's own contribution to some Action Unit sides (`ids[i]` to `values[i]`, each clamped to 0..1): it
   * adds to the sliders and presets (clamped per side) without moving them, and tells no listener, because it may
   * change every frame. The eye simulation drives the lids with it. Bad input throws and changes nothing.
   */
  setOverlay(ids: readonly string[], values: ArrayLike<number>): void {
    const expression = this.parts.expressed();
    if (ids.length !== values.length) throw refusal('setOverlay', 'values', `${ids.length} values, one per id`, values);
    for (let i = 0; i < ids.length; i++) {
      if (!isActionUnitId(ids[i])) throw refusal('setOverlay', `ids[${i}]`, 'an Action Unit id like "AU43", "AU43L" or "AU43R"', ids[i]);
      checkNumber('setOverlay', ids[i], values[i]);
    }
    expression.setOverlay(ids, values);
  }

  /** Removes the page's whole contribution (see `setOverlay`). */
  clearOverlay(): void {
    this.parts.expressed().clearOverlay();
  }

  /** The overlay by side id, like `getActionUnits`. */
  getOverlay(): Record<string, number> {
    return this.parts.expressed().getOverlay();
  }

  /** The sliders and preset weights as one expression (what a new head or a recording takes over). */
  current(): HashExpression {
    return {
      actionUnits: this.getActionUnits(),
      presets: Object.fromEntries(this.listPresets().map((p) => [p.name, p.weight])),
    };
  }

  /**
   * Sets the sliders and preset weights of a timeline frame (see `ExpressionState.setFrame`) and tells listeners if
   * they changed; returns whether they did. Does nothing before the face is ready.
   */
  applyFrame(ids: readonly string[], values: ArrayLike<number>, presets: readonly string[], weights: ArrayLike<number>): boolean {
    const expression = this.parts.expression;
    if (this.parts.disposed || !expression) return false;
    const changed = expression.setFrame(ids, values, presets, weights);
    if (changed) this.parts.emit('expression');
    return changed;
  }
}

/** The handle's methods that ExpressionController answers. */
export const EXPRESSION_METHODS = [
  'setActionUnit',
  'getActionUnits',
  'setExpression',
  'setFACS',
  'getFACS',
  'setEmotion',
  'listEmotionVariants',
  'getHeadPose',
  'getEffectiveActionUnits',
  'listActionUnits',
  'applyPreset',
  'listPresets',
  'reset',
  'setOverlay',
  'clearOverlay',
  'getOverlay',
] as const;
