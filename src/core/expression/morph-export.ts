/**
 * What a glTF export of the face holds, as plain data: its morph targets (Action Units and presets, each solved on its
 * own at full strength) and a timeline turned into morph weights over time. Pure: no DOM, no three.
 */

import { ACTION_UNIT_ID, refusal } from '../check';
import { isActionUnitId } from './facs';
import { HEAD_POSITION_UNITS } from './head-pose';
import {
  createTimelineSample,
  PRESET_TARGET_PREFIX,
  sampleTimeline,
  targetSides,
  timelineDuration,
  type Timeline,
} from '../timeline/timeline';

/** One morph target: its name in the file, and the expression it holds (one Action Unit id or one preset, at 1). */
export interface MorphTarget {
  name: string;
  kind: 'actionUnit' | 'preset';
  /** The Action Unit id (`AU12`, `AU12L`, `AU17`) or the preset's name. */
  id: string;
}

/** Morph weights over time: `weights[i * targets + k]` is target k's weight at `times[i]` seconds. */
export interface MorphWeights {
  times: Float32Array;
  weights: Float32Array;
  duration: number;
}

/** Most frames per second a timeline is sampled at. */
export const MAX_EXPORT_FPS = 120;

/**
 * The morph targets of an export: the Action Units and presets asked for, then those the timeline needs (see
 * `timelineTargets`) that are not among them. Each id and preset is checked first: an unknown one, one listed twice,
 * a preset named like an Action Unit, or nothing to export at all throws naming the option.
 */
export function planTargets(
  actionUnits: readonly string[],
  presets: readonly string[],
  known: readonly string[],
  timeline: Timeline | null,
  what = 'exportGLTF',
): MorphTarget[] {
  if (!Array.isArray(actionUnits)) throw new Error(`${what}: actionUnits must be an array of Action Unit ids, got ${String(actionUnits)}`);
  if (!Array.isArray(presets)) throw new Error(`${what}: presets must be an array of preset names, got ${String(presets)}`);
  const targets: MorphTarget[] = [];
  const names = new Set<string>();
  for (const id of actionUnits) {
    if (typeof id !== 'string' || !isActionUnitId(id)) throw refusal(what, 'actionUnits', ACTION_UNIT_ID, id);
    if (HEAD_POSITION_UNITS.includes(id)) {
      throw new Error(
        `${what}: actionUnits: ${id} is a head position, which turns the whole head rather than shaping the skin; ` +
          'a morph target cannot hold it',
      );
    }
    if (names.has(id)) throw new Error(`${what}: actionUnits: ${id} is listed twice`);
    names.add(id);
    targets.push({ name: id, kind: 'actionUnit', id });
  }
  for (const name of presets) {
    if (typeof name !== 'string' || !known.includes(name))
      throw refusal(what, 'presets', `one of the presets ${known.join(', ') || '(none)'}`, name);
    // A preset's target takes the preset's name: it must not be taken for an Action Unit's.
    if (isActionUnitId(name)) throw new Error(`${what}: presets: the preset ${JSON.stringify(name)} is named like an Action Unit`);
    if (names.has(name)) throw new Error(`${what}: presets: ${name} is listed twice`);
    names.add(name);
    targets.push({ name, kind: 'preset', id: name });
  }
  if (timeline) {
    for (const t of timelineTargets(timeline)) {
      if (names.has(t.name)) continue;
      names.add(t.name);
      targets.push(t);
    }
  }
  if (targets.length === 0) throw new Error(`${what}: actionUnits and presets are empty and there is no timeline: nothing to export`);
  return targets;
}

/**
 * The morph targets a timeline's weights need: a preset for each `preset:<name>` it names; for an Action Unit, the
 * both-sides id (`AU12`) when the timeline names that unit only so, else one target per side (`AU12L`, `AU12R`),
 * whose weights then follow each side's value; a midline unit's own id (`AU17`).
 */
export function timelineTargets(timeline: Timeline): MorphTarget[] {
  const named = [...Object.keys(timeline.tracks), ...timeline.actions.map((a) => a.target)];
  // The bilateral unit of an Action Unit name (`AU12` of `AU12`, `AU12L`, `AU12R`), or null for a midline unit.
  const unitOf = (name: string): string | null => {
    if (targetSides(name).length === 2) return name;
    const base = name.slice(0, -1);
    return /[LR]$/.test(name) && isActionUnitId(base) ? base : null;
  };
  const sided = new Set<string>();
  for (const name of named)
    if (!name.startsWith(PRESET_TARGET_PREFIX) && unitOf(name) !== null && unitOf(name) !== name) sided.add(unitOf(name)!);
  const out: MorphTarget[] = [];
  const seen = new Set<string>();
  const add = (kind: MorphTarget['kind'], id: string): void => {
    if (seen.has(id)) return;
    seen.add(id);
    out.push({ name: id, kind, id });
  };
  for (const name of named) {
    if (name.startsWith(PRESET_TARGET_PREFIX)) {
      add('preset', name.slice(PRESET_TARGET_PREFIX.length));
      continue;
    }
    // A head position turns the whole head, which no morph target holds.
    if (HEAD_POSITION_UNITS.includes(name)) continue;
    const unit = unitOf(name);
    if (unit !== null && sided.has(unit)) {
      add('actionUnit', `${unit}L`);
      add('actionUnit', `${unit}R`);
    } else add('actionUnit', name);
  }
  return out;
}

/**
 * A timeline sampled at `fps` from 0 to its duration (the last sample at the duration itself), as weights of
 * `targets`: an Action Unit side's or midline unit's target takes that side's value, a both-sides target the left
 * side's (the timeline names the unit only with both sides, so they are equal), a preset's target the preset's weight.
 * Targets that `timelineTargets` does not give for it stay at 0.
 */
export function timelineWeights(timeline: Timeline, targets: readonly MorphTarget[], fps: number): MorphWeights {
  if (typeof fps !== 'number' || !Number.isFinite(fps) || fps <= 0 || fps > MAX_EXPORT_FPS)
    throw refusal('timelineWeights', 'fps', `a number above 0 and at most ${MAX_EXPORT_FPS}`, fps);
  const duration = timelineDuration(timeline);
  const sample = createTimelineSample(timeline);
  // Only the targets the timeline itself needs move: an `AU12` asked for beside a timeline of `AU12L` stays at 0,
  // as `AU12L` and `AU12R` carry the unit's values.
  const animated = new Set(timelineTargets(timeline).map((t) => t.name));
  const source = targets.map((t) => {
    if (!animated.has(t.name)) return -1;
    const key = t.kind === 'preset' ? `${PRESET_TARGET_PREFIX}${t.id}` : targetSides(t.id)[0];
    return sample.targets.indexOf(key);
  });
  const steps = Math.max(1, Math.ceil(duration * fps - 1e-9));
  const count = duration > 0 ? steps + 1 : 1;
  const times = new Float32Array(count);
  const weights = new Float32Array(count * targets.length);
  for (let i = 0; i < count; i++) {
    const t = i === count - 1 ? duration : i / fps;
    times[i] = t;
    sampleTimeline(timeline, t, sample);
    for (let k = 0; k < targets.length; k++) weights[i * targets.length + k] = source[k] >= 0 ? sample.values[source[k]] : 0;
  }
  return { times, weights, duration };
}
