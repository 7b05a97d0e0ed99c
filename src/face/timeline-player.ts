import {
  createTimelineSample,
  localTime,
  PRESET_TARGET_PREFIX,
  sampleTimeline,
  timelineDuration,
  type Timeline,
  type TimelineSample,
} from '../core/timeline/timeline';
import type { FrameHooks } from './eye-driver';
import type { FaceTimeline, TimelineState } from './face-ports';

/** Where the player's frames go: the face's sliders and preset weights, and the news that its clock moved. */
export interface TimelineTarget {
  /** Sets sliders and preset weights (see `ExpressionState.setFrame`); returns whether they changed. */
  applyFrame(ids: readonly string[], values: ArrayLike<number>, presets: readonly string[], weights: ArrayLike<number>): boolean;
  clockMoved(): void;
}

/** Options of the timeline player. */
export interface TimelinePlayerOptions {
  /**
   * Longest gap between two frames that counts in full, in ms: after a longer one (a hidden tab, a face scrolled out
   * of view, a stalled machine) the timeline moves on by this much, so that it does not jump past what was not seen.
   */
  maxStepMs?: number;
}

const TIMELINE_PLAYER_DEFAULTS: Required<TimelinePlayerOptions> = { maxStepMs: 250 };

/**
 * Plays a timeline on the face like a media player: every frame while it plays it moves the clock on by the frame's
 * time and sets the sliders and preset weights the timeline names to their sampled values (the sliders follow: the
 * panels show what the face shows). Sides and presets it does not name stay as the user left them. Paused, it holds;
 * a seek sets the values of its time once. A recorder steps it at a fixed time per frame with `seek`, paused.
 */
export class TimelinePlayer implements FaceTimeline {
  private readonly o: Required<TimelinePlayerOptions>;
  private readonly stopFrames: () => void;
  private timelineNow: Timeline | null = null;
  private sample: TimelineSample | undefined;
  /** Where each Action Unit side and preset of the sample goes: its index in the sample, and its id or name. */
  private unitIndex = new Int32Array(0);
  private unitIds: string[] = [];
  private unitValues = new Float64Array(0);
  private presetIndex = new Int32Array(0);
  private presetNames: string[] = [];
  private presetValues = new Float64Array(0);
  private time = 0;
  private duration = 0;
  private playing = false;
  /** Frame time of the last frame played (NaN until the first frame after `play`). */
  private lastFrame = Number.NaN;

  constructor(
    private readonly face: TimelineTarget,
    frames: FrameHooks,
    options: TimelinePlayerOptions = {},
  ) {
    this.o = { ...TIMELINE_PLAYER_DEFAULTS, ...options };
    this.stopFrames = frames.onFrame((now) => this.frame(now));
  }

  /** Loads a checked timeline (or none), paused at 0, and sets the face to its start. */
  set(timeline: Timeline | null): void {
    this.playing = false;
    this.time = 0;
    this.timelineNow = timeline;
    if (!timeline) {
      this.sample = undefined;
      this.duration = 0;
      return;
    }
    const sample = createTimelineSample(timeline);
    const units: number[] = [];
    const presets: number[] = [];
    sample.targets.forEach((target, i) => (target.startsWith(PRESET_TARGET_PREFIX) ? presets : units).push(i));
    this.sample = sample;
    this.unitIndex = Int32Array.from(units);
    this.unitIds = units.map((i) => sample.targets[i]);
    this.unitValues = new Float64Array(units.length);
    this.presetIndex = Int32Array.from(presets);
    this.presetNames = presets.map((i) => sample.targets[i].slice(PRESET_TARGET_PREFIX.length));
    this.presetValues = new Float64Array(presets.length);
    this.duration = timelineDuration(timeline);
    this.apply();
  }

  timeline(): Timeline | null {
    return this.timelineNow;
  }

  /** Plays from the current time (from the start again if a timeline without loop had ended). */
  play(): void {
    if (!this.timelineNow) return;
    if (!this.timelineNow.loop && this.time >= this.duration) this.time = 0;
    this.playing = true;
    this.lastFrame = Number.NaN;
  }

  pause(): void {
    this.playing = false;
  }

  /** Moves the clock to `seconds` (wrapped with loop, clamped without) and sets the face to the values there. */
  seek(seconds: number): void {
    if (!this.timelineNow) return;
    this.time = localTime(this.timelineNow, seconds);
    this.lastFrame = Number.NaN;
    this.apply();
  }

  state(): TimelineState {
    return {
      loaded: this.timelineNow !== null,
      playing: this.playing,
      time: this.time,
      duration: this.duration,
      loop: this.timelineNow?.loop ?? false,
    };
  }

  /** Stops following frames, for good: the face is going away. */
  dispose(): void {
    this.stopFrames();
    this.playing = false;
  }

  /** Moves the clock on by the frame's time and sets the face; returns whether the face changed. */
  private frame(now: number): boolean {
    if (!this.playing || !this.timelineNow) return false;
    if (Number.isNaN(this.lastFrame)) {
      this.lastFrame = now;
      return this.apply();
    }
    const step = Math.min(Math.max(now - this.lastFrame, 0), this.o.maxStepMs) / 1000;
    this.lastFrame = now;
    const t = this.time + step;
    if (!this.timelineNow.loop && t >= this.duration) {
      // The end of a timeline that does not loop: it stops there, as a player does.
      this.time = this.duration;
      this.playing = false;
    } else this.time = localTime(this.timelineNow, t);
    const changed = this.apply();
    this.face.clockMoved();
    return changed;
  }

  /** Samples the timeline at the clock's time and sets the face's sliders and preset weights to it. */
  private apply(): boolean {
    const sample = this.sample;
    if (!this.timelineNow || !sample) return false;
    sampleTimeline(this.timelineNow, this.time, sample);
    for (let i = 0; i < this.unitIndex.length; i++) this.unitValues[i] = sample.values[this.unitIndex[i]];
    for (let i = 0; i < this.presetIndex.length; i++) this.presetValues[i] = sample.values[this.presetIndex[i]];
    return this.face.applyFrame(this.unitIds, this.unitValues, this.presetNames, this.presetValues);
  }
}
