import { describe, expect, it } from 'vitest';
import { computeMuscleTargets } from '../src/core/rig/muscles';
import { validateMuscle } from '../src/core/rig/muscle-validation';
import type { LinearMuscle, SphincterMuscle } from '../src/core/rig/rig-types';

/** A flat sheet of skin in the z = 0 plane, `step` apart, over x, y in -0.04..0.04. */
function sheet(step: number): Float32Array {
  const p: number[] = [];
  const n = Math.round(0.08 / step);
  for (let i = 0; i <= n; i++) for (let j = 0; j <= n; j++) p.push(-0.04 + i * step, -0.04 + j * step, 0);
  return Float32Array.from(p);
}

function solve(rest: Float32Array, muscle: LinearMuscle | SphincterMuscle) {
  const n = rest.length / 3;
  const out = { targets: new Float32Array(3 * n), weights: new Float32Array(n), normalWeights: new Float32Array(n) };
  computeMuscleTargets(rest, [muscle], [1], out);
  return out;
}

/** The vertex of `rest` at (x, y, 0). */
function at(rest: Float32Array, x: number, y: number): number {
  for (let v = 0; v < rest.length / 3; v++) if (Math.abs(rest[3 * v] - x) < 1e-6 && Math.abs(rest[3 * v + 1] - y) < 1e-6) return v;
  throw new Error(`no vertex at ${x}, ${y}`);
}

const muscle: LinearMuscle = {
  name: 'test',
  side: 'mid',
  type: 'linear',
  origin: [0, 0.03, 0],
  insertion: [0, 0, 0],
  angle: 20,
  falloffStart: 0.8,
  falloffEnd: 1.3,
  strength: 0.3,
  normalWeight: 0.2,
};

describe('a muscle brush (rest-space spheres)', () => {
  it('removes skin inside a remove sphere and leaves the rest of the zone as it was', () => {
    const rest = sheet(0.002);
    const plain = solve(rest, muscle);
    const removed = solve(rest, { ...muscle, brush: { add: [], remove: [[0, 0.004, 0, 0.006]] } });
    const inside = at(rest, 0, 0.004);
    expect(plain.weights[inside]).toBeGreaterThan(0.3);
    expect(removed.weights[inside]).toBe(0);
    expect(Array.from(removed.targets.subarray(3 * inside, 3 * inside + 3))).toEqual(Array.from(rest.subarray(3 * inside, 3 * inside + 3)));
    // Farther than the sphere: untouched.
    const outside = at(rest, 0, 0.016);
    expect(plain.weights[outside]).toBeGreaterThan(0);
    expect(removed.weights[outside]).toBe(plain.weights[outside]);
    expect(removed.targets[3 * outside + 1]).toBe(plain.targets[3 * outside + 1]);
  });

  it('adds skin outside the zone, pulled toward the origin as the muscle pulls, the same at two resolutions', () => {
    const brush = { add: [[0.02, 0, 0, 0.008]], remove: [] } as LinearMuscle['brush'];
    const results = [0.002, 0.001].map((step) => {
      const rest = sheet(step);
      const plain = solve(rest, muscle);
      const added = solve(rest, { ...muscle, brush });
      const v = at(rest, 0.02, 0);
      return { plain: plain.weights[v], weight: added.weights[v], target: Array.from(added.targets.subarray(3 * v, 3 * v + 3)) };
    });
    for (const r of results) {
      expect(r.plain).toBe(0);
      expect(r.weight).toBe(1);
      // Toward the origin (0, 0.03, 0): 8 substeps each take the strength's eighth of what is left (full falloff).
      const left = (1 - 0.3 / 8) ** 8;
      expect(r.target[0]).toBeCloseTo(0.02 * left, 6);
      expect(r.target[1]).toBeCloseTo(0.03 * (1 - left), 6);
    }
    expect(results[1].target).toEqual(results[0].target);
  });

  it('works for a sphincter too, and refuses a brush that is not spheres', () => {
    const rest = sheet(0.002);
    const ring: SphincterMuscle = {
      name: 'r',
      side: 'mid',
      type: 'sphincter',
      center: [0, 0, 0],
      rotation: [0, 0, 0],
      radii: [0.01, 0.01, 0.01],
      innerRadii: [0.005, 0.005, 0.005],
      scale: [1, 1, 0],
      strength: 0.5,
      normalWeight: 0.2,
    };
    const v = at(rest, 0.02, 0);
    expect(solve(rest, ring).weights[v]).toBe(0);
    const added = solve(rest, { ...ring, brush: { add: [[0.02, 0, 0, 0.004]], remove: [] } });
    expect(added.weights[v]).toBe(1);
    expect(added.targets[3 * v]).toBeCloseTo(0.02 * (1 - 0.5 / 8) ** 8, 6);
    expect(() => validateMuscle({ ...ring, brush: { add: [[0, 0, 0]], remove: [] } } as never)).toThrow(
      'muscle r: brush.add[0]: expected a sphere [x, y, z, radius], got [0,0,0]',
    );
    expect(() => validateMuscle({ ...ring, brush: { add: [], remove: [[0, 0, 0, 0]] } })).toThrow(
      'muscle r: brush.remove[0][3]: expected a positive radius of at most 0.1 m, got 0',
    );
  });
});
