import { describe, expect, it } from 'vitest';
import { ExpressionState } from '../src/core/expression/facs';
import {
  actionUnitHeadPose,
  HEAD_POSE_AT_E,
  inverseTransformPoint,
  POSE_TRANSFORM_SIZE,
  poseTransform,
  restingHeadPose,
  transformPoint,
  type HeadPose,
} from '../src/core/expression/head-pose';
import { mulberry32 } from '../src/core/random';

describe('the head positions AU51 to AU58 as a head pose', () => {
  const pose = (units: Record<string, number>): HeadPose => {
    const s = new ExpressionState();
    for (const [id, v] of Object.entries(units)) s.setActionUnit(id, v);
    return actionUnitHeadPose((id) => s.effectiveOf(id), restingHeadPose());
  };
  const moved = (p: HeadPose, point: [number, number, number], pivot: [number, number, number] = [0, 0, 0], fraction = 1) => {
    const m = new Float64Array(POSE_TRANSFORM_SIZE);
    poseTransform(p, fraction, pivot, m);
    const out = [0, 0, 0];
    transformPoint(m, ...point, out);
    return out;
  };

  it('reach FACS E grades: 45 degrees of turn, 30 up, down and to either side, 2 cm forward and back', () => {
    expect(HEAD_POSE_AT_E).toEqual({ turn: 45, up: 30, down: 30, tilt: 30, forward: 0.02, back: 0.02 });
    expect(pose({ AU51: 1 })).toEqual({ yaw: 45, pitch: 0, roll: 0, forward: 0 });
    expect(pose({ AU52: 1 }).yaw).toBe(-45);
    expect(pose({ AU53: 1 }).pitch).toBe(30);
    expect(pose({ AU54: 1 }).pitch).toBe(-30);
    expect(pose({ AU55: 1 }).roll).toBe(30);
    expect(pose({ AU56: 1 }).roll).toBe(-30);
    expect(pose({ AU57: 1 }).forward).toBe(0.02);
    expect(pose({ AU58: 1 }).forward).toBe(-0.02);
    expect(pose({ AU51: 0.5, AU52: 0.5 }).yaw).toBe(0);
    expect(pose({ AU51: 0.2 }).yaw).toBeCloseTo(9, 12);
  });

  it('turn the face toward the subject’s left for AU51, up for AU53, and the crown toward the left shoulder for AU55', () => {
    // The face looks along +z; the subject's left is +x.
    const left = moved(pose({ AU51: 1 }), [0, 0, 1]);
    expect(left[0]).toBeCloseTo(Math.SQRT1_2, 12);
    expect(left[2]).toBeCloseTo(Math.SQRT1_2, 12);
    const up = moved(pose({ AU53: 1 }), [0, 0, 1]);
    expect(up[1]).toBeCloseTo(0.5, 12);
    const tilt = moved(pose({ AU55: 1 }), [0, 1, 0]);
    expect(tilt[0]).toBeCloseTo(0.5, 12);
    // A pure tilt leaves the face looking ahead; forward moves along +z.
    expect(moved(pose({ AU55: 1 }), [0, 0, 1])).toEqual([0, 0, 1]);
    expect(moved(pose({ AU57: 1 }), [0, 0, 0])).toEqual([0, 0, 0.02]);
  });

  it('turn about the pivot, a fraction of the pose at a time, and undo exactly with the inverse', () => {
    const pivot: [number, number, number] = [0.01, 0.63, 0.04];
    const random = mulberry32(7);
    const m = new Float64Array(POSE_TRANSFORM_SIZE);
    for (let k = 0; k < 50; k++) {
      const p = { yaw: 90 * random() - 45, pitch: 60 * random() - 30, roll: 60 * random() - 30, forward: 0.04 * random() - 0.02 };
      const fraction = random();
      poseTransform(p, fraction, pivot, m);
      // A rotation: orthonormal rows, determinant 1.
      const row = (i: number) => [m[3 * i], m[3 * i + 1], m[3 * i + 2]];
      const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) expect(dot(row(i), row(j))).toBeCloseTo(i === j ? 1 : 0, 12);
      const point = [random() - 0.5, random(), random() - 0.5] as const;
      const there = [0, 0, 0];
      transformPoint(m, ...point, there);
      const back = [0, 0, 0];
      inverseTransformPoint(m, there[0], there[1], there[2], back);
      for (let i = 0; i < 3; i++) expect(back[i]).toBeCloseTo(point[i], 12);
      // With no shift, the pivot stays where it is.
      const still = moved({ ...p, forward: 0 }, pivot, pivot, fraction);
      for (let i = 0; i < 3; i++) expect(still[i]).toBeCloseTo(pivot[i], 12);
    }
    expect(moved(pose({ AU51: 1 }), [0.3, 0.2, 0.1], pivot, 0)).toEqual([0.3, 0.2, 0.1]);
  });
});
