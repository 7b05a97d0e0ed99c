import { clamp01 } from '../core/math3';
import { ACTION_UNIT_ID, checkNumber, refusal } from '../core/check';
import { ExpressionState, isActionUnitId, type ActionUnitListing, type PresetListing } from '../core/expression/facs';
import type { Rig } from '../core/rig/rig-types';
import type { HashExpression } from './expression-hash';
import { actionUnitHeadPose, restingHeadPose, type HeadPose } from '../core/expression/head-pose';

/** Where a face's muscle contractions go after every change: the solver, the jaw's teeth, the muscle glyphs. */
export type ContractionSink = (contractions: Float32Array) => void;
/** Where a face's head pose (AU51 to AU58) goes when it changes: the solver's neck and the view's head. */
export type HeadPoseSink = (pose: HeadPose) => void;

/**
 * A face's expression: the Action Unit sliders, preset weights and overlay of its rig, and the muscle contractions
 * they add up to, handed to the sink after every change. Bad input throws, naming it, and changes nothing.
 */
export class FaceExpression {
  private state: ExpressionState;
  /** Contraction per rig muscle, reused for every change. */
  private contractions: Float32Array;
  /** A muscle contracted on its own while it is edited (index and contraction), on top of the Action Units. */
  private preview: { index: number; value: number } | null = null;

  /** The head pose last sent, and the one each change computes (reused). */
  private readonly sentPose = restingHeadPose();
  private readonly pose = restingHeadPose();
  private readonly read = (id: string): number => this.state.effectiveOf(id);

  constructor(
    private rigNow: Rig,
    private readonly sink: ContractionSink,
    private readonly poseSink?: HeadPoseSink,
  ) {
    this.state = new ExpressionState(rigNow.presets);
    this.contractions = new Float32Array(rigNow.muscles.length);
  }

  /** The rig the expression drives. */
  get rig(): Rig {
    return this.rigNow;
  }

  /**
   * Drives an edited rig from now on and sends its contractions (unless `send` is false: the muscles' shapes alone
   * changed, not what drives them). The sliders stay; preset weights stay when the
   * presets did not change (they start from 0 otherwise); a preview is dropped if its muscle is gone.
   */
  setRig(rig: Rig, send = true): void {
    if (JSON.stringify(rig.presets) !== JSON.stringify(this.rigNow.presets)) {
      const sliders = this.state.getActionUnits();
      const overlay = this.state.getOverlay();
      const resting = this.state.getResting();
      this.state = new ExpressionState(rig.presets);
      for (const [id, value] of Object.entries(sliders)) this.state.setActionUnit(id, value);
      for (const [id, value] of Object.entries(overlay)) this.state.setOverlay(id, value);
      this.state.setResting(resting);
    }
    this.rigNow = rig;
    if (this.contractions.length !== rig.muscles.length) this.contractions = new Float32Array(rig.muscles.length);
    if (this.preview && this.preview.index >= rig.muscles.length) this.preview = null;
    if (send) this.send();
  }

  /** Sets the face's resting pull (see ExpressionState.setResting) and sends. */
  setResting(intensities: Readonly<Record<string, number>>): void {
    this.state.setResting(intensities);
    this.send();
  }

  /** Contracts muscle `index` by at least `value` (0..1) while it is edited; null ends the preview. */
  setPreview(index: number | null, value = 0): void {
    this.preview = index === null ? null : { index, value: clamp01(value) };
    this.send();
  }

  /** Sets an Action Unit's intensity (clamped to 0..1): `AU12` both sides, `AU12L` / `AU12R` one. */
  setActionUnit(id: string, value: number): void {
    this.state.setActionUnit(id, value);
    this.send();
  }

  /** Sets a preset's weight (clamped to 0..1). */
  applyPreset(name: string, weight: number): void {
    this.state.applyPreset(name, weight);
    this.send();
  }

  /** Zeroes every Action Unit and preset; the overlay stays. */
  reset(): void {
    this.state.reset();
    this.send();
  }

  /**
   * Replaces the sliders and preset weights by those given (the rest go to 0). Every id, preset name and value is
   * checked before anything changes.
   */
  set(expression: HashExpression, what = 'expression'): void {
    checkExpression(
      expression,
      this.state.listPresets().map((p) => p.name),
      what,
    );
    this.state.reset();
    for (const [id, value] of Object.entries(expression.actionUnits)) this.state.setActionUnit(id, value);
    for (const [name, weight] of Object.entries(expression.presets)) this.state.applyPreset(name, weight);
    this.send();
  }

  /** Sets some sliders and preset weights as a player's frame does (see `ExpressionState.setFrame`); sends only if they changed. */
  setFrame(ids: readonly string[], values: ArrayLike<number>, presets: readonly string[], weights: ArrayLike<number>): boolean {
    const changed = this.state.setFrame(ids, values, presets, weights);
    if (changed) this.send();
    return changed;
  }

  /** Sets overlay entries (see FaceHandle.setOverlay); sends only if the overlay changed. Allocates nothing. */
  setOverlay(ids: readonly string[], values: ArrayLike<number>): void {
    let changed = false;
    for (let i = 0; i < ids.length; i++) if (this.state.setOverlay(ids[i], values[i])) changed = true;
    if (changed) this.send();
  }

  clearOverlay(): void {
    if (this.state.clearOverlay()) this.send();
  }

  getActionUnits(): Record<string, number> {
    return this.state.getActionUnits();
  }

  getOverlay(): Record<string, number> {
    return this.state.getOverlay();
  }

  /** What each side adds up to with the presets and the overlay, clamped to 0..1. */
  effective(): Record<string, number> {
    return this.state.effective();
  }

  /** One side's (or midline unit's) effective intensity, without building a record: for a per-frame reader. */
  effectiveOf(id: string): number {
    return this.state.effectiveOf(id);
  }

  /** What each side adds up to with the presets, without the overlay and the resting pull (see `getFACS`). */
  expressionIntensities(): Record<string, number> {
    return this.state.expressionIntensities();
  }

  listActionUnits(): ActionUnitListing[] {
    return this.state.listActionUnits();
  }

  listPresets(): PresetListing[] {
    return this.state.listPresets();
  }

  private send(): void {
    const c = this.state.muscleContractions(this.rigNow, this.contractions);
    if (this.preview && this.preview.index < c.length) c[this.preview.index] = Math.max(c[this.preview.index], this.preview.value);
    this.sink(c);
    if (!this.poseSink) return;
    const p = actionUnitHeadPose(this.read, this.pose);
    const s = this.sentPose;
    if (p.yaw === s.yaw && p.pitch === s.pitch && p.roll === s.roll && p.forward === s.forward) return;
    Object.assign(s, p);
    this.poseSink(p);
  }

  /** The head pose the head positions ask for now (a copy). */
  headPose(): HeadPose {
    return { ...actionUnitHeadPose(this.read, this.pose) };
  }
}

/**
 * Checks an expression's Action Unit ids against the catalogue and its presets against `presets` (a rig's preset
 * names), and that every value is finite; throws an error starting with `what` and naming the first bad entry.
 */
export function checkExpression(expression: HashExpression, presets: readonly string[], what: string): void {
  for (const [id, value] of Object.entries(expression.actionUnits)) {
    if (!isActionUnitId(id)) throw refusal(what, '', ACTION_UNIT_ID, id);
    checkNumber(what, id, value);
  }
  for (const [name, weight] of Object.entries(expression.presets)) {
    if (!presets.includes(name)) throw refusal(what, '', `one of the presets ${presets.join(', ') || '(none)'}`, name);
    checkNumber(what, `preset:${name}`, weight);
  }
}
