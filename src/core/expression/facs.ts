/**
 * The FACS side of the face: the Action Units the product offers (thesis 3.3 and 4.5), FACS intensity grades, and
 * the expression state that turns Action Unit sliders and preset weights into muscle contractions. Pure: no DOM.
 */

import { clamp01 } from '../math3';
import { ACTION_UNIT_ID, checkNumber, refusal, show } from '../check';
import type { PresetDefinition, Rig } from '../rig/rig-types';

/** An Action Unit of the catalogue: id `AU12`, its FACS number and name, and whether each side is set on its own. */
export interface ActionUnitInfo {
  readonly id: string;
  readonly number: number;
  readonly name: string;
  readonly bilateral: boolean;
}

/**
 * Bilateral units get one slider per side (`AU12L`, `AU12R`; left is the subject's left, +x); midline units get one.
 *
 * Midline, because the action is one structure or its sides never act apart in this rig:
 * - AU9 nose wrinkler: FACS scores it for the nose as a whole, and the thesis contracts its two muscles as one unit;
 *   a one-sided AU9 reads as AU10 (upper lip raiser), which is bilateral here.
 * - AU17 chin raiser: the mentalis pair meet on the chin boss and act together (thesis 4.5.10).
 * - AU18 pucker, AU23 lip tightener, AU24 lip pressor: the orbicularis oris is one ring around the mouth, modelled as
 *   one sphincter per action; FACS allows scoring 23 and 24 on one side, but this rig cannot produce it.
 * - AU25 lips part, AU26 jaw drop, AU27 mouth stretch: the lips and the jaw open as one.
 * - AU51 to AU58, the head positions (turn, up and down, tilt, forward and back): the head turns about the neck as
 *   a whole, and the neck's skin is solved under it (see head-pose.ts and neck-carry.ts).
 * - AU61 to AU66, the eye positions (eyes turn left, right, up, down, out, in): both eyes turn together. They turn the
 *   eyeballs (see gaze.ts); the upper lids follow the eyes up and down through the rig's lid muscles.
 * Bilateral, because FACS scores them on one side and the thesis or the prototypes need it: 1, 2, 4, 5, 6, 7
 * (winks, one raised brow, a squint), 10, 12, 14, 15, 16, 20 (contempt is R12A + R14A) and 43 (one eye closed); the
 * lid positions of the 1978 manual, 41 (lid droop), 42 (slit) and 44 (squint), likewise: they are made by the same lid
 * muscles as 43 and 7 (the 2002 manual scores them as intensities of those; people still code them, and tools offer
 * them). 45 (blink) closes the lids as 43 does; what makes it a blink is its timing, a timeline's FACS action of a
 * tenth of a second each way (docs/timeline.md). 46 (wink) closes one eye and raises its cheek.
 */
export const ACTION_UNITS: readonly ActionUnitInfo[] = Object.freeze(
  (
    [
      [1, 'inner brow raiser', true],
      [2, 'outer brow raiser', true],
      [4, 'brow lowerer', true],
      [5, 'upper lid raiser', true],
      [6, 'cheek raiser', true],
      [7, 'lid tightener', true],
      [9, 'nose wrinkler', false],
      [10, 'upper lip raiser', true],
      [11, 'nasolabial deepener', true],
      [12, 'lip corner puller', true],
      [13, 'sharp lip puller', true],
      [14, 'dimpler', true],
      [15, 'lip corner depressor', true],
      [16, 'lower lip depressor', true],
      [17, 'chin raiser', false],
      [18, 'lip pucker', false],
      [20, 'lip stretcher', true],
      [22, 'lip funneler', false],
      [23, 'lip tightener', false],
      [24, 'lip pressor', false],
      [25, 'lips part', false],
      [26, 'jaw drop', false],
      [27, 'mouth stretch', false],
      [38, 'nostril dilator', true],
      [39, 'nostril compressor', true],
      [41, 'lid droop', true],
      [42, 'slit', true],
      [43, 'eyes closed', true],
      [44, 'squint', true],
      [45, 'blink', true],
      [46, 'wink', true],
      [51, 'head turn left', false],
      [52, 'head turn right', false],
      [53, 'head up', false],
      [54, 'head down', false],
      [55, 'head tilt left', false],
      [56, 'head tilt right', false],
      [57, 'head forward', false],
      [58, 'head back', false],
      [61, 'eyes turn left', false],
      [62, 'eyes turn right', false],
      [63, 'eyes up', false],
      [64, 'eyes down', false],
      [65, 'walleye', false],
      [66, 'cross-eye', false],
    ] as const
  ).map(([n, name, bilateral]) => Object.freeze({ id: `AU${n}`, number: n, name, bilateral })),
);

/** A FACS intensity grade: '' for none, then A (trace) to E (maximum). */
export type Grade = '' | 'A' | 'B' | 'C' | 'D' | 'E';

/**
 * Upper bound (inclusive) of each grade on the 0..1 intensity scale. FACS grades are not evenly spaced: A and B are
 * narrow, C and D wide, E narrow (the 2002 manual's picture of the scale), so: A up to 10 %, B to 20 %, C to 55 %,
 * D to 90 %, E to 100 %.
 */
const GRADE_BANDS: readonly (readonly [upTo: number, grade: Grade])[] = Object.freeze([
  [0.1, 'A'],
  [0.2, 'B'],
  [0.55, 'C'],
  [0.9, 'D'],
  [1, 'E'],
] as const);

/** The FACS grade of an intensity (0..1): '' at 0 (or below, or NaN), 'E' above 1. */
export function gradeOf(intensity: number): Grade {
  if (!(intensity > 0)) return '';
  for (const [upTo, grade] of GRADE_BANDS) if (intensity <= upTo) return grade;
  return 'E';
}

/** Side codes in listings: left, right, or midline. */
export type SideCode = 'L' | 'R' | 'M';

/** An Action Unit as `listActionUnits` shows it. */
export interface ActionUnitListing {
  /** The unit's id without a side, as `setActionUnit` takes it for both sides: `AU12`. */
  id: string;
  /** Its FACS number: 12 for `AU12`. */
  number: number;
  /** Its FACS name, lower case: `lip corner puller`. */
  name: string;
  /** `['L', 'R']` for a unit set per side (ids `AU12L`, `AU12R`), `['M']` for a midline one set whole (`AU17`). */
  sides: SideCode[];
}

/** A preset as `listPresets` shows it, with its current weight. */
export interface PresetListing {
  /** Its name in the rig, as `applyPreset` takes it: `happiness`. */
  name: string;
  /** Where it comes from: `FACS prototype`, `thesis 5.2`. */
  source: string;
  /** The rig's remark on it, if any: which Action Units it combines and why at these intensities. */
  note?: string;
  /** Its current weight, 0..1 (0: off). */
  weight: number;
}

// ---------------------------------------------------------------------------------------------------------------
// Slots: one number per Action Unit side, in catalogue order (AU1L, AU1R, AU2L, ..., AU9, ...).

const SLOT_IDS: readonly string[] = ACTION_UNITS.flatMap((au) => (au.bilateral ? [`${au.id}L`, `${au.id}R`] : [au.id]));

/** The slots an id sets: `AU12` both sides, `AU12L` one, `AU17` its only one. */
const SLOTS_OF: ReadonlyMap<string, readonly number[]> = (() => {
  const map = new Map<string, number[]>();
  SLOT_IDS.forEach((id, slot) => map.set(id, [slot]));
  for (const au of ACTION_UNITS) if (au.bilateral) map.set(au.id, [...map.get(`${au.id}L`)!, ...map.get(`${au.id}R`)!]);
  return map;
})();

/** Whether `id` names an Action Unit or one of its sides (`AU12`, `AU12L`, `AU17`). */
export function isActionUnitId(id: string): boolean {
  return SLOTS_OF.has(id);
}

const CATALOGUE_BY_ID: ReadonlyMap<string, ActionUnitInfo> = new Map(ACTION_UNITS.map((au) => [au.id, au]));

/** What `muscleContractions` needs from a rig, flattened: for each Action Unit side -> muscle link, its slot and weight. */
interface ContractionPlan {
  muscleCount: number;
  slot: Int32Array;
  muscle: Int32Array;
  weight: Float64Array;
}

/** Rigs are treated as immutable once parsed, so a plan is built once per rig object. */
const plans = new WeakMap<Rig, ContractionPlan>();

/**
 * Action Unit sliders and preset weights, and the intensities and muscle contractions they add up to. Inputs are
 * checked where they enter: a bad id or value throws and changes nothing.
 */
export class ExpressionState {
  private readonly sliders = new Float64Array(SLOT_IDS.length);
  private readonly presets: readonly PresetDefinition[];
  private readonly presetWeights: Float64Array;
  /** Each preset's intensity per slot (`AU12` spread to both sides), so that summing is one pass. */
  private readonly presetSlots: readonly Float64Array[];
  /**
   * A contribution added on top of the sliders and presets by the page itself (the eye simulation's blinks and lid
   * follow), kept apart so that it never moves a slider and `reset` leaves it alone.
   */
  private readonly overlay = new Float64Array(SLOT_IDS.length);
  /** The face's resting pull (see setResting). */
  private readonly resting = new Float64Array(SLOT_IDS.length);
  private readonly effectiveSlots = new Float64Array(SLOT_IDS.length);
  private dirty = false;

  /** The presets (usually `rig.presets`) must name catalogue Action Units, with a side only for bilateral ones. */
  constructor(presets: readonly PresetDefinition[] = []) {
    const names = new Set<string>();
    this.presetSlots = presets.map((p) => {
      if (names.has(p.name)) throw new Error(`ExpressionState: duplicate preset name ${show(p.name)}`);
      names.add(p.name);
      return presetToSlots(p);
    });
    this.presets = [...presets];
    this.presetWeights = new Float64Array(presets.length);
  }

  /** Sets a slider (clamped to 0..1): `AU12` sets both sides, `AU12L` / `AU12R` one, `AU17` a midline unit. */
  setActionUnit(id: string, value: number): void {
    const slots = SLOTS_OF.get(id);
    if (!slots) throw refusal('setActionUnit', '', ACTION_UNIT_ID, id);
    checkNumber('setActionUnit', id, value);
    for (const s of slots) this.sliders[s] = clamp01(value);
    this.dirty = true;
  }

  /**
   * Sets an overlay intensity (clamped to 0..1) that adds to the sliders and presets without changing them; ids as in
   * `setActionUnit`. Returns whether the overlay changed. Allocation-free: the eye simulation calls it every frame.
   */
  setOverlay(id: string, value: number): boolean {
    const slots = SLOTS_OF.get(id);
    if (!slots) throw refusal('setOverlay', '', 'an Action Unit id like "AU43", "AU43L" or "AU43R"', id);
    checkNumber('setOverlay', id, value);
    const v = clamp01(value);
    let changed = false;
    for (let i = 0; i < slots.length; i++) {
      if (this.overlay[slots[i]] !== v) {
        this.overlay[slots[i]] = v;
        changed = true;
      }
    }
    if (changed) this.dirty = true;
    return changed;
  }

  /**
   * Sets the face's resting pull (Action Unit intensities, clamped to 0..1; others 0): what an old face keeps at rest
   * (src/core/head/identity-skin.ts). It adds to everything else, moves no slider, and `reset` leaves it.
   */
  setResting(intensities: Readonly<Record<string, number>>): void {
    const next = new Float64Array(SLOT_IDS.length);
    for (const [id, value] of Object.entries(intensities)) {
      const slots = SLOTS_OF.get(id);
      if (!slots) throw refusal('setResting', '', ACTION_UNIT_ID, id);
      checkNumber('setResting', id, value);
      for (const s of slots) next[s] = clamp01(value);
    }
    this.resting.set(next);
    this.dirty = true;
  }

  /** The resting pull by side id, like `getActionUnits`. */
  getResting(): Record<string, number> {
    const out: Record<string, number> = {};
    SLOT_IDS.forEach((id, s) => {
      if (this.resting[s] !== 0) out[id] = this.resting[s];
    });
    return out;
  }

  /** Zeroes the overlay; returns whether it had any contribution. */
  clearOverlay(): boolean {
    let changed = false;
    for (let s = 0; s < this.overlay.length; s++) if (this.overlay[s] !== 0) changed = true;
    if (changed) {
      this.overlay.fill(0);
      this.dirty = true;
    }
    return changed;
  }

  /** The overlay intensities by side id, like `getActionUnits`. */
  getOverlay(): Record<string, number> {
    const out: Record<string, number> = {};
    SLOT_IDS.forEach((id, s) => (out[id] = this.overlay[s]));
    return out;
  }

  /** The slider values by side id (`AU12L`, `AU12R`, `AU17`, ...), presets not included. */
  getActionUnits(): Record<string, number> {
    const out: Record<string, number> = {};
    SLOT_IDS.forEach((id, s) => (out[id] = this.sliders[s]));
    return out;
  }

  /** The catalogue with the side ids each unit has. */
  listActionUnits(): ActionUnitListing[] {
    return ACTION_UNITS.map((au) => ({ id: au.id, number: au.number, name: au.name, sides: au.bilateral ? ['L', 'R'] : ['M'] }));
  }

  /** Sets a preset's weight (clamped to 0..1; 0 turns it off). */
  applyPreset(name: string, weight: number): void {
    const index = this.presets.findIndex((p) => p.name === name);
    if (index < 0) throw refusal('applyPreset', '', `one of the presets ${this.presets.map((p) => p.name).join(', ') || '(none)'}`, name);
    checkNumber('applyPreset', name, weight);
    this.presetWeights[index] = clamp01(weight);
    this.dirty = true;
  }

  /**
   * Sets some sliders (`ids[i]` to `values[i]`, ids as in `setActionUnit`) and preset weights (`presets[i]` to
   * `weights[i]`), each clamped to 0..1, as a player's frame does; ids and presets the face does not have are
   * skipped (a preset may have left with an edited rig). Returns whether anything changed. Allocation-free.
   */
  setFrame(ids: readonly string[], values: ArrayLike<number>, presets: readonly string[], weights: ArrayLike<number>): boolean {
    let changed = false;
    for (let i = 0; i < ids.length; i++) {
      const slots = SLOTS_OF.get(ids[i]);
      if (!slots || !Number.isFinite(values[i])) continue;
      const v = clamp01(values[i]);
      for (let k = 0; k < slots.length; k++) {
        if (this.sliders[slots[k]] !== v) {
          this.sliders[slots[k]] = v;
          changed = true;
        }
      }
    }
    for (let i = 0; i < presets.length; i++) {
      let index = -1;
      for (let p = 0; p < this.presets.length; p++) if (this.presets[p].name === presets[i]) index = p;
      if (index < 0 || !Number.isFinite(weights[i])) continue;
      const w = clamp01(weights[i]);
      if (this.presetWeights[index] !== w) {
        this.presetWeights[index] = w;
        changed = true;
      }
    }
    if (changed) this.dirty = true;
    return changed;
  }

  /** The presets, in rig order, with their current weights. */
  listPresets(): PresetListing[] {
    return this.presets.map((p, i) => ({
      name: p.name,
      source: p.source,
      ...(p.note === undefined ? {} : { note: p.note }),
      weight: this.presetWeights[i],
    }));
  }

  /** Every slider and preset weight back to 0 (the overlay is the page's, and stays). */
  reset(): void {
    this.sliders.fill(0);
    this.presetWeights.fill(0);
    this.dirty = true;
  }

  /** Intensity per Action Unit side: slider plus the weighted presets plus the overlay, clamped to 0..1. */
  effective(): Record<string, number> {
    const e = this.effectiveIntensities();
    const out: Record<string, number> = {};
    SLOT_IDS.forEach((id, s) => (out[id] = e[s]));
    return out;
  }

  /** One side's (or midline unit's) effective intensity, as `effective` has it, without building the record. */
  effectiveOf(id: string): number {
    const slots = SLOTS_OF.get(id);
    if (slots?.length !== 1) throw refusal('effectiveOf', '', 'an Action Unit side or midline unit like "AU12L" or "AU61"', id);
    return this.effectiveIntensities()[slots[0]];
  }

  /**
   * The expression set, by side id like `getActionUnits`: each side's slider plus the weighted presets, clamped to
   * 0..1, without the page's overlay and the resting pull (what `getFACS` writes).
   */
  expressionIntensities(): Record<string, number> {
    const out: Record<string, number> = {};
    SLOT_IDS.forEach((id, s) => {
      let v = this.sliders[s];
      this.presetSlots.forEach((values, p) => (v += this.presetWeights[p] * values[s]));
      out[id] = clamp01(v);
    });
    return out;
  }

  /**
   * Contraction of each rig muscle (index = position in `rig.muscles`) into `into`: the sum over the Action Unit
   * sides that drive it of intensity x weight, at most 1. Entries past the muscle count are left alone. The rig's
   * links are read once per rig object (rigs are immutable once parsed): pass a new object after editing one.
   */
  muscleContractions(rig: Rig, into: Float32Array): Float32Array {
    const plan = planFor(rig);
    if (into.length < plan.muscleCount)
      throw new RangeError(`muscleContractions: needs room for ${plan.muscleCount} muscles, got ${into.length}`);
    const e = this.effectiveIntensities();
    into.fill(0, 0, plan.muscleCount);
    for (let k = 0; k < plan.slot.length; k++) into[plan.muscle[k]] += e[plan.slot[k]] * plan.weight[k];
    for (let m = 0; m < plan.muscleCount; m++) into[m] = clamp01(into[m]);
    return into;
  }

  private effectiveIntensities(): Float64Array {
    if (!this.dirty) return this.effectiveSlots;
    const e = this.effectiveSlots;
    e.set(this.sliders);
    for (let s = 0; s < e.length; s++) e[s] += this.overlay[s] + this.resting[s];
    this.presetSlots.forEach((values, p) => {
      const w = this.presetWeights[p];
      if (w !== 0) for (let s = 0; s < e.length; s++) e[s] += w * values[s];
    });
    for (let s = 0; s < e.length; s++) e[s] = clamp01(e[s]);
    this.dirty = false;
    return e;
  }
}

/** A preset's intensities per slot; `AU12` adds to both sides, `AU12R` to the right only. */
function presetToSlots(p: PresetDefinition): Float64Array {
  const values = new Float64Array(SLOT_IDS.length);
  for (const [id, value] of Object.entries(p.actionUnits)) {
    const slots = SLOTS_OF.get(id);
    if (!slots) throw new Error(`ExpressionState: preset ${show(p.name)} names unknown Action Unit id ${show(id)}`);
    if (typeof value !== 'number' || !Number.isFinite(value))
      throw new Error(`ExpressionState: preset ${show(p.name)} gives ${id} a non-finite value ${show(value)}`);
    for (const s of slots) values[s] += value;
  }
  return values;
}

function planFor(rig: Rig): ContractionPlan {
  let plan = plans.get(rig);
  if (!plan) {
    plan = buildPlan(rig);
    plans.set(rig, plan);
  }
  return plan;
}

/** Links each rig Action Unit side to its muscles; throws if the rig does not fit the catalogue. */
function buildPlan(rig: Rig): ContractionPlan {
  const muscleIndex = new Map(rig.muscles.map((m, i) => [m.name, i]));
  const slot: number[] = [];
  const muscle: number[] = [];
  const weight: number[] = [];
  for (const au of rig.actionUnits) {
    const known = CATALOGUE_BY_ID.get(au.id);
    if (!known) throw new Error(`muscleContractions: rig Action Unit ${au.id} is not in the catalogue`);
    if (known.bilateral !== au.bilateral)
      throw new Error(
        `muscleContractions: rig has ${au.id} as ${au.bilateral ? 'bilateral' : 'midline'}, ` +
          `the catalogue as ${known.bilateral ? 'bilateral' : 'midline'}`,
      );
    for (const link of au.muscles) {
      const m = muscleIndex.get(link.muscle);
      if (m === undefined) throw new Error(`muscleContractions: ${au.id} names unknown muscle ${show(link.muscle)}`);
      const sideId = !au.bilateral ? au.id : link.side === 'left' ? `${au.id}L` : link.side === 'right' ? `${au.id}R` : undefined;
      if (sideId === undefined) throw new Error(`muscleContractions: bilateral ${au.id} links ${show(link.muscle)} on side "mid"`);
      slot.push(SLOTS_OF.get(sideId)![0]);
      muscle.push(m);
      weight.push(link.weight);
    }
  }
  return {
    muscleCount: rig.muscles.length,
    slot: Int32Array.from(slot),
    muscle: Int32Array.from(muscle),
    weight: Float64Array.from(weight),
  };
}
