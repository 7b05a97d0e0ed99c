/**
 * The eye simulation of thesis section 5.3.3 as a pure, seeded state machine: blinks at random intervals, gaze held
 * still for a while and then moved quickly (a saccade) to a random target, and the lid Action Unit shares that
 * follow from both. No DOM, no three.js, no allocation once constructed: a driver calls `advance` every frame.
 */
import { checkOptions, refusal } from '../check';
import { mulberry32 } from '../random';

/** Timing, range and lid options of the eye simulation; times in ms, angles in degrees. */
export interface EyeSimulationOptions {
  /** Seed of the random generator: the same seed gives the same blinks and gaze path. */
  seed: number;
  /**
   * Shortest time from one blink's start to the next's, ms (default 3000); each interval is drawn uniformly between
   * this and `blinkIntervalMax` (thesis: 3 to 8 s). It must exceed a whole blink plus `saccadeMax`.
   */
  blinkIntervalMin: number;
  /** Longest time from one blink's start to the next's, ms (default 8000). */
  blinkIntervalMax: number;
  /** How long the lids take to close at a blink's start, ms (default 100). */
  blinkClose: number;
  /** How long the lids stay fully closed in a blink, between closing and opening, ms (default 50). */
  blinkHold: number;
  /** How long the lids take to open again after the hold, ms (default 150: slower than closing, as in real blinks). */
  blinkOpen: number;
  /** Shortest time the gaze holds still between saccades, ms (default 500); each is drawn uniformly up to `holdMax`. */
  holdMin: number;
  /** Longest time the gaze holds still between saccades, ms (default 3000). */
  holdMax: number;
  /**
   * Shortest time a saccade takes, ms (default 40); each is drawn uniformly up to `saccadeMax` (real ones take
   * 20..100 ms, longer for larger turns).
   */
  saccadeMin: number;
  /** Longest time a saccade takes, ms (default 80), at most 1000. */
  saccadeMax: number;
  /**
   * Low end of the saccades' yaw, degrees, -45..45 (default -30: 30 to the subject's right); each target's yaw is
   * drawn uniformly between this and `yawMax` (thesis: -30..30). Positive yaw turns to the subject's left.
   */
  yawMin: number;
  /** High end of the saccades' yaw, degrees, -45..45 (default 30: 30 to the subject's left). */
  yawMax: number;
  /**
   * Low end of the saccades' pitch, degrees, -45..45 (default -20: 20 down); each target's pitch is drawn uniformly
   * between this and `pitchMax` (thesis: -20..25). Positive pitch turns up.
   */
  pitchMin: number;
  /** High end of the saccades' pitch, degrees, -45..45 (default 25: 25 up). */
  pitchMax: number;
  /** Lid closing (AU43) added per degree of downward gaze: the upper lid follows the eye down. */
  lidDownPerDegree: number;
  /** Lid raising (AU5) added per degree of upward gaze: the upper lid follows the eye up. */
  lidUpPerDegree: number;
}

/**
 * Defaults. The lid shares: AU43's lid muscle turns the upper lid by up to 38 degrees, so 0.013 per degree follows
 * about half of a downward turn (20 degrees down: AU43 0.26, the lid 10 degrees lower); AU5 turns it up by 17.5, so
 * 0.011 per degree follows about a fifth of an upward turn (25 up: AU5 0.275, the lid 4.8 degrees higher), enough to
 * keep the iris's top in view.
 */
export const EYE_SIMULATION_DEFAULTS: Readonly<Required<EyeSimulationOptions>> = Object.freeze({
  seed: 1,
  blinkIntervalMin: 3000,
  blinkIntervalMax: 8000,
  blinkClose: 100,
  blinkHold: 50,
  blinkOpen: 150,
  holdMin: 500,
  holdMax: 3000,
  saccadeMin: 40,
  saccadeMax: 80,
  yawMin: -30,
  yawMax: 30,
  pitchMin: -20,
  pitchMax: 25,
  lidDownPerDegree: 0.013,
  lidUpPerDegree: 0.011,
});

/** Each option's accepted range, as [least, greatest] (times in ms, angles in degrees). */
const OPTION_RANGES: Readonly<Record<keyof EyeSimulationOptions, readonly [number, number]>> = {
  seed: [0, 2 ** 32 - 1],
  blinkIntervalMin: [0, 600_000],
  blinkIntervalMax: [0, 600_000],
  blinkClose: [0, 10_000],
  blinkHold: [0, 10_000],
  blinkOpen: [0, 10_000],
  holdMin: [0, 600_000],
  holdMax: [0, 600_000],
  saccadeMin: [1, 1000],
  saccadeMax: [1, 1000],
  yawMin: [-45, 45],
  yawMax: [-45, 45],
  pitchMin: [-45, 45],
  pitchMax: [-45, 45],
  lidDownPerDegree: [0, 0.1],
  lidUpPerDegree: [0, 0.1],
};

/**
 * Checks eye simulation options given by a caller (`where` names it in messages): an object of known options, each a
 * number in its range (the seed an integer), whose ranges are ordered and whose blinks fit between each other. Returns
 * the options; throws `<where>: <option>: expected …, got …` otherwise.
 */
export function checkEyeSimulationOptions(value: unknown, where: string): Partial<EyeSimulationOptions> {
  const given = checkOptions<EyeSimulationOptions>(where, value, EYE_SIMULATION_DEFAULTS, { ranges: OPTION_RANGES, integers: ['seed'] });
  const o = { ...EYE_SIMULATION_DEFAULTS, ...given };
  for (const [min, max] of [
    ['blinkIntervalMin', 'blinkIntervalMax'],
    ['holdMin', 'holdMax'],
    ['saccadeMin', 'saccadeMax'],
    ['yawMin', 'yawMax'],
    ['pitchMin', 'pitchMax'],
  ] as const)
    if (o[min] > o[max]) throw refusal(where, min, `at most ${max} (${o[max]})`, o[min]);
  const blink = o.blinkClose + o.blinkHold + o.blinkOpen + o.saccadeMax;
  if (!(o.blinkIntervalMin > blink))
    throw refusal(where, 'blinkIntervalMin', `more than a blink and a saccade (${blink} ms)`, o.blinkIntervalMin);
  return given;
}

/** A small seeded generator (mulberry32): uniform numbers in [0, 1), the same sequence for the same seed. */
export class SeededRandom {
  private readonly draw: () => number;

  constructor(seed: number) {
    this.draw = mulberry32(seed);
  }

  /** The next number in [0, 1). */
  next(): number {
    return this.draw();
  }

  /** A uniform number in [min, max). */
  between(min: number, max: number): number {
    return min + (max - min) * this.next();
  }
}

/** Hermite ease (0 -> 0, 1 -> 1, flat at both ends): a saccade speeds up and brakes. */
function smoothstep(x: number): number {
  return x <= 0 ? 0 : x >= 1 ? 1 : x * x * (3 - 2 * x);
}

/**
 * Blinks and gaze over time. Times are ms on the caller's clock, starting at 0. Events happen at their scheduled
 * times however coarse the steps are, so counts and intervals do not depend on the frame rate.
 *
 * No blink starts during a saccade: a saccade that would overlap a blink in progress or due waits until that blink
 * has ended (the thesis updates the gaze only while the eye does not blink). Blinks keep their schedule exactly.
 */
export class EyeSimulation {
  /** Blinks started and saccades started since construction or `reset`. */
  blinks = 0;
  saccades = 0;
  /** Current gaze in degrees. */
  yaw = 0;
  pitch = 0;
  /** Lid closure of the blink now, 0 open .. 1 closed (the largest since the previous step, see `advance`). */
  blink = 0;
  /** Whether a blink or a saccade is under way at the current time. */
  blinking = false;
  saccading = false;
  /** Start times of the last blink and saccade (-Infinity before the first), and the last saccade's duration. */
  lastBlinkStart = -Infinity;
  lastSaccadeStart = -Infinity;
  lastSaccadeDuration = 0;

  private readonly o: Readonly<Required<EyeSimulationOptions>>;
  private readonly random: SeededRandom;
  private time = 0;
  private nextBlinkAt = 0;
  private nextSaccadeAt = 0;
  private saccadeEnd = 0;
  private fromYaw = 0;
  private fromPitch = 0;
  private toYaw = 0;
  private toPitch = 0;

  constructor(options: Partial<EyeSimulationOptions> = {}) {
    this.o = { ...EYE_SIMULATION_DEFAULTS, ...options };
    const o = this.o;
    if (!(o.blinkIntervalMin > o.blinkClose + o.blinkHold + o.blinkOpen + o.saccadeMax))
      throw new Error('EyeSimulation: blink intervals must be longer than a blink and a saccade');
    if (!(o.blinkIntervalMax >= o.blinkIntervalMin && o.holdMax >= o.holdMin && o.saccadeMax >= o.saccadeMin && o.saccadeMin > 0))
      throw new Error('EyeSimulation: a range has its maximum below its minimum');
    this.random = new SeededRandom(o.seed);
    this.reset();
  }

  /** Back to time 0: gaze straight ahead, lids open, counts zeroed, the first blink and saccade drawn anew. */
  reset(): void {
    this.time = 0;
    this.blinks = this.saccades = 0;
    this.yaw = this.pitch = this.fromYaw = this.fromPitch = this.toYaw = this.toPitch = 0;
    this.blink = 0;
    this.blinking = this.saccading = false;
    this.lastBlinkStart = this.lastSaccadeStart = -Infinity;
    this.lastSaccadeDuration = 0;
    this.nextBlinkAt = this.random.between(this.o.blinkIntervalMin, this.o.blinkIntervalMax);
    this.nextSaccadeAt = this.random.between(this.o.holdMin, this.o.holdMax);
  }

  /** The time of the last `advance`. */
  get now(): number {
    return this.time;
  }

  /** Length of a whole blink (close, hold, open). */
  get blinkDuration(): number {
    return this.o.blinkClose + this.o.blinkHold + this.o.blinkOpen;
  }

  /**
   * Moves to time `t` (ms, not before the current time), running every blink and saccade due on the way. `blink`
   * becomes the largest closure over the stepped interval, so that a slow frame cannot skip a blink's closed phase.
   */
  advance(t: number): void {
    if (!(t >= this.time)) return;
    const from = this.time;
    for (;;) {
      // The earliest event due by t: a blink start or a saccade start or end.
      const saccadeEvent = this.saccading ? this.saccadeEnd : this.nextSaccadeAt;
      if (this.nextBlinkAt <= t && this.nextBlinkAt <= saccadeEvent) this.startBlink();
      else if (saccadeEvent <= t) {
        if (this.saccading) this.endSaccade();
        else this.startSaccade();
      } else break;
    }
    this.time = t;
    this.updateGaze(t);
    this.blink = this.blinkPeak(from, t);
    this.blinking = t < this.lastBlinkStart + this.blinkDuration;
  }

  /** AU43 (lid closing) share now: the gaze's downward follow, closed the rest of the way by the blink. */
  lidClose(): number {
    const follow = Math.min(1, Math.max(0, -this.pitch) * this.o.lidDownPerDegree);
    return follow + (1 - follow) * this.blink;
  }

  /** AU5 (lid raising) share now: the gaze's upward follow, let go while a blink closes the lid. */
  lidRaise(): number {
    return Math.min(1, Math.max(0, this.pitch) * this.o.lidUpPerDegree) * (1 - this.blink);
  }

  private startBlink(): void {
    // Saccades are scheduled around blinks, so none can be under way here; if one were, it would end first.
    if (this.saccading) this.endSaccade();
    const start = this.nextBlinkAt;
    this.lastBlinkStart = start;
    this.blinks++;
    this.nextBlinkAt = start + this.random.between(this.o.blinkIntervalMin, this.o.blinkIntervalMax);
  }

  private startSaccade(): void {
    const start = this.nextSaccadeAt;
    const duration = this.random.between(this.o.saccadeMin, this.o.saccadeMax);
    const blinkEnd = this.lastBlinkStart + this.blinkDuration;
    if (start < blinkEnd) {
      this.nextSaccadeAt = blinkEnd; // wait for the blink in progress
      return;
    }
    if (this.nextBlinkAt < start + duration) {
      this.nextSaccadeAt = this.nextBlinkAt + this.blinkDuration; // a blink is due before the saccade would end
      return;
    }
    this.fromYaw = this.toYaw;
    this.fromPitch = this.toPitch;
    this.toYaw = this.random.between(this.o.yawMin, this.o.yawMax);
    this.toPitch = this.random.between(this.o.pitchMin, this.o.pitchMax);
    this.saccading = true;
    this.lastSaccadeStart = start;
    this.lastSaccadeDuration = duration;
    this.saccadeEnd = start + duration;
    this.saccades++;
  }

  private endSaccade(): void {
    this.saccading = false;
    this.fromYaw = this.toYaw;
    this.fromPitch = this.toPitch;
    this.nextSaccadeAt = this.saccadeEnd + this.random.between(this.o.holdMin, this.o.holdMax);
  }

  private updateGaze(t: number): void {
    const s = this.saccading ? smoothstep((t - this.lastSaccadeStart) / this.lastSaccadeDuration) : 1;
    this.yaw = this.fromYaw + (this.toYaw - this.fromYaw) * s;
    this.pitch = this.fromPitch + (this.toPitch - this.fromPitch) * s;
  }

  /** Lid closure of the last blink at time t: linear close, hold, linear open. */
  private closureAt(t: number): number {
    const o = this.o;
    const u = t - this.lastBlinkStart;
    if (!(u >= 0)) return 0;
    if (u < o.blinkClose) return u / o.blinkClose;
    if (u <= o.blinkClose + o.blinkHold) return 1;
    if (u < this.blinkDuration) return 1 - (u - o.blinkClose - o.blinkHold) / o.blinkOpen;
    return 0;
  }

  /** Largest closure over [a, b]: the closure rises, holds and falls, so it is 1 if the hold overlaps, else an end's. */
  private blinkPeak(a: number, b: number): number {
    const holdStart = this.lastBlinkStart + this.o.blinkClose;
    const holdEnd = holdStart + this.o.blinkHold;
    if (a <= holdEnd && b >= holdStart) return 1;
    return Math.max(this.closureAt(a), this.closureAt(b));
  }
}
