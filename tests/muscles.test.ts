import { Euler, Matrix4 } from 'three';
import { describe, expect, it } from 'vitest';
import { mulberry32 } from '../src/core/random';
import { DEGREES, eulerMatrix, rotateAboutAxis } from '../src/core/math3';
import { MuscleField } from '../src/core/rig/muscle-fields';
import { validateMuscle } from '../src/core/rig/muscle-validation';
import { MuscleRig, computeMuscleTargets } from '../src/core/rig/muscles';
import type { MuscleInputs } from '../src/core/solver/muscle-inputs';
import type { JawMuscle, LidMuscle, LinearMuscle, Muscle, SphincterMuscle, Vec3 } from '../src/core/rig/rig-types';

/** A seeded generator of uniform numbers in [0, 1) (mulberry32), so every run sees the same points. */
const random = mulberry32;

/** n points uniform in the box lo..hi, seeded. */
function randomPoints(n: number, lo: Vec3, hi: Vec3, seed: number): Float32Array {
  const next = random(seed);
  const p = new Float32Array(3 * n);
  for (let i = 0; i < n; i++) for (let k = 0; k < 3; k++) p[3 * i + k] = lo[k] + (hi[k] - lo[k]) * next();
  return p;
}

/** Points from a to b, `step` apart. */
function line(a: Vec3, b: Vec3, step: number): Float32Array {
  const length = Math.hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  const count = Math.round(length / step) + 1;
  const p = new Float32Array(3 * count);
  for (let i = 0; i < count; i++) for (let k = 0; k < 3; k++) p[3 * i + k] = a[k] + ((b[k] - a[k]) * i) / (count - 1);
  return p;
}

function outputsFor(vertexCount: number): MuscleInputs {
  return {
    targets: new Float32Array(3 * vertexCount),
    weights: new Float32Array(vertexCount),
    normalWeights: new Float32Array(vertexCount),
  };
}

/** Largest change of the displacement (target - rest) between neighbouring points of a line. */
function largestJump(rest: Float32Array, targets: Float32Array): number {
  let jump = 0;
  for (let i = 3; i < rest.length; i += 3) {
    const d = Math.hypot(
      targets[i] - rest[i] - (targets[i - 3] - rest[i - 3]),
      targets[i + 1] - rest[i + 1] - (targets[i - 2] - rest[i - 2]),
      targets[i + 2] - rest[i + 2] - (targets[i - 1] - rest[i - 1]),
    );
    jump = Math.max(jump, d);
  }
  return jump;
}

/** Largest change of a field's displacement between neighbouring points of a line, and the largest displacement. */
function fieldJumps(field: MuscleField, c: number, points: Float32Array): { jump: number; largest: number } {
  const previous = [0, 0, 0];
  const out = [0, 0, 0];
  let jump = 0;
  let largest = 0;
  for (let i = 0; i < points.length; i += 3) {
    field.displace(c, points[i], points[i + 1], points[i + 2], out);
    if (i > 0) jump = Math.max(jump, Math.hypot(out[0] - previous[0], out[1] - previous[1], out[2] - previous[2]));
    largest = Math.max(largest, Math.hypot(out[0], out[1], out[2]));
    previous[0] = out[0];
    previous[1] = out[1];
    previous[2] = out[2];
  }
  return { jump, largest };
}

const sub = (a: ArrayLike<number>, b: ArrayLike<number>): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: ArrayLike<number>, b: ArrayLike<number>): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: ArrayLike<number>, b: ArrayLike<number>): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
const norm = (a: ArrayLike<number>): number => Math.hypot(a[0], a[1], a[2]);

// Origin at 0, pulling along -y; length 4 cm, so Rs = 2 cm and Rf = 4.8 cm.
const LINEAR: LinearMuscle = {
  name: 'test-linear',
  side: 'left',
  type: 'linear',
  origin: [0, 0, 0],
  insertion: [0, 0.04, 0],
  angle: 30,
  falloffStart: 0.5,
  falloffEnd: 1.2,
  strength: 0.5,
  normalWeight: 0.2,
};

const SPHINCTER: SphincterMuscle = {
  name: 'test-sphincter',
  side: 'mid',
  type: 'sphincter',
  center: [0.01, -0.02, 0.03],
  rotation: [0, 0, 0],
  radii: [0.03, 0.03, 0.02],
  innerRadii: [0.01, 0.01, 0.007],
  scale: [1, 1, 1],
  strength: 0.4,
  normalWeight: 0.1,
};

const LID: LidMuscle = {
  name: 'test-lid',
  side: 'left',
  type: 'lid',
  center: [0.03, 0.01, 0.02],
  rotation: [10, 20, -5],
  radii: [0.015, 0.012, 0.012],
  maxAngle: 40,
  innerFraction: 0.6,
};

// Joint at the back face's centre: (0, -0.05, -0.01).
const JAW: JawMuscle = {
  name: 'test-jaw',
  side: 'mid',
  type: 'jaw',
  center: [0, -0.05, 0.04],
  rotation: [0, 0, 0],
  size: [0.1, 0.06, 0.1],
  maxAngle: 20,
  curve: 0.3,
  fade: 0.01,
};

describe('math3', () => {
  it('builds R = Rz * Ry * Rx from XYZ Euler degrees, the matrix of three.js Euler order ZYX', () => {
    const next = random(1);
    const m = new Float64Array(9);
    for (let trial = 0; trial < 20; trial++) {
      const r: Vec3 = [360 * next() - 180, 180 * next() - 90, 360 * next() - 180];
      eulerMatrix(r, m);
      const e = new Matrix4().makeRotationFromEuler(new Euler(r[0] * DEGREES, r[1] * DEGREES, r[2] * DEGREES, 'ZYX')).elements;
      // three.js stores column-major.
      const rowMajor = [e[0], e[4], e[8], e[1], e[5], e[9], e[2], e[6], e[10]];
      for (let i = 0; i < 9; i++) expect(m[i]).toBeCloseTo(rowMajor[i], 12);
    }
    // A quarter turn about z alone takes the local x axis (first column) to the head's +y.
    eulerMatrix([0, 0, 90], m);
    expect([m[0], m[3], m[6]].map((v) => Math.round(v * 1e12) / 1e12 + 0)).toEqual([0, 1, 0]);
  });

  it('rotates about an axis through a point right-handedly, keeping the distance to the axis point', () => {
    const out = [0, 0, 0];
    // A quarter turn about +x through (0, 1, 0) takes (0, 2, 0) to (0, 1, 1).
    rotateAboutAxis(0, 2, 0, 0, 1, 0, 1, 0, 0, Math.PI / 2, out);
    expect(out[0]).toBeCloseTo(0, 14);
    expect(out[1]).toBeCloseTo(1, 14);
    expect(out[2]).toBeCloseTo(1, 14);
    rotateAboutAxis(0.3, -0.2, 0.5, 0.1, 0.1, 0.1, 0, 0.6, 0.8, 1.234, out);
    expect(norm(sub(out, [0.1, 0.1, 0.1]))).toBeCloseTo(norm([0.2, -0.3, 0.4]), 14);
  });
});

describe('linear muscle (Waters)', () => {
  const field = new MuscleField(LINEAR);
  const out = [0, 0, 0];

  it('is zero outside its zone: past Rf, outside the cone, behind the origin', () => {
    for (const p of [
      [0, 0.0481, 0],
      [0, 0.06, 0],
      [0.02 * Math.sin(31 * DEGREES), 0.02 * Math.cos(31 * DEGREES), 0],
      [0, 0.02 * Math.cos(31 * DEGREES), 0.02 * Math.sin(31 * DEGREES)],
      [0, -0.02, 0],
      [0.02, 0, 0],
    ]) {
      expect(field.displace(1, p[0], p[1], p[2], out)).toBe(0);
      expect(out).toEqual([0, 0, 0]);
    }
  });

  it('is zero at the bone and rises from it smoothly', () => {
    expect(field.displace(1, 0, 0, 0, out)).toBe(0);
    expect(out).toEqual([0, 0, 0]);
    field.displace(1, 0, 1e-4, 0, out);
    // R ~ (pi/2) D / Rs near the bone, so the pull is second order in D there.
    expect(norm(out)).toBeLessThan(0.5 * (Math.PI / 2) * (1e-4 / 0.02) * 1e-4 * 1.01);
  });

  it('has full falloff at Rs on the axis and its largest pull inside the zone, between Rs and Rf', () => {
    expect(field.displace(1, 0, 0.02, 0, out)).toBeCloseTo(1, 12);
    let best = 0;
    let bestD = 0;
    for (let D = 0; D <= 0.05; D += 0.0001) {
      field.displace(1, 0, D, 0, out);
      if (norm(out) > best) {
        best = norm(out);
        bestD = D;
      }
    }
    expect(bestD).toBeGreaterThanOrEqual(0.02);
    expect(bestD).toBeLessThan(0.048);
    // The whole pull at Rs on the axis: strength x D.
    field.displace(1, 0, 0.02, 0, out);
    expect(out[1]).toBeCloseTo(-0.5 * 0.02, 12);
  });

  it('pulls every point of its zone straight toward the origin by c K A R D', () => {
    const next = random(2);
    let inside = 0;
    for (let trial = 0; trial < 2000; trial++) {
      const p: Vec3 = [0.1 * next() - 0.05, 0.06 * next() - 0.005, 0.1 * next() - 0.05];
      const falloff = field.displace(0.7, p[0], p[1], p[2], out);
      if (falloff === 0) continue;
      inside++;
      const toOrigin = sub(LINEAR.origin, p);
      expect(norm(cross(out, toOrigin))).toBeLessThan(1e-12);
      expect(dot(out, toOrigin)).toBeGreaterThan(0);
      expect(norm(out)).toBeCloseTo(0.7 * 0.5 * falloff * norm(toOrigin), 12);
    }
    expect(inside).toBeGreaterThan(50);
  });

  it('is continuous across Rs, Rf and the cone edge', () => {
    const step = 1e-4;
    for (const [a, b] of [
      [
        [0, 0.001, 0],
        [0, 0.06, 0],
      ],
      [
        [-0.03, 0.03, 0.005],
        [0.03, 0.03, 0.005],
      ],
    ] as [Vec3, Vec3][]) {
      const { jump, largest } = fieldJumps(field, 1, line(a, b, step));
      expect(largest).toBeGreaterThan(0.005);
      // Slope at most about 2 (no step anywhere), and halving the spacing halves the largest jump.
      expect(jump).toBeLessThan(2 * step);
      expect(fieldJumps(field, 1, line(a, b, step / 2)).jump).toBeLessThan(0.6 * jump);
    }
  });
});

describe('sphincter muscle', () => {
  const field = new MuscleField(SPHINCTER);
  const c = SPHINCTER.center;
  const out = [0, 0, 0];

  it('is zero outside its ellipsoid and at its centre', () => {
    for (const p of [
      [c[0] + 0.0301, c[1], c[2]],
      [c[0], c[1] - 0.0301, c[2]],
      [c[0], c[1], c[2] + 0.0201],
      [c[0] + 0.022, c[1] + 0.022, c[2]],
    ]) {
      expect(field.displace(1, p[0], p[1], p[2], out)).toBe(0);
      expect(out).toEqual([0, 0, 0]);
    }
    expect(field.displace(1, c[0], c[1], c[2], out)).toBe(0);
    expect(out).toEqual([0, 0, 0]);
  });

  it('pulls toward the centre, fully at the inner surface, less toward the centre and the outer surface', () => {
    const next = random(3);
    for (let trial = 0; trial < 1000; trial++) {
      const p: Vec3 = [c[0] + 0.06 * next() - 0.03, c[1] + 0.06 * next() - 0.03, c[2] + 0.04 * next() - 0.02];
      if (field.displace(1, p[0], p[1], p[2], out) === 0) continue;
      const toCentre = sub(c, p);
      expect(norm(cross(out, toCentre))).toBeLessThan(1e-12);
      expect(dot(out, toCentre)).toBeGreaterThan(0);
    }
    // Along +x: inner surface at 1 cm, outer at 3 cm.
    expect(field.displace(1, c[0] + 0.01, c[1], c[2], out)).toBeCloseTo(1, 12);
    const atInner = norm(out);
    field.displace(1, c[0] + 0.002, c[1], c[2], out);
    expect(norm(out)).toBeLessThan(atInner);
    field.displace(1, c[0] + 0.0285, c[1], c[2], out);
    expect(norm(out)).toBeLessThan(atInner);
  });

  it('scales the pull per local axis: with scale.y > scale.x the vertical motion is larger', () => {
    const squint = new MuscleField({ ...SPHINCTER, scale: [0.5, 1.5, 1] });
    const side = [0, 0, 0];
    const above = [0, 0, 0];
    // Same normalised distance (the ellipsoid is round in xy), so the same falloff.
    const fSide = squint.displace(1, c[0] + 0.015, c[1], c[2], side);
    const fAbove = squint.displace(1, c[0], c[1] + 0.015, c[2], above);
    expect(fSide).toBeCloseTo(fAbove, 12);
    expect(Math.abs(above[1])).toBeCloseTo(3 * Math.abs(side[0]), 12);
    // On the diagonal, too, it moves more vertically than sideways.
    squint.displace(1, c[0] + 0.01, c[1] + 0.01, c[2], out);
    expect(Math.abs(out[1])).toBeGreaterThan(2.9 * Math.abs(out[0]));
  });

  it('pushes away from the center along an axis of negative scale (lips thrust forward in a pucker)', () => {
    const pucker = new MuscleField({ ...SPHINCTER, scale: [1, 1, -0.5] });
    // In front of the center and to its side: pulled in sideways, pushed out in front, half as much per metre.
    const f = pucker.displace(1, c[0] + 0.01, c[1], c[2] + 0.01, out);
    expect(f).toBeGreaterThan(0);
    expect(out[0]).toBeLessThan(0);
    expect(out[2]).toBeGreaterThan(0);
    expect(out[2]).toBeCloseTo(-0.5 * out[0], 12);
  });

  it('works in its turned frame: turning the muscle turns its field', () => {
    const plain = new MuscleField({ ...SPHINCTER, center: [0, 0, 0], scale: [0.5, 1.5, 1] });
    const rotation: Vec3 = [25, -40, 70];
    const turned = new MuscleField({ ...SPHINCTER, center: [0, 0, 0], scale: [0.5, 1.5, 1], rotation });
    const R = new Float64Array(9);
    eulerMatrix(rotation, R);
    const turn = (v: ArrayLike<number>): Vec3 => [
      R[0] * v[0] + R[1] * v[1] + R[2] * v[2],
      R[3] * v[0] + R[4] * v[1] + R[5] * v[2],
      R[6] * v[0] + R[7] * v[1] + R[8] * v[2],
    ];
    const next = random(4);
    const a = [0, 0, 0];
    const b = [0, 0, 0];
    for (let trial = 0; trial < 200; trial++) {
      const p: Vec3 = [0.05 * next() - 0.025, 0.05 * next() - 0.025, 0.03 * next() - 0.015];
      const q = turn(p);
      expect(turned.displace(1, q[0], q[1], q[2], b)).toBeCloseTo(plain.displace(1, p[0], p[1], p[2], a), 12);
      const expected = turn(a);
      for (let k = 0; k < 3; k++) expect(b[k]).toBeCloseTo(expected[k], 14);
    }
  });

  it('is continuous through the centre and across the inner and outer surfaces', () => {
    const step = 1e-4;
    const { jump, largest } = fieldJumps(
      field,
      1,
      line([c[0] - 0.035, c[1] + 0.004, c[2] + 0.002], [c[0] + 0.035, c[1] + 0.004, c[2] + 0.002], step),
    );
    expect(largest).toBeGreaterThan(0.003);
    expect(jump).toBeLessThan(2 * step);
    expect(
      fieldJumps(field, 1, line([c[0] - 0.035, c[1] + 0.004, c[2] + 0.002], [c[0] + 0.035, c[1] + 0.004, c[2] + 0.002], step / 2)).jump,
    ).toBeLessThan(0.6 * jump);
  });
});

describe('lid muscle (rotation)', () => {
  const field = new MuscleField(LID);
  const joint = field.joint()!;
  const axis = field.axis()!;
  const out = [0, 0, 0];

  /** Signed angle (degrees) by which p turned into p + d about the lid's axis through its joint. */
  function turnAngle(p: ArrayLike<number>, d: ArrayLike<number>): number {
    const w = sub(p, joint);
    const moved = [w[0] + d[0], w[1] + d[1], w[2] + d[2]];
    const a = sub(w, [axis[0] * dot(w, axis), axis[1] * dot(w, axis), axis[2] * dot(w, axis)]);
    const b = sub(moved, [axis[0] * dot(moved, axis), axis[1] * dot(moved, axis), axis[2] * dot(moved, axis)]);
    return Math.atan2(dot(cross(a, b), axis), dot(a, b)) / DEGREES;
  }

  it('puts its joint at the ellipsoid back (centre - radii.z along local z) and turns about local x', () => {
    const R = new Float64Array(9);
    eulerMatrix(LID.rotation, R);
    for (let k = 0; k < 3; k++) {
      expect(joint[k]).toBeCloseTo(LID.center[k] - 0.012 * R[3 * k + 2], 15);
      expect(axis[k]).toBeCloseTo(R[3 * k], 15);
    }
  });

  it('turns a point in the inner region by exactly c x maxAngle about the joint, keeping its radius', () => {
    const next = random(5);
    for (let trial = 0; trial < 50; trial++) {
      // Within 0.5 of the radii of the centre: inside the inner region (0.6).
      const p: Vec3 = [
        LID.center[0] + 0.004 * (next() - 0.5),
        LID.center[1] + 0.004 * (next() - 0.5),
        LID.center[2] + 0.004 * (next() - 0.5),
      ];
      const c = 0.2 + 0.8 * next();
      expect(field.displace(c, p[0], p[1], p[2], out)).toBe(1);
      expect(turnAngle(p, out)).toBeCloseTo(c * LID.maxAngle, 10);
      const moved = [p[0] + out[0], p[1] + out[1], p[2] + out[2]];
      expect(norm(sub(moved, joint))).toBeCloseTo(norm(sub(p, joint)), 14);
      expect(dot(sub(moved, joint), axis)).toBeCloseTo(dot(sub(p, joint), axis), 14);
    }
  });

  it('keeps the exact turn through the substeps of a rig when the skin stays in the inner region', () => {
    // The centre turns on a circle of radius radii.z about the joint; at 30 degrees it is still within 0.52 < 0.6.
    const rest = Float32Array.from(LID.center);
    const rig = new MuscleRig(rest, [LID]);
    const o = outputsFor(1);
    rig.compute([0.75], o);
    const d = sub(o.targets, rest);
    expect(turnAngle(rest, d)).toBeCloseTo(30, 4);
    expect(norm(sub(o.targets, joint))).toBeCloseTo(norm(sub(rest, joint)), 7);
    expect(o.weights[0]).toBe(1);
    expect(o.normalWeights[0]).toBe(1);
  });

  it('carries its skin the whole turn even where the turn takes it out of the ellipsoid (its zone is asked at rest)', () => {
    // A point in the inner region, 9 mm along local z from the joint: 90 degrees swing it out of the ellipsoid.
    const R = new Float64Array(9);
    eulerMatrix(LID.rotation, R);
    const rest = Float32Array.from([0, 1, 2].map((k) => joint[k] + 0.009 * R[3 * k + 2]));
    const wide: LidMuscle = { ...LID, maxAngle: 90 };
    const o = outputsFor(1);
    new MuscleRig(rest, [wide]).compute([1], o);
    const moved = sub(o.targets, rest);
    const wideField = new MuscleField(wide);
    expect(wideField.displace(1, o.targets[0], o.targets[1], o.targets[2], out)).toBe(0); // outside now
    expect(turnAngle(rest, moved)).toBeCloseTo(90, 4);
  });

  it('is zero outside its ellipsoid and fades continuously to it', () => {
    const R = new Float64Array(9);
    eulerMatrix(LID.rotation, R);
    // Along the local y axis through the centre: inner region to 7.2 mm, surface at 12 mm.
    const along = (s: number): Vec3 => [LID.center[0] + s * R[1], LID.center[1] + s * R[4], LID.center[2] + s * R[7]];
    let p = along(0.0121);
    expect(field.displace(1, p[0], p[1], p[2], out)).toBe(0);
    expect(out).toEqual([0, 0, 0]);
    p = along(0.0119);
    expect(field.displace(1, p[0], p[1], p[2], out)).toBeGreaterThan(0);
    const step = 1e-4;
    const points = line(along(-0.02), along(0.02), step);
    const { jump, largest } = fieldJumps(field, 1, points);
    expect(largest).toBeGreaterThan(0.005);
    // The fade's slope: 0.7 rad x (pi/2) / (0.4 x 12 mm) x 17 mm from the joint, about 4; a step would be millimetres.
    expect(jump).toBeLessThan(5 * step);
    expect(fieldJumps(field, 1, line(along(-0.02), along(0.02), step / 2)).jump).toBeLessThan(0.6 * jump);
  });
});

describe('jaw muscle (rotation)', () => {
  const field = new MuscleField(JAW);
  const joint = field.joint()!;
  const out = [0, 0, 0];

  /** Angle (degrees) by which p turned about the x axis through the joint. */
  function turnAngle(p: Vec3, d: ArrayLike<number>): number {
    const a = Math.atan2(p[1] - joint[1], p[2] - joint[2]);
    const b = Math.atan2(p[1] + d[1] - joint[1], p[2] + d[2] - joint[2]);
    return (a - b) / DEGREES;
  }

  it('hinges at the centre of the back face', () => {
    [0, -0.05, -0.01].forEach((x, k) => expect(joint[k]).toBeCloseTo(x, 15));
    [1, 0, 0].forEach((x, k) => expect(field.axis()![k]).toBeCloseTo(x, 15));
  });

  it('turns about the hinge by c x maxAngle x (1 + curve (1 - (2x / size.x)^2)): the centre line opens further', () => {
    const c = 0.8;
    const middle: Vec3 = [0, -0.05, 0.07];
    const side: Vec3 = [0.03, -0.05, 0.07];
    expect(field.displace(c, ...middle, out)).toBe(1);
    // Positive angles open the jaw: the chin, in front of the hinge, moves down.
    expect(out[1]).toBeLessThan(0);
    expect(out[0]).toBe(0);
    const middleAngle = turnAngle(middle, out);
    const middleMove = norm(out);
    expect(middleAngle).toBeCloseTo(c * 20 * 1.3, 10);
    expect(field.displace(c, ...side, out)).toBe(1);
    expect(turnAngle(side, out)).toBeCloseTo(c * 20 * (1 + 0.3 * (1 - 0.6 * 0.6)), 10);
    expect(middleMove).toBeGreaterThan(norm(out) * 1.05);
    // Without the curve, the middle and the side turn alike.
    const straight = new MuscleField({ ...JAW, curve: 0 });
    straight.displace(c, ...middle, out);
    expect(turnAngle(middle, out)).toBeCloseTo(c * 20, 10);
    straight.displace(c, ...side, out);
    expect(turnAngle(side, out)).toBeCloseTo(c * 20, 10);
  });

  it('is zero outside its box', () => {
    for (const p of [
      [0.0501, -0.05, 0.04],
      [0, -0.0801, 0.04],
      [0, -0.019, 0.04],
      [0, -0.05, 0.0901],
      [0, -0.05, -0.0101],
    ]) {
      expect(field.displace(1, p[0], p[1], p[2], out)).toBe(0);
      expect(out).toEqual([0, 0, 0]);
    }
  });

  it('fades continuously to zero at its faces', () => {
    const step = 1e-4;
    for (const [a, b] of [
      [
        [0.02, -0.06, 0.07],
        [0.07, -0.06, 0.07],
      ],
      [
        [0.01, -0.1, 0.07],
        [0.01, -0.01, 0.07],
      ],
      [
        [0.01, -0.06, 0.05],
        [0.01, -0.06, 0.11],
      ],
    ] as [Vec3, Vec3][]) {
      const { jump, largest } = fieldJumps(field, 1, line(a, b, step));
      expect(largest).toBeGreaterThan(0.01);
      // The fade's slope is pi/2 per `fade` (1 cm) times a turn of a few centimetres; a step would be ~1 cm.
      expect(jump).toBeLessThan(10 * step);
      expect(fieldJumps(field, 1, line(a, b, step / 2)).jump).toBeLessThan(0.6 * jump);
    }
  });
});

describe('jaw muscle lip fade', () => {
  it('fades over lipFade below its top face and over fade above its bottom face', () => {
    const jaw = new MuscleField({ ...JAW, lipFade: 0.002 });
    const plain = new MuscleField(JAW);
    const out = [0, 0, 0];
    // Top face at y = -0.02, bottom at -0.08 (centre -0.05, height 6 cm); x, z well inside.
    expect(jaw.displace(1, 0, -0.0225, 0.04, out)).toBe(1); // 2.5 mm under the top: past the lip fade
    expect(plain.displace(1, 0, -0.0225, 0.04, out)).toBeLessThan(0.5); // within the 1 cm fade
    expect(jaw.displace(1, 0, -0.0775, 0.04, out)).toBeCloseTo(plain.displace(1, 0, -0.0775, 0.04, out), 12);
    expect(jaw.displace(1, 0, -0.0775, 0.04, out)).toBeLessThan(0.5);
  });

  it('rejects a lipFade that is not positive, naming it', () => {
    expect(() => validateMuscle({ ...JAW, lipFade: 0 })).toThrow(
      'muscle test-jaw: lipFade: expected a positive length of at most 10 m, got 0',
    );
  });
});

describe('combining muscles into solver inputs', () => {
  it("gives the rotation muscles' share of each vertex's hold as its turn weight, none for a linear muscle", () => {
    // Points over the lid's and a linear muscle's zones at once; the linear one alone holds most of them.
    const rest = randomPoints(4000, [-0.03, -0.03, -0.01], [0.06, 0.05, 0.04], 11);
    const n = rest.length / 3;
    const o = { ...outputsFor(n), turnWeights: new Float32Array(n).fill(0.5) };
    new MuscleRig(rest, [LINEAR, LID]).compute([1, 1], o);
    const alone = outputsFor(n);
    new MuscleRig(rest, [LID]).compute([1], alone);
    const linearOnly = { ...outputsFor(n), turnWeights: new Float32Array(n).fill(0.5) };
    new MuscleRig(rest, [LINEAR]).compute([1], linearOnly);
    let turned = 0;
    for (let v = 0; v < n; v++) {
      // The lid's hold, whatever else holds the vertex; nothing where the lid does not reach.
      expect(o.turnWeights[v]).toBeCloseTo(alone.weights[v], 6);
      expect(linearOnly.turnWeights[v]).toBe(0);
      if (o.turnWeights[v] > 0) turned++;
    }
    expect(turned).toBeGreaterThan(20);
  });

  // Two linear muscles whose zones overlap, pulling toward origins 3 cm apart.
  const A: LinearMuscle = { ...LINEAR, name: 'overlap-a' };
  const B: LinearMuscle = {
    ...LINEAR,
    name: 'overlap-b',
    origin: [0.03, 0, 0],
    insertion: [0.015, 0.035, 0.005],
    angle: 40,
    strength: 0.6,
    normalWeight: 0.5,
  };

  it('gives a continuous field where two linear muscles overlap (0.1 mm apart: no jump)', () => {
    const step = 1e-4;
    for (const [a, b] of [
      [
        [-0.03, 0.03, 0.001],
        [0.06, 0.03, 0.001],
      ],
      [
        [0.012, -0.005, 0.001],
        [0.012, 0.06, 0.001],
      ],
    ] as [Vec3, Vec3][]) {
      const rest = line(a, b, step);
      const o = outputsFor(rest.length / 3);
      const held = computeMuscleTargets(rest, [A, B], [1, 1], o);
      expect(held).toBeGreaterThan(100);
      const jump = largestJump(rest, o.targets);
      let largest = 0;
      for (let i = 0; i < rest.length; i++) largest = Math.max(largest, Math.abs(o.targets[i] - rest[i]));
      expect(largest).toBeGreaterThan(0.005);
      // Full contraction moves skin by up to centimetres; a jump at a zone edge would be of that size, while the
      // fields' slopes (about 2 each, see above) allow a few tenths of a millimetre.
      expect(jump).toBeLessThan(5 * step);
      let weightJump = 0;
      for (let v = 1; v < o.weights.length; v++)
        weightJump = Math.max(weightJump, Math.abs(o.weights[v] - o.weights[v - 1]), Math.abs(o.normalWeights[v] - o.normalWeights[v - 1]));
      expect(weightJump).toBeLessThan(0.02);
      // Continuity, not just a small slope: halving the spacing halves the largest jump.
      const fine = line(a, b, step / 2);
      const f = outputsFor(fine.length / 3);
      computeMuscleTargets(fine, [A, B], [1, 1], f);
      expect(largestJump(fine, f.targets)).toBeLessThan(0.6 * jump);
    }
  });

  it('gives targets = rest and weights 0 for contraction 0, also after a contraction', () => {
    const rest = randomPoints(2000, [-0.05, -0.05, -0.05], [0.05, 0.05, 0.05], 6);
    const rig = new MuscleRig(rest, [A, B, SPHINCTER, LID, JAW]);
    const o = outputsFor(2000);
    expect(rig.compute([1, 0.5, 1, 1, 1], o)).toBeGreaterThan(0);
    expect(rig.compute([0, 0, 0, 0, 0], o)).toBe(0);
    expect(Array.from(o.targets)).toEqual(Array.from(rest));
    expect(o.weights.every((w) => w === 0)).toBe(true);
    expect(o.normalWeights.every((w) => w === 0)).toBe(true);
  });

  it('sums the active muscles falloffs at rest into the weights, capped at 1; inactive muscles take no part', () => {
    const rest = randomPoints(3000, [-0.05, -0.05, -0.05], [0.06, 0.06, 0.06], 7);
    const muscles: Muscle[] = [A, B, SPHINCTER, LID, JAW];
    const fields = muscles.map((m) => new MuscleField(m));
    const rig = new MuscleRig(rest, muscles);
    const o = outputsFor(3000);
    const contractions = [0.9, 0.5, 0, 0.3, 0.2];
    rig.compute(contractions, o);
    const out = [0, 0, 0];
    let held = 0;
    for (let v = 0; v < 3000; v++) {
      let weight = 0;
      let normalWeight = 0;
      muscles.forEach((m, i) => {
        if (contractions[i] === 0) return;
        const falloff = fields[i].displace(1, rest[3 * v], rest[3 * v + 1], rest[3 * v + 2], out);
        weight += falloff;
        normalWeight += falloff * (m.type === 'linear' || m.type === 'sphincter' ? m.normalWeight : 1);
      });
      expect(o.weights[v]).toBeCloseTo(Math.min(1, weight), 6);
      expect(o.normalWeights[v]).toBeCloseTo(Math.min(1, normalWeight), 6);
      if (weight > 0) held++;
      else for (let k = 0; k < 3; k++) expect(o.targets[3 * v + k]).toBe(rest[3 * v + k]);
    }
    expect(rig.lastHeld).toBe(held);
    expect(held).toBeGreaterThan(100);
    // The idle sphincter changes nothing: the same as a rig without it.
    const without = outputsFor(3000);
    new MuscleRig(rest, [A, B, LID, JAW]).compute([0.9, 0.5, 0.3, 0.2], without);
    expect(Array.from(o.targets)).toEqual(Array.from(without.targets));
    expect(Array.from(o.weights)).toEqual(Array.from(without.weights));
  });

  it('fades a muscle hold in over the first holdFadeIn of contraction, so starting to contract moves nothing abruptly', () => {
    const rest = randomPoints(500, [-0.02, 0, -0.02], [0.02, 0.05, 0.02], 8);
    const rig = new MuscleRig(rest, [A]);
    const full = outputsFor(500);
    const small = outputsFor(500);
    rig.compute([0.5], full);
    rig.compute([0.02], small);
    for (let v = 0; v < 500; v++) expect(small.weights[v]).toBeCloseTo(0.2 * full.weights[v], 6);
    const literal = outputsFor(500);
    new MuscleRig(rest, [A], { holdFadeIn: 0 }).compute([0.02], literal);
    for (let v = 0; v < 500; v++) expect(literal.weights[v]).toBeCloseTo(full.weights[v], 6);
  });

  it('integrates in substeps with the fields where the skin is now: 1 substep is the plain sum, more converge', () => {
    const rest = randomPoints(1000, [-0.02, -0.005, -0.01], [0.05, 0.06, 0.01], 9);
    const fields = [new MuscleField(A), new MuscleField(B)];
    const one = outputsFor(1000);
    new MuscleRig(rest, [A, B], { substeps: 1 }).compute([1, 1], one);
    const out = [0, 0, 0];
    for (let v = 0; v < 1000; v++) {
      const sum = [rest[3 * v], rest[3 * v + 1], rest[3 * v + 2]];
      for (const f of fields) {
        f.displace(1, rest[3 * v], rest[3 * v + 1], rest[3 * v + 2], out);
        for (let k = 0; k < 3; k++) sum[k] += out[k];
      }
      for (let k = 0; k < 3; k++) expect(one.targets[3 * v + k]).toBeCloseTo(sum[k], 6);
    }
    const error = (substeps: number): number => {
      const o = outputsFor(1000);
      const reference = outputsFor(1000);
      new MuscleRig(rest, [A, B], { substeps }).compute([1, 1], o);
      new MuscleRig(rest, [A, B], { substeps: 64 }).compute([1, 1], reference);
      let e = 0;
      for (let i = 0; i < o.targets.length; i++) e = Math.max(e, Math.abs(o.targets[i] - reference.targets[i]));
      return e;
    };
    // First-order integration: the error falls with the number of substeps.
    const e2 = error(2);
    const e8 = error(8);
    expect(e8).toBeLessThan(0.5 * e2);
    expect(e8).toBeLessThan(0.001);
  });

  it('moves targets only slightly when a contraction or a muscle changes slightly', () => {
    const rest = randomPoints(5000, [-0.03, -0.01, -0.02], [0.06, 0.06, 0.02], 10);
    const a = outputsFor(5000);
    const b = outputsFor(5000);
    const rig = new MuscleRig(rest, [A, B, SPHINCTER, JAW]);
    rig.compute([0.6, 0.6, 0.6, 0.6], a);
    rig.compute([0.6001, 0.6, 0.6001, 0.6001], b);
    const largestDifference = (): number => {
      let d = 0;
      for (let i = 0; i < a.targets.length; i++) d = Math.max(d, Math.abs(a.targets[i] - b.targets[i]));
      return d;
    };
    expect(largestDifference()).toBeLessThan(1e-5);
    // Moving B's insertion and the jaw's centre by 10 micrometres.
    rig.setMuscle(1, { ...B, insertion: [0.01501, 0.035, 0.005] });
    rig.setMuscle(3, { ...JAW, center: [0, -0.04999, 0.04] });
    rig.compute([0.6, 0.6, 0.6, 0.6], b);
    expect(largestDifference()).toBeLessThan(1e-4);
  });

  it('chooses candidates from rest geometry with a margin, so a rig gives the same targets at every mesh resolution', () => {
    // A fine grid with 1 mm spacing and a coarse one with 2 mm that shares every other point.
    const grid = (spacing: number): Float32Array => {
      const count = Math.round(0.12 / (spacing * 0.001)) + 1;
      const p = new Float32Array(3 * count * count);
      for (let j = 0; j < count; j++)
        for (let i = 0; i < count; i++) p.set([(i * spacing) / 1000 - 0.05, (j * spacing) / 1000 - 0.06, 0.004], 3 * (j * count + i));
      return p;
    };
    const fine = grid(1);
    const coarse = grid(2);
    const muscles: Muscle[] = [A, B, { ...SPHINCTER, center: [0.01, -0.005, 0.01] }, JAW];
    const fineRig = new MuscleRig(fine, muscles);
    const coarseRig = new MuscleRig(coarse, muscles);
    const fo = outputsFor(fine.length / 3);
    const co = outputsFor(coarse.length / 3);
    fineRig.compute([0.8, 0.7, 0.5, 0.6], fo);
    coarseRig.compute([0.8, 0.7, 0.5, 0.6], co);
    const fineCount = Math.round(Math.sqrt(fine.length / 3));
    const coarseCount = Math.round(Math.sqrt(coarse.length / 3));
    for (let j = 0; j < coarseCount; j++) {
      for (let i = 0; i < coarseCount; i++) {
        const c = j * coarseCount + i;
        const f = 2 * j * fineCount + 2 * i;
        expect(fine[3 * f]).toBe(coarse[3 * c]);
        for (let k = 0; k < 3; k++) expect(fo.targets[3 * f + k]).toBe(co.targets[3 * c + k]);
        expect(fo.weights[f]).toBe(co.weights[c]);
      }
    }
    // About four times as many candidates on the grid with twice the resolution.
    for (let m = 0; m < muscles.length; m++) {
      expect(coarseRig.candidateCounts[m]).toBeGreaterThan(50);
      const ratio = fineRig.candidateCounts[m] / coarseRig.candidateCounts[m];
      expect(ratio).toBeGreaterThan(3.4);
      expect(ratio).toBeLessThan(4.6);
    }
    expect(fineRig.candidateReport().map((r) => r.name)).toEqual(muscles.map((m) => m.name));
  });

  it('gives the same targets whatever the candidate margin: skin that slides farther meets every active muscle', () => {
    const rest = randomPoints(4000, [-0.03, -0.01, -0.02], [0.06, 0.06, 0.02], 15);
    const muscles: Muscle[] = [A, B, SPHINCTER, LID, JAW];
    const contractions = [1, 1, 0.8, 0.6, 0.7];
    const results = [0, 0.005, 1].map((margin) => {
      const rig = new MuscleRig(rest, muscles, { margin });
      const o = outputsFor(4000);
      rig.compute(contractions, o);
      return { o, rig };
    });
    // Skin slid farther than the default margin, so the slower path was taken too.
    expect(results[1].rig.lastLargestMove).toBeGreaterThan(0.005);
    for (const { o } of results.slice(1)) {
      expect(Array.from(o.targets)).toEqual(Array.from(results[0].o.targets));
      expect(Array.from(o.weights)).toEqual(Array.from(results[0].o.weights));
    }
    // A margin of 1 m makes every vertex a candidate of every muscle.
    expect(Array.from(results[2].rig.candidateCounts)).toEqual(muscles.map(() => 4000));
  });

  it('keeps every vertex of a zone among the candidates, and none far outside it', () => {
    const rest = randomPoints(20000, [-0.08, -0.1, -0.05], [0.08, 0.06, 0.1], 11);
    const muscles: Muscle[] = [A, B, SPHINCTER, LID, JAW];
    const rig = new MuscleRig(rest, muscles, { margin: 0.002 });
    const out = [0, 0, 0];
    muscles.forEach((m, i) => {
      const field = new MuscleField(m);
      const candidate = new Uint8Array(20000);
      for (const v of rig.candidates(i)) candidate[v] = 1;
      let inZone = 0;
      for (let v = 0; v < 20000; v++) {
        const x = rest[3 * v];
        const y = rest[3 * v + 1];
        const z = rest[3 * v + 2];
        if (field.displace(1, x, y, z, out) > 0) {
          inZone++;
          expect(candidate[v]).toBe(1);
        }
        // Nothing farther than the margin from the zone: no point within 2.5 mm of this one is in the zone.
        if (candidate[v] === 1 && m.type === 'jaw') {
          const g = [0.05 + 0.0025, 0.03 + 0.0025, 0.05 + 0.0025];
          const q = sub([x, y, z], m.center);
          for (let k = 0; k < 3; k++) expect(Math.abs(q[k])).toBeLessThanOrEqual(g[k]);
        }
      }
      expect(inZone).toBeGreaterThan(20);
      expect(rig.candidateCounts[i]).toBeLessThan(3 * inZone);
    });
  });

  it('is deterministic', () => {
    const rest = randomPoints(5000, [-0.06, -0.08, -0.03], [0.06, 0.06, 0.09], 12);
    const muscles: Muscle[] = [A, B, SPHINCTER, LID, JAW];
    const a = outputsFor(5000);
    const b = outputsFor(5000);
    new MuscleRig(rest, muscles).compute([0.3, 0.8, 0.6, 0.4, 0.9], a);
    const rig = new MuscleRig(rest, muscles);
    rig.compute([1, 1, 1, 1, 1], b);
    rig.compute([0.3, 0.8, 0.6, 0.4, 0.9], b);
    expect(Buffer.from(b.targets.buffer).equals(Buffer.from(a.targets.buffer))).toBe(true);
    expect(Buffer.from(b.weights.buffer).equals(Buffer.from(a.weights.buffer))).toBe(true);
    expect(Buffer.from(b.normalWeights.buffer).equals(Buffer.from(a.normalWeights.buffer))).toBe(true);
  });

  it('computes 68k points again and again without allocating (no typed array is made) and with the same result', () => {
    const n = 68_277;
    const rest = randomPoints(n, [-0.09, -0.13, -0.06], [0.09, 0.12, 0.12], 13);
    const muscles: Muscle[] = [A, B, SPHINCTER, LID, JAW];
    const rig = new MuscleRig(rest, muscles);
    const o = outputsFor(n);
    const contractions = new Float32Array([0.7, 0.4, 0.5, 0.3, 0.6]);
    rig.compute(contractions, o);
    const first = Float32Array.from(o.targets);
    const firstWeights = Float32Array.from(o.weights);
    for (let m = 0; m < muscles.length; m++) {
      expect(rig.candidateCounts[m]).toBeGreaterThan(0);
      expect(rig.candidateCounts[m]).toBeLessThan(n);
    }
    expect(rig.lastReached).toBeGreaterThan(1000);

    // Count typed arrays constructed during compute() by swapping the global constructors for counting subclasses.
    const names = ['Float32Array', 'Float64Array', 'Uint32Array', 'Uint8Array', 'Int32Array', 'Array'] as const;
    const globals = globalThis as unknown as Record<string, unknown>;
    const originals = names.map((name) => globals[name]);
    let made = 0;
    names.forEach((name, i) => {
      const Base = originals[i] as new (...args: unknown[]) => object;
      globals[name] = class extends Base {
        constructor(...args: unknown[]) {
          super(...args);
          made++;
        }
      };
    });
    try {
      for (let call = 0; call < 30; call++) rig.compute(contractions, o);
    } finally {
      names.forEach((name, i) => (globals[name] = originals[i]));
    }
    expect(made).toBe(0);
    expect(Array.from(o.targets)).toEqual(Array.from(first));
    expect(Array.from(o.weights)).toEqual(Array.from(firstWeights));
  });
});

describe('runtime checks', () => {
  const rest = randomPoints(200, [-0.03, -0.01, -0.03], [0.03, 0.05, 0.03], 14);

  it('clamps contractions to 0..1', () => {
    const rig = new MuscleRig(rest, [LINEAR, SPHINCTER]);
    const a = outputsFor(200);
    const b = outputsFor(200);
    rig.compute([1.5, -0.2], a);
    rig.compute([1, 0], b);
    expect(Array.from(a.targets)).toEqual(Array.from(b.targets));
    expect(Array.from(a.weights)).toEqual(Array.from(b.weights));
  });

  it('rejects a non-finite contraction naming its muscle, and writes nothing', () => {
    const rig = new MuscleRig(rest, [LINEAR, SPHINCTER]);
    const o = outputsFor(200);
    rig.compute([1, 1], o);
    const before = Float32Array.from(o.targets);
    const weightsBefore = Float32Array.from(o.weights);
    expect(() => rig.compute([0.5, NaN], o)).toThrow('muscle test-sphincter: contraction must be a finite number, got NaN');
    expect(() => rig.compute([Infinity, 0], o)).toThrow('muscle test-linear: contraction must be a finite number, got Infinity');
    expect(() => rig.compute([0.5], o)).toThrow('contractions: the rig has 2 muscles, got 1 contractions');
    expect(() => rig.compute([0.5, 0.5], outputsFor(199))).toThrow(/muscle outputs must hold 200 vertices/);
    expect(Array.from(o.targets)).toEqual(Array.from(before));
    expect(Array.from(o.weights)).toEqual(Array.from(weightsBefore));
  });

  it('rejects muscles whose field would be undefined, naming them', () => {
    expect(() => validateMuscle({ ...SPHINCTER, innerRadii: [0.01, 0.031, 0.007] })).toThrow(
      'muscle test-sphincter: innerRadii[1]: expected at most radii[1] (0.03), got 0.031',
    );
    expect(() => validateMuscle({ ...SPHINCTER, innerRadii: [0.01, 0.01, 0.02] })).not.toThrow();
    expect(() => validateMuscle({ ...LINEAR, falloffStart: 1.2 })).toThrow(
      'muscle test-linear: falloffEnd: expected more than falloffStart (1.2), got 1.2',
    );
    expect(() => validateMuscle({ ...LINEAR, insertion: [0, 0, 0] })).toThrow(
      'muscle test-linear: insertion: expected a point apart from the origin, got the same point',
    );
    expect(() => validateMuscle({ ...LINEAR, origin: [0, NaN, 0] })).toThrow(
      'muscle test-linear: origin[1]: expected a coordinate within ±10 m, got NaN',
    );
    expect(() => validateMuscle({ ...LID, innerFraction: 1 })).toThrow(
      'muscle test-lid: innerFraction: expected a number from 0 to below 1, got 1',
    );
    expect(() => validateMuscle({ ...JAW, fade: 0 })).toThrow('muscle test-jaw: fade: expected a positive length of at most 10 m, got 0');
    expect(() => new MuscleRig(rest, [LINEAR, { ...JAW, size: [0.1, -0.06, 0.1] }])).toThrow(
      'muscle test-jaw: size[1]: expected a positive length of at most 10 m, got -0.06',
    );
    expect(() => new MuscleRig(rest, [LINEAR], { substeps: 0 })).toThrow(/substeps/);
    const rig = new MuscleRig(rest, [LINEAR]);
    expect(() => rig.setMuscle(0, { ...LINEAR, angle: 120 })).toThrow(
      'muscle test-linear: angle: expected an angle from 0 to 90 degrees, got 120',
    );
    expect(rig.muscles[0]).toBe(LINEAR);
  });
});

describe('jaw muscle with an explicit hinge', () => {
  it('turns its skin about the given joint, not the box, so the chin moves down and back on an arc', () => {
    const jaw: JawMuscle = {
      name: 'jaw',
      side: 'mid',
      type: 'jaw',
      center: [0, 0.63, 0.12],
      rotation: [0, 0, 0],
      size: [0.13, 0.05, 0.11],
      joint: [0, 0.69, 0.065],
      maxAngle: 20,
      curve: 0,
      fade: 0.002,
    };
    const field = new MuscleField(jaw);
    expect(field.joint()).toEqual([0, 0.69, 0.065]);
    const chin = [0.03, 0.62, 0.14];
    const d = [0, 0, 0];
    field.displace(1, chin[0], chin[1], chin[2], d);
    const moved = chin.map((c, k) => c + d[k]);
    const radius = (p: number[]) => Math.hypot(p[1] - 0.69, p[2] - 0.065);
    expect(radius(moved)).toBeCloseTo(radius(chin), 9);
    expect(moved[0]).toBeCloseTo(chin[0], 12);
    const angle = (p: number[]) => Math.atan2(p[1] - 0.69, p[2] - 0.065);
    expect((angle(chin) - angle(moved)) * (180 / Math.PI)).toBeCloseTo(20, 6);
    expect(d[1]).toBeLessThan(0); // down
    expect(d[2]).toBeLessThan(0); // and back
  });
});
