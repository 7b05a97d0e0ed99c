import { beforeAll, describe, expect, it } from 'vitest';
import { carryShare, findNeck, NeckCarry } from '../src/core/rig/neck-carry';
import { inverseTransformPoint, POSE_TRANSFORM_SIZE, poseTransform, transformPoint } from '../src/core/expression/head-pose';
import { createSolverBuffers } from '../src/core/solver/solver-buffers';
import { faceLandmarks, type FaceLandmarks } from './fixtures/face-landmarks';
import { loadHeadSimulation, settleExpression } from './fixtures/head-simulation';

describe('the neck under a turned head', () => {
  let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
  let landmarks: FaceLandmarks;
  beforeAll(async () => {
    sim = await loadHeadSimulation('medium');
    landmarks = faceLandmarks(sim.host.topology.rest, sim.triangles);
  });

  it('finds the cut at the base of the neck: its loop, an axis up the neck and a pivot above it', () => {
    const { rest, triangles } = sim.host.topology;
    const neck = findNeck(rest, triangles)!;
    // The default head's cut runs from 5.8 cm under the mouth at the front up to the skull's base at the back.
    expect(neck.base[0]).toBeCloseTo(0, 6);
    expect(neck.base[1]).toBeGreaterThan(0.58);
    expect(neck.base[1]).toBeLessThan(0.61);
    expect(neck.up[1]).toBeGreaterThan(0.9);
    expect(neck.radius).toBeGreaterThan(0.04);
    expect(neck.radius).toBeLessThan(0.06);
    expect(neck.pivot[1]).toBeCloseTo(neck.base[1] + neck.length * neck.up[1], 12);
    // A closed skin (no cut) has no neck.
    expect(
      findNeck(new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]), new Uint32Array([0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2])),
    ).toBeNull();
  });

  it('carries the whole pose at the cut, none from the carried length up, smoothly between', () => {
    expect(carryShare(-0.01, 0.04)).toBe(1);
    expect(carryShare(0, 0.04)).toBe(1);
    expect(carryShare(0.02, 0.04)).toBeCloseTo(0.5, 12);
    expect(carryShare(0.04, 0.04)).toBe(0);
    expect(carryShare(0.001, 0.04)).toBeGreaterThan(carryShare(0.002, 0.04));
  });

  it('puts the cut’s targets where the inverse pose takes them, so the view’s turn brings them back to rest', () => {
    const { rest, triangles } = sim.host.topology;
    const carry = NeckCarry.create(rest, triangles)!;
    const inputs = createSolverBuffers(sim.host.topology);
    const pose = { yaw: 45, pitch: -10, roll: 5, forward: 0.01 };
    carry.apply(pose, inputs);
    const m = new Float64Array(POSE_TRANSFORM_SIZE);
    poseTransform(pose, 1, carry.frame.pivot, m);
    const shown = [0, 0, 0];
    const { base, up } = carry.frame;
    let checked = 0;
    for (const v of landmarks.neckCut) {
      const h = (rest[3 * v] - base[0]) * up[0] + (rest[3 * v + 1] - base[1]) * up[1] + (rest[3 * v + 2] - base[2]) * up[2];
      if (h > 0) continue;
      transformPoint(m, inputs.targets[3 * v], inputs.targets[3 * v + 1], inputs.targets[3 * v + 2], shown);
      for (let k = 0; k < 3; k++) expect(shown[k]).toBeCloseTo(rest[3 * v + k], 6);
      expect(inputs.weights[v]).toBe(1);
      checked++;
    }
    expect(checked).toBeGreaterThan(10);
    // The face, far above the carried length, is not touched; a resting pose touches nothing.
    const nose = 3 * landmarks.chin.left[0];
    expect(inputs.weights[nose / 3]).toBe(0);
    const untouched = createSolverBuffers(sim.host.topology);
    carry.apply({ yaw: 0, pitch: 0, roll: 0, forward: 0 }, untouched);
    expect(untouched.weights.every((w) => w === 0)).toBe(true);
    expect(untouched.targets).toEqual(rest);
    // inverseTransformPoint is the inverse the carry uses.
    inverseTransformPoint(m, ...([0.1, 0.6, 0.05] as const), shown);
    const again = [0, 0, 0];
    transformPoint(m, shown[0], shown[1], shown[2], again);
    expect(again[1]).toBeCloseTo(0.6, 12);
  });

  // Where the neck's skin bunches: the area of its triangles after the pose over their area at rest, on each side.
  const sideAreas = (): Record<'left' | 'right' | 'front' | 'back', number> => {
    const { rest } = sim.host.topology;
    const x = sim.host.solver.buffers.positions;
    const tri = sim.triangles;
    const neck = sim.host.neck!.frame;
    const sums = { left: [0, 0], right: [0, 0], front: [0, 0], back: [0, 0] };
    const area = (p: Float32Array, a: number, b: number, c: number) => {
      const u = [0, 1, 2].map((k) => p[3 * b + k] - p[3 * a + k]);
      const w = [0, 1, 2].map((k) => p[3 * c + k] - p[3 * a + k]);
      return Math.hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]);
    };
    for (let t = 0; t < tri.length; t += 3) {
      const c = [0, 1, 2].map((k) => (rest[3 * tri[t] + k] + rest[3 * tri[t + 1] + k] + rest[3 * tri[t + 2] + k]) / 3);
      const h = (c[0] - neck.base[0]) * neck.up[0] + (c[1] - neck.base[1]) * neck.up[1] + (c[2] - neck.base[2]) * neck.up[2];
      if (h > neck.length) continue;
      const dz = c[2] - neck.base[2];
      const side = Math.abs(c[0]) > Math.abs(dz) ? (c[0] > 0 ? 'left' : 'right') : dz > 0 ? 'front' : 'back';
      sums[side][0] += area(x, tri[t], tri[t + 1], tri[t + 2]);
      sums[side][1] += area(rest, tri[t], tri[t + 1], tri[t + 2]);
    }
    return {
      left: sums.left[0] / sums.left[1],
      right: sums.right[0] / sums.right[1],
      front: sums.front[0] / sums.front[1],
      back: sums.back[0] / sums.back[1],
    };
  };

  it.each([
    ['AU51', 'left', 'right'],
    ['AU52', 'right', 'left'],
    ['AU53', 'back', 'front'],
    ['AU54', 'front', 'back'],
    ['AU55', 'left', 'right'],
    ['AU56', 'right', 'left'],
  ] as const)('%s bunches the neck’s skin on its near side (%s) more than on its far side (%s)', (id, near, far) => {
    const r = settleExpression(sim, id, 1500);
    expect(r).toMatchObject({ sleeping: true, nonFinite: 0, inverted: 0 });
    const areas = sideAreas();
    console.log(
      `${id}: neck skin area over rest ${JSON.stringify(areas, (_k, v: unknown) => (typeof v === 'number' ? Number(v.toFixed(3)) : v))}`,
    );
    expect(areas[near]).toBeLessThan(0.97);
    expect(areas[far] - areas[near]).toBeGreaterThan(0.03);
  });
});
