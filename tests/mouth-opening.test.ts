import { beforeAll, describe, expect, it } from 'vitest';
import { DEFAULT_LANDMARKS } from '../src/core/head/landmarks';
import { findLipSlit, type LipSlit } from '../src/core/head/lip-slit';
import {
  MOUTH_OPENING_SIZE,
  OPENING_ACROSS,
  OPENING_CENTRE,
  OPENING_HALF,
  OPENING_OUT,
  OPENING_UP,
  lightThroughOpening,
  measureMouthOpening,
  nearestVertex,
  openingView,
} from '../src/core/head/mouth-opening';
import { DEGREES } from '../src/core/math3';
import type { Vec3 } from '../src/core/rig/rig-types';
import { loadHeadSimulation, resetToRest } from './fixtures/head-simulation';

/** An opening in the xy plane at the origin, looking out along +z, with half sizes `a` by `b` (metres). */
function flatOpening(a: number, b: number): Float64Array {
  const o = new Float64Array(MOUTH_OPENING_SIZE);
  o.set([1, 0, 0], OPENING_ACROSS);
  o.set([0, 1, 0], OPENING_UP);
  o.set([0, 0, 1], OPENING_OUT);
  o[OPENING_HALF] = a;
  o[OPENING_HALF + 1] = b;
  return o;
}

/**
 * The view factor from a patch at `p` facing +z to the opening's rectangle (of the ellipse's area), by the midpoint
 * rule on an n by n grid: the integral of cos^2 / (pi s^2) over the rectangle.
 */
function integratedView(a: number, b: number, p: Vec3, n = 600): number {
  const hx = (Math.sqrt(Math.PI) / 2) * a;
  const hy = (Math.sqrt(Math.PI) / 2) * b;
  const depth = -p[2];
  const dx = (2 * hx) / n;
  const dy = (2 * hy) / n;
  let sum = 0;
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < n; j++) {
      const s2 = (-hx + (i + 0.5) * dx - p[0]) ** 2 + (-hy + (j + 0.5) * dy - p[1]) ** 2 + depth * depth;
      sum += (depth * depth) / (Math.PI * s2 * s2);
    }
  }
  return sum * dx * dy;
}

describe('the light inside the mouth: the view of the lips opening and the key light through it', () => {
  it('the view of the opening is the exact view factor of its rectangle, on axis, off it and behind the cheek', () => {
    const o = flatOpening(0.02, 0.008);
    for (const p of [
      [0, 0, -0.006],
      [0.005, -0.003, -0.012],
      [0.03, 0.002, -0.01],
      [0, 0, -0.04],
    ] as Vec3[]) {
      expect(openingView(o, p)).toBeCloseTo(integratedView(0.02, 0.008, p), 3);
    }
  });

  it('sees all of the room just behind a wide opening, none of it behind closed lips', () => {
    expect(openingView(flatOpening(1, 1), [0, 0, -0.001])).toBeGreaterThan(0.999);
    expect(openingView(flatOpening(0.025, 0), [0, 0, -0.005])).toBe(0);
    // A slit two millimetres high leaves a point 5 mm behind it a fifth of the room (the strip's view factor).
    expect(openingView(flatOpening(1, 0.001 / (Math.sqrt(Math.PI) / 2)), [0, 0, -0.005])).toBeCloseTo(0.001 / Math.hypot(0.001, 0.005), 2);
  });

  it('lets a light in where its ray crosses the opening, not where the ray meets the lip or comes from behind', () => {
    const o = flatOpening(0.02, 0.008);
    expect(lightThroughOpening(o, [0, 0, -0.01], [0, 0, 1])).toBe(1);
    // 30 degrees up: the ray rises 5.8 mm over 10 mm of depth (inside), 17 mm over 30 mm (on the upper lip).
    const up30: Vec3 = [0, Math.sin(30 * DEGREES), Math.cos(30 * DEGREES)];
    expect(lightThroughOpening(o, [0, 0, -0.01], up30)).toBeGreaterThan(0.9);
    expect(lightThroughOpening(o, [0, 0, -0.03], up30)).toBe(0);
    expect(lightThroughOpening(o, [0, 0, -0.01], [0, 0, -1])).toBe(0);
  });

  describe('on the default head', () => {
    let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
    let slit: LipSlit;
    let left: number;
    let right: number;
    beforeAll(async () => {
      sim = await loadHeadSimulation('low');
      const rest = sim.host.topology.rest;
      slit = findLipSlit(rest, sim.host.topology.restNormals, DEFAULT_LANDMARKS['mouth-l'], DEFAULT_LANDMARKS['mouth-r'])!;
      left = nearestVertex(rest, DEFAULT_LANDMARKS['mouth-l']);
      right = nearestVertex(rest, DEFAULT_LANDMARKS['mouth-r']);
    }, 120_000);

    /** The opening measured on the solved skin after `item` at full intensity (or at rest). */
    function openingUnder(item: string | null): Float64Array {
      resetToRest(sim);
      if (item) {
        sim.expression.setActionUnit(item, 1);
        sim.apply();
        for (let k = 0; k < 1500 && sim.host.step(); k++);
      }
      const out = new Float64Array(MOUTH_OPENING_SIZE);
      measureMouthOpening(sim.host.solver.buffers.positions, slit, left, right, out);
      return out;
    }

    /** A point `depth` metres behind the opening's centre and `side` metres across it. */
    function behind(o: Float64Array, depth: number, side = 0): Vec3 {
      const p: Vec3 = [0, 0, 0];
      for (let k = 0; k < 3; k++) p[k] = o[OPENING_CENTRE + k] - depth * o[OPENING_OUT + k] + side * o[OPENING_ACROSS + k];
      return p;
    }

    it('lies across the mouth facing forward; closed at rest, the teeth behind the lips see almost none of the room', () => {
      const o = openingUnder(null);
      expect(o[OPENING_ACROSS]).toBeGreaterThan(Math.cos(10 * DEGREES));
      expect(o[OPENING_OUT + 2]).toBeGreaterThan(Math.cos(30 * DEGREES));
      expect(o[OPENING_UP + 1]).toBeGreaterThan(Math.cos(30 * DEGREES));
      expect(o[OPENING_HALF]).toBeGreaterThan(0.015);
      expect(o[OPENING_HALF + 1]).toBeLessThan(0.001);
      expect(openingView(o, behind(o, 0.006))).toBeLessThan(0.1);
    });

    it('opens with the jaw (AU26): the front teeth see much of the room and take the key light, the back of the mouth does not', () => {
      const o = openingUnder('AU26');
      expect(o[OPENING_HALF + 1]).toBeGreaterThan(0.005);
      expect(openingView(o, behind(o, 0.006))).toBeGreaterThan(0.4);
      // Behind the cheek, 3 cm to the side.
      expect(openingView(o, behind(o, 0.01, 0.03))).toBeLessThan(0.15);
      // The default key light: 29 degrees to the face's left, 30 up.
      const key: Vec3 = [
        Math.sin(29 * DEGREES) * Math.cos(30 * DEGREES),
        Math.sin(30 * DEGREES),
        Math.cos(29 * DEGREES) * Math.cos(30 * DEGREES),
      ];
      expect(lightThroughOpening(o, behind(o, 0.006), key)).toBeGreaterThan(0.9);
      expect(lightThroughOpening(o, behind(o, 0.04), key)).toBe(0);
    });
  });
});
