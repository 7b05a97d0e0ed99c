import { describe, expect, it } from 'vitest';
import {
  checkEyeSimulationOptions,
  EYE_SIMULATION_DEFAULTS as D,
  EyeSimulation,
  SeededRandom,
} from '../src/core/expression/eye-simulation';

interface Run {
  blinkStarts: number[];
  saccades: { start: number; duration: number }[];
  yaw: [number, number];
  pitch: [number, number];
  maxBlink: number;
  maxLidClose: number;
  maxLidRaise: number;
}

/** Runs a simulation for `ms` in steps of `step` ms and records every blink and saccade it starts. */
function run(seed: number, ms: number, step: number): Run {
  const sim = new EyeSimulation({ seed });
  const out: Run = {
    blinkStarts: [],
    saccades: [],
    yaw: [Infinity, -Infinity],
    pitch: [Infinity, -Infinity],
    maxBlink: 0,
    maxLidClose: 0,
    maxLidRaise: 0,
  };
  for (let t = 0; t <= ms; t += step) {
    const blinks = sim.blinks;
    const saccades = sim.saccades;
    sim.advance(t);
    // A step spans at most one event of each kind at these step sizes (blinks >= 3 s, holds >= 0.5 s apart).
    expect(sim.blinks - blinks).toBeLessThanOrEqual(1);
    expect(sim.saccades - saccades).toBeLessThanOrEqual(1);
    if (sim.blinks > blinks) out.blinkStarts.push(sim.lastBlinkStart);
    if (sim.saccades > saccades) out.saccades.push({ start: sim.lastSaccadeStart, duration: sim.lastSaccadeDuration });
    out.yaw = [Math.min(out.yaw[0], sim.yaw), Math.max(out.yaw[1], sim.yaw)];
    out.pitch = [Math.min(out.pitch[0], sim.pitch), Math.max(out.pitch[1], sim.pitch)];
    out.maxBlink = Math.max(out.maxBlink, sim.blink);
    out.maxLidClose = Math.max(out.maxLidClose, sim.lidClose());
    out.maxLidRaise = Math.max(out.maxLidRaise, sim.lidRaise());
  }
  return out;
}

describe('the seeded random generator', () => {
  it('repeats its sequence for a seed, differs for another, and stays in [0, 1)', () => {
    const a = new SeededRandom(7);
    const b = new SeededRandom(7);
    const c = new SeededRandom(8);
    const xs = Array.from({ length: 1000 }, () => a.next());
    expect(Array.from({ length: 1000 }, () => b.next())).toEqual(xs);
    expect(Array.from({ length: 1000 }, () => c.next())).not.toEqual(xs);
    expect(Math.min(...xs)).toBeGreaterThanOrEqual(0);
    expect(Math.max(...xs)).toBeLessThan(1);
    const mean = xs.reduce((s, x) => s + x, 0) / xs.length;
    expect(mean).toBeGreaterThan(0.45);
    expect(mean).toBeLessThan(0.55);
  });
});

describe('the eye simulation over a simulated minute', () => {
  for (const seed of [1, 2, 3, 42, 1234]) {
    it(`seed ${seed}: blinks every 3 to 8 s, saccades of 40 to 80 ms after holds, gaze within its range, no blink during a saccade`, () => {
      const r = run(seed, 60_000, 5);
      // 60 s at 3..8 s apart: between 7 and 20 blinks.
      expect(r.blinkStarts.length).toBeGreaterThanOrEqual(7);
      expect(r.blinkStarts.length).toBeLessThanOrEqual(20);
      expect(r.blinkStarts[0]).toBeGreaterThanOrEqual(D.blinkIntervalMin);
      expect(r.blinkStarts[0]).toBeLessThanOrEqual(D.blinkIntervalMax);
      for (let i = 1; i < r.blinkStarts.length; i++) {
        const interval = r.blinkStarts[i] - r.blinkStarts[i - 1];
        expect(interval).toBeGreaterThanOrEqual(D.blinkIntervalMin);
        expect(interval).toBeLessThanOrEqual(D.blinkIntervalMax);
      }
      // Holds of 0.5..3 s plus a blink's wait: at least 60 / 3.4 saccades, at most 60 / 0.54.
      expect(r.saccades.length).toBeGreaterThanOrEqual(17);
      expect(r.saccades.length).toBeLessThanOrEqual(111);
      const blinkLength = D.blinkClose + D.blinkHold + D.blinkOpen;
      for (let i = 0; i < r.saccades.length; i++) {
        const s = r.saccades[i];
        expect(s.duration).toBeGreaterThanOrEqual(D.saccadeMin);
        expect(s.duration).toBeLessThanOrEqual(D.saccadeMax);
        const previousEnd = i === 0 ? 0 : r.saccades[i - 1].start + r.saccades[i - 1].duration;
        // At least the shortest hold after the previous one; at most the longest hold plus waiting out one blink.
        expect(s.start - previousEnd).toBeGreaterThanOrEqual(D.holdMin - 1e-9);
        expect(s.start - previousEnd).toBeLessThanOrEqual(D.holdMax + D.saccadeMax + blinkLength + 1e-9);
        for (const b of r.blinkStarts) {
          const during = b >= s.start && b < s.start + s.duration;
          expect(during, `blink at ${b.toFixed(1)} ms during the saccade ${s.start.toFixed(1)}+${s.duration.toFixed(1)} ms`).toBe(false);
          // Nor does a saccade start while a blink is under way.
          expect(s.start >= b && s.start < b + blinkLength).toBe(false);
        }
      }
      expect(r.yaw[0]).toBeGreaterThanOrEqual(D.yawMin);
      expect(r.yaw[1]).toBeLessThanOrEqual(D.yawMax);
      expect(r.pitch[0]).toBeGreaterThanOrEqual(D.pitchMin);
      expect(r.pitch[1]).toBeLessThanOrEqual(D.pitchMax);
      // The gaze really wanders: it covers most of its range in a minute.
      expect(r.yaw[1] - r.yaw[0]).toBeGreaterThan(30);
      expect(r.pitch[1] - r.pitch[0]).toBeGreaterThan(20);
      expect(r.maxBlink).toBe(1);
      expect(r.maxLidClose).toBe(1);
      expect(r.maxLidRaise).toBeGreaterThan(0);
      expect(r.maxLidRaise).toBeLessThan(0.5);
    });
  }

  it('is deterministic for a seed and independent of the step size', () => {
    const fine = run(9, 30_000, 1);
    const coarse = run(9, 30_000, 250);
    expect(coarse.blinkStarts).toEqual(fine.blinkStarts);
    expect(coarse.saccades).toEqual(fine.saccades);
    expect(run(9, 30_000, 1)).toEqual(fine);
    expect(run(10, 30_000, 1).blinkStarts).not.toEqual(fine.blinkStarts);
  });

  it('reports a closed lid even when a slow frame steps over the whole blink', () => {
    const sim = new EyeSimulation({ seed: 5 });
    let closedSteps = 0;
    for (let t = 0; t <= 20_000; t += 400) {
      const blinks = sim.blinks;
      sim.advance(t);
      if (sim.blinks > blinks) expect(sim.blink).toBe(1);
      if (sim.blink === 1) closedSteps++;
    }
    expect(closedSteps).toBeGreaterThanOrEqual(sim.blinks);
    expect(sim.blinks).toBeGreaterThanOrEqual(2);
  });

  it('shapes a blink as a close of 100 ms, a hold of 50 ms and an open of 150 ms', () => {
    const sim = new EyeSimulation({ seed: 3 });
    // Blinks come every few seconds: a minute of 1 ms steps holds one.
    for (let t = 1; sim.blinks === 0 && t <= 60_000; t++) sim.advance(t);
    expect(sim.blinks).toBeGreaterThan(0);
    const start = sim.lastBlinkStart;
    const closureAt = (dt: number): number => {
      sim.advance(start + dt);
      sim.advance(start + dt); // a zero step: the closure at that moment, not the peak since the last step
      return sim.blink;
    };
    expect(closureAt(50)).toBeCloseTo(0.5, 6);
    expect(closureAt(100)).toBe(1);
    expect(closureAt(150)).toBe(1);
    expect(closureAt(225)).toBeCloseTo(0.5, 6);
    expect(closureAt(300)).toBe(0);
    expect(sim.blinking).toBe(false);
  });

  it('lets the upper lid follow the gaze: down closes it a little, up raises it', () => {
    const sim = new EyeSimulation({ seed: 11, blinkIntervalMin: 1e9, blinkIntervalMax: 1e9 });
    let down = false;
    let up = false;
    for (let t = 0; t < 60_000 && !(down && up); t += 10) {
      sim.advance(t);
      if (sim.pitch < -10) {
        down = true;
        expect(sim.lidClose()).toBeCloseTo(-sim.pitch * D.lidDownPerDegree, 9);
        expect(sim.lidRaise()).toBe(0);
      }
      if (sim.pitch > 10) {
        up = true;
        expect(sim.lidRaise()).toBeCloseTo(sim.pitch * D.lidUpPerDegree, 9);
        expect(sim.lidClose()).toBe(0);
      }
    }
    expect(down && up).toBe(true);
  });

  it('refuses options whose blinks could not fit between intervals', () => {
    expect(() => new EyeSimulation({ blinkIntervalMin: 200 })).toThrow(/blink intervals/);
    expect(() => new EyeSimulation({ holdMin: 4000 })).toThrow(/maximum below/);
  });
});

describe('checkEyeSimulationOptions', () => {
  it('accepts known options within their ranges and returns them', () => {
    const o = { seed: 7, blinkHold: 600, blinkIntervalMin: 1500, blinkIntervalMax: 2000 };
    expect(checkEyeSimulationOptions(o, 'test')).toBe(o);
    expect(() => new EyeSimulation(o)).not.toThrow();
  });

  it.each([
    [null, 'test: expected an object of options, got null'],
    [[1], 'test: expected an object of options, got [1]'],
    [{ blinkHoldMs: 5 }, 'test: expected one of the options seed, blinkIntervalMin,'],
    [{ blinkHold: -1 }, 'test: blinkHold: expected a number from 0 to 10000, got -1'],
    [{ blinkHold: Number.NaN }, 'test: blinkHold: expected a number from 0 to 10000, got NaN'],
    [{ seed: 1.5 }, 'test: seed: expected an integer from 0 to 4294967295, got 1.5'],
    [{ yawMin: 20, yawMax: 10 }, 'test: yawMin: expected at most yawMax (10), got 20'],
    [{ blinkIntervalMin: 200 }, 'test: blinkIntervalMin: expected more than a blink and a saccade (380 ms), got 200'],
  ])('refuses %j, naming what is wrong', (value, message) => {
    expect(() => checkEyeSimulationOptions(value, 'test')).toThrow(message);
  });
});
