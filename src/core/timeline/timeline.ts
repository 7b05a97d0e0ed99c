/**
 * Timelines: Action Unit values and preset weights over time. Keyframe tracks with an easing per segment, and FACS
 * actions (one unit or preset rising to an intensity, holding at its apex and falling back: onset, apex, offset).
 * Sampling writes into a reused buffer, so a player (or a recorder stepping a fixed time per frame) allocates
 * nothing per frame. Pure: no DOM, no three.
 */

import { isActionUnitId } from '../expression/facs';

/** How a segment goes from its key to the next: a straight line, or the cubic ease curves. */
export type Easing = 'linear' | 'ease-in' | 'ease-out' | 'ease-in-out';

export const EASINGS: readonly Easing[] = Object.freeze(['linear', 'ease-in', 'ease-out', 'ease-in-out'] as const);

/** A keyframe: the value (0..1) at `time` seconds; `easing` shapes the segment from this key to the next (as in CSS). */
export interface TimelineKey {
  /** When the key is, in seconds from the timeline's start (0..3600); a track's keys have strictly increasing times. */
  time: number;
  /** The target's value at the key (0..1); a track holds its first key's value before it, its last's after it. */
  value: number;
  /** How the segment from this key to the next is eased; `linear` when left out. */
  easing?: Easing;
}

/** The keys of one Action Unit side or preset, in strictly increasing time. */
export interface TimelineTrack {
  /** The keys (1 to 4096), in strictly increasing time; the value is eased from each key to the next. */
  keys: TimelineKey[];
}

/**
 * One FACS action (a unit or preset going through its onset, apex and offset): from `start` it rises to `intensity`
 * over `onset` seconds (ease-in-out), holds there for `apex` seconds and falls back to 0 over `offset` seconds.
 */
export interface TimelineAction {
  /** What the action sets: an Action Unit id (`AU12`, `AU12L`, `AU17`) or a preset as `preset:<name>`. */
  target: string;
  /** When the action starts to rise, in seconds from the timeline's start (0..3600). */
  start: number;
  /** The value the action rises to and holds at its apex (0..1). */
  intensity: number;
  /** How long the action rises from 0 to `intensity` (ease-in-out), in seconds (above 0, at most 3600). */
  onset: number;
  /** How long the action holds at `intensity`, in seconds (0..3600). */
  apex: number;
  /** How long the action falls from `intensity` back to 0 (ease-in-out), in seconds (above 0, at most 3600). */
  offset: number;
}

/**
 * A timeline document. Track names and action targets are Action Unit ids as `setActionUnit` takes them (`AU12`,
 * `AU12L`, `AU17`) or presets as `preset:<name>`. A side's value is the sum of its tracks' and actions' (`AU12` adds
 * to both sides), clamped to 0..1. `duration` defaults to the end of the last key or action; with `loop` the timeline
 * starts again after it.
 */
export interface Timeline {
  /** Marks the JSON document as a softface timeline: always `softface-timeline`. */
  format: 'softface-timeline';
  /** The document format's version, 1; a document that leaves it out is read as version 1. */
  version: 1;
  /**
   * How long the timeline runs, in seconds (above 0, at most 3600, and not before the end of its last key or action);
   * when left out, it ends with its last key or action.
   */
  duration?: number;
  /** Whether the timeline starts again from 0 at its end; without it (the default), it stops and holds its end. */
  loop?: boolean;
  /** The keyframe tracks (at most 128), by target: an Action Unit id (`AU12`, `AU12L`) or `preset:<name>`. */
  tracks: Record<string, TimelineTrack>;
  /** The FACS actions (at most 4096), each one target rising, holding and falling back to 0. */
  actions: TimelineAction[];
}

/** The format name a timeline document carries, and the version this code writes. */
export const TIMELINE_FORMAT = 'softface-timeline';
export const TIMELINE_VERSION = 1;

/** The prefix of a preset target: `preset:happiness`. */
export const PRESET_TARGET_PREFIX = 'preset:';

/**
 * A timeline sampled at one time: `values[i]` is the value of `targets[i]`, an Action Unit side (`AU12L`, `AU17`) or a
 * preset (`preset:happiness`). Made by `createTimelineSample`.
 */
export interface TimelineSample {
  readonly targets: readonly string[];
  readonly values: Float64Array;
  /** The time within the timeline that was sampled, after looping or clamping. */
  time: number;
}

/** An empty timeline (no tracks, no actions, no loop). */
export function emptyTimeline(): Timeline {
  return { format: TIMELINE_FORMAT, version: TIMELINE_VERSION, tracks: {}, actions: [] };
}

// ---------------------------------------------------------------------------------------------------------------
// Easing.

const EASE_LINEAR = 0;
const EASE_IN = 1;
const EASE_OUT = 2;
const EASE_IN_OUT = 3;

function easingCode(easing: Easing | undefined): number {
  switch (easing) {
    case 'ease-in':
      return EASE_IN;
    case 'ease-out':
      return EASE_OUT;
    case 'ease-in-out':
      return EASE_IN_OUT;
    default:
      return EASE_LINEAR;
  }
}

function easeByCode(code: number, u: number): number {
  if (code === EASE_IN) return u * u * u;
  if (code === EASE_OUT) {
    const w = 1 - u;
    return 1 - w * w * w;
  }
  if (code === EASE_IN_OUT) return u < 0.5 ? 4 * u * u * u : 1 - 4 * (1 - u) * (1 - u) * (1 - u);
  return u;
}

/** The eased fraction of a segment at `u` (0..1, clamped): 0 at its start, 1 at its end. */
export function ease(easing: Easing, u: number): number {
  return easeByCode(easingCode(easing), u <= 0 ? 0 : u >= 1 ? 1 : u);
}

// ---------------------------------------------------------------------------------------------------------------
// Actions.

/** The end of an action: start + onset + apex + offset. */
function actionEnd(a: TimelineAction): number {
  return a.start + a.onset + a.apex + a.offset;
}

/** An action's value at `t` seconds: 0 before and after it, rising, holding and falling as its phases say. */
export function actionValue(a: TimelineAction, t: number): number {
  return actionAt(a.start, a.intensity, a.onset, a.apex, a.offset, t);
}

function actionAt(start: number, intensity: number, onset: number, apex: number, offset: number, t: number): number {
  const rel = t - start;
  if (rel < 0) return 0;
  if (rel < onset) return intensity * easeByCode(EASE_IN_OUT, rel / onset);
  if (rel <= onset + apex) return intensity;
  const fall = rel - onset - apex;
  if (fall < offset) return intensity * (1 - easeByCode(EASE_IN_OUT, fall / offset));
  return 0;
}

/**
 * The keys an action amounts to on its own (what the Timeline panel lists, and a way to turn it into a track): 0 at
 * the start, the intensity from the end of the onset to the end of the apex, 0 at the end, both ramps ease-in-out.
 * Onset and offset are positive (the schema says so); an apex of 0 gives no key of its own.
 */
export function expandAction(a: TimelineAction): TimelineKey[] {
  const rise = a.start + a.onset;
  const hold = rise + a.apex;
  const keys: TimelineKey[] = [{ time: a.start, value: 0, easing: 'ease-in-out' }];
  if (a.apex > 0) keys.push({ time: rise, value: a.intensity, easing: 'linear' });
  keys.push({ time: hold, value: a.intensity, easing: 'ease-in-out' }, { time: hold + a.offset, value: 0 });
  return keys;
}

// ---------------------------------------------------------------------------------------------------------------
// Duration and time.

/** The end of the last key or action, in seconds (0 for an empty timeline). */
function contentEnd(t: Timeline): number {
  let end = 0;
  for (const track of Object.values(t.tracks)) {
    const last = track.keys[track.keys.length - 1];
    if (last && last.time > end) end = last.time;
  }
  for (const a of t.actions) end = Math.max(end, actionEnd(a));
  return end;
}

/** How long the timeline runs: its `duration`, or the end of its content. */
export function timelineDuration(t: Timeline): number {
  return planFor(t).duration;
}

/** The time within the timeline at `seconds` of playing: wrapped into [0, duration) with `loop`, else clamped. */
export function localTime(t: Timeline, seconds: number): number {
  const plan = planFor(t);
  return wrap(plan.duration, plan.loop, seconds);
}

function wrap(duration: number, loop: boolean, seconds: number): number {
  if (!(duration > 0)) return 0;
  if (loop) {
    const r = seconds % duration;
    return r < 0 ? r + duration : r;
  }
  return seconds < 0 ? 0 : seconds > duration ? duration : seconds;
}

// ---------------------------------------------------------------------------------------------------------------
// Sampling.

/** A timeline flattened into typed arrays, once per timeline object (timelines are immutable once parsed). */
interface Plan {
  /** Action Unit sides (`AU12L`, `AU17`) and presets (`preset:happiness`) the timeline sets, in first-use order. */
  targets: readonly string[];
  duration: number;
  loop: boolean;
  /** Per track: where its keys start in the key arrays, and how many it has. */
  keyFrom: Int32Array;
  keyCount: Int32Array;
  times: Float64Array;
  values: Float64Array;
  easings: Uint8Array;
  /** Per target: the tracks that add to it, as a range of `trackList`, which holds track indices. */
  trackFrom: Int32Array;
  trackCount: Int32Array;
  trackList: Int32Array;
  /** Per target: the actions that add to it, as a range of `actionList`, which holds action indices. */
  actionFrom: Int32Array;
  actionCount: Int32Array;
  actionList: Int32Array;
  /** start, intensity, onset, apex, offset per action. */
  actions: Float64Array;
}

const plans = new WeakMap<Timeline, Plan>();

function planFor(t: Timeline): Plan {
  let plan = plans.get(t);
  if (!plan) {
    plan = buildPlan(t);
    plans.set(t, plan);
  }
  return plan;
}

/**
 * The Action Unit sides a target sets: both of a bilateral unit named without a side (`AU12` sets `AU12L` and
 * `AU12R`), so that `AU12` and `AU12L` contributions add up per side as presets and sliders do.
 */
export function targetSides(target: string): string[] {
  if (target.startsWith(PRESET_TARGET_PREFIX)) return [target];
  // A bilateral unit's id with a side letter added is an id too; a side's or a midline unit's is not.
  const left = `${target}L`;
  return isActionUnitId(left) ? [left, `${target}R`] : [target];
}

function buildPlan(t: Timeline): Plan {
  const targets: string[] = [];
  const byTarget = new Map<string, { tracks: number[]; actions: number[] }>();
  const entry = (target: string): { tracks: number[]; actions: number[] } => {
    let e = byTarget.get(target);
    if (!e) {
      e = { tracks: [], actions: [] };
      byTarget.set(target, e);
      targets.push(target);
    }
    return e;
  };
  const names = Object.keys(t.tracks);
  const keyFrom = new Int32Array(names.length);
  const keyCount = new Int32Array(names.length);
  const times: number[] = [];
  const values: number[] = [];
  const easings: number[] = [];
  names.forEach((name, i) => {
    keyFrom[i] = times.length;
    for (const k of t.tracks[name].keys) {
      times.push(k.time);
      values.push(k.value);
      easings.push(easingCode(k.easing));
    }
    keyCount[i] = times.length - keyFrom[i];
    for (const side of targetSides(name)) entry(side).tracks.push(i);
  });
  const actions: number[] = [];
  t.actions.forEach((a, i) => {
    actions.push(a.start, a.intensity, a.onset, a.apex, a.offset);
    for (const side of targetSides(a.target)) entry(side).actions.push(i);
  });
  const n = targets.length;
  const trackFrom = new Int32Array(n);
  const trackCount = new Int32Array(n);
  const actionFrom = new Int32Array(n);
  const actionCount = new Int32Array(n);
  const trackList: number[] = [];
  const actionList: number[] = [];
  targets.forEach((target, i) => {
    const e = byTarget.get(target)!;
    trackFrom[i] = trackList.length;
    trackCount[i] = e.tracks.length;
    trackList.push(...e.tracks);
    actionFrom[i] = actionList.length;
    actionCount[i] = e.actions.length;
    actionList.push(...e.actions);
  });
  return {
    targets: Object.freeze(targets),
    duration: t.duration ?? contentEnd(t),
    loop: t.loop ?? false,
    keyFrom,
    keyCount,
    times: Float64Array.from(times),
    values: Float64Array.from(values),
    easings: Uint8Array.from(easings),
    trackFrom,
    trackCount,
    trackList: Int32Array.from(trackList),
    actionFrom,
    actionCount,
    actionList: Int32Array.from(actionList),
    actions: Float64Array.from(actions),
  };
}

/** A buffer for `sampleTimeline`, with a value for each track and action target of `t`. */
export function createTimelineSample(t: Timeline): TimelineSample {
  const plan = planFor(t);
  return { targets: plan.targets, values: new Float64Array(plan.targets.length), time: 0 };
}

/**
 * Writes every target's value at `seconds` of playing into `out` (made for this timeline by `createTimelineSample`)
 * and returns the time sampled (looped or clamped, as `localTime`). Allocates nothing: it runs every frame.
 */
export function sampleTimeline(t: Timeline, seconds: number, out: TimelineSample): number {
  const plan = planFor(t);
  if (out.targets !== plan.targets) throw new Error('sampleTimeline: the sample was made for another timeline (use createTimelineSample)');
  if (!Number.isFinite(seconds)) throw new RangeError(`sampleTimeline: needs a finite time, got ${String(seconds)}`);
  const time = wrap(plan.duration, plan.loop, seconds);
  const a = plan.actions;
  for (let i = 0; i < plan.targets.length; i++) {
    let v = 0;
    const tracksTo = plan.trackFrom[i] + plan.trackCount[i];
    for (let k = plan.trackFrom[i]; k < tracksTo; k++) {
      const track = plan.trackList[k];
      v += trackValue(plan, plan.keyFrom[track], plan.keyCount[track], time);
    }
    const actionsTo = plan.actionFrom[i] + plan.actionCount[i];
    for (let k = plan.actionFrom[i]; k < actionsTo; k++) {
      const j = 5 * plan.actionList[k];
      v += actionAt(a[j], a[j + 1], a[j + 2], a[j + 3], a[j + 4], time);
    }
    out.values[i] = v < 0 ? 0 : v > 1 ? 1 : v;
  }
  out.time = time;
  return time;
}

/** A track's value at `time`: held before its first key and after its last, eased between. */
function trackValue(plan: Plan, from: number, count: number, time: number): number {
  if (count === 0) return 0;
  const times = plan.times;
  const last = from + count - 1;
  if (time <= times[from]) return plan.values[from];
  if (time >= times[last]) return plan.values[last];
  // The segment [lo, lo + 1] holding `time`: binary search, times being strictly increasing.
  let lo = from;
  let hi = last;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (times[mid] <= time) lo = mid;
    else hi = mid;
  }
  const u = (time - times[lo]) / (times[hi] - times[lo]);
  const v0 = plan.values[lo];
  return v0 + (plan.values[hi] - v0) * easeByCode(plan.easings[lo], u);
}
