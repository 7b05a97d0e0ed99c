import { describe, expect, it } from 'vitest';
import { archSlabs, colliderDistance, slabSide, type Collider } from '../src/core/solver/colliders';
import { SkinSolver } from '../src/core/solver/solver';
import { buildTopology } from '../src/core/solver/topology';
import { loadHeadSkin } from './fixtures/head';
import { triangleGrid } from './fixtures/grids';

describe('collisions', () => {
  it('keeps a sheet pressed onto a sphere outside it (an eyelid over the eye)', () => {
    // A flat 4 x 4 cm sheet 2 mm above a 12 mm sphere; a muscle presses its middle 8 mm down.
    const g = triangleGrid(0.04, 0.04, 0.001);
    const t = buildTopology(g.positions, g.indices);
    const eye: Collider = { name: 'eye', a: [0, 0, -0.014], radius: 0.012 };
    const vertices: number[] = [];
    const targets: number[] = [];
    for (let v = 0; v < t.vertexCount; v++) {
      if (Math.hypot(t.rest[3 * v], t.rest[3 * v + 1]) < 0.006) {
        vertices.push(v);
        targets.push(t.rest[3 * v], t.rest[3 * v + 1], -0.008);
      }
    }
    const run = (colliders: Collider[]) => {
      const s = new SkinSolver(t, { colliders });
      s.setMuscleTargets(vertices, targets, 1);
      for (let f = 0; f < 400 && s.step(); f++);
      let deepest = Infinity;
      const dir = [0, 0, 0];
      for (let v = 0; v < t.vertexCount; v++) {
        const p = s.buffers.positions;
        deepest = Math.min(deepest, colliderDistance(eye, p[3 * v], p[3 * v + 1], p[3 * v + 2], dir));
      }
      return deepest;
    };
    // Without the collider the skin sinks deep into the sphere; with it, no vertex goes inside.
    expect(run([])).toBeLessThan(-0.003);
    expect(run([eye])).toBeGreaterThan(-1e-5);
  });

  it('builds a thin wall of slabs that follows the dental arch', () => {
    // A U-shaped row of teeth: x = 2 cm sin(a), z = 2 cm cos(a) for a in -90..90 degrees, 1 cm tall, 2 mm thick.
    const pts: number[] = [];
    for (let i = 0; i <= 40; i++) {
      const a = -Math.PI / 2 + (Math.PI * i) / 40;
      for (const r of [0.019, 0.021]) for (const y of [-0.005, 0.005]) pts.push(r * Math.sin(a), y, r * Math.cos(a));
    }
    const slabs = archSlabs('teeth', pts, 8);
    expect(slabs.length).toBe(8);
    const dir = [0, 0, 0];
    const distance = (x: number, y: number, z: number) => Math.min(...slabs.map((c) => colliderDistance(c, x, y, z, dir)));
    // Every tooth point is enclosed; the wall stays thin (a point 3 mm in front of the incisors is outside it) and
    // the mouth's middle, behind the teeth, is far outside.
    for (let i = 0; i < pts.length; i += 3) expect(distance(pts[i], pts[i + 1], pts[i + 2])).toBeLessThanOrEqual(1e-9);
    expect(distance(0, 0, 0.024)).toBeGreaterThan(0.0005);
    expect(distance(0, 0, 0)).toBeGreaterThan(0.01);
    expect(Math.max(...slabs.map((s) => s.radius))).toBeLessThan(0.004);
  });

  it('pushes a point that went through a slab back to the side it started on, not out the far side', () => {
    // A 2 cm x 1 cm wall in the x-y plane, 1 mm thick; the point starts in front (+z) and ends 0.8 mm behind its middle.
    const wall: Collider = { name: 'wall', a: [-0.01, 0, 0], b: [0.01, 0, 0], up: [0, 0.01, 0], radius: 0.0005 };
    const dir = [0, 0, 0];
    const side = slabSide(wall, 0, 0.005, 0.003);
    expect(side).toBe(1);
    // Measured to the nearest surface it is outside behind the wall; measured from its side it is 1.3 mm inside.
    expect(colliderDistance(wall, 0, 0.005, -0.0008, dir)).toBeCloseTo(0.0003, 9);
    expect(colliderDistance(wall, 0, 0.005, -0.0008, dir, side)).toBeCloseTo(-0.0013, 9);
    expect(dir).toEqual([0, 0, 1]);
    // Beyond the wall's edge there is no wrong side: the nearest surface counts.
    expect(colliderDistance(wall, 0, 0.012, -0.003, dir, side)).toBeCloseTo(colliderDistance(wall, 0, 0.012, -0.003, dir), 12);
  });

  it('lets skin pushed through the teeth come home: a lip behind its slab returns to rest in front of it', () => {
    // A 2 cm sheet 1 mm in front of a wider wall is put 3 mm behind the wall, as a jaw opening once left the lips,
    // then left to return. The wall must bring it back to the front, where it started, not hold it behind.
    const g = triangleGrid(0.02, 0.02, 0.001);
    const t = buildTopology(g.positions, g.indices);
    const wall: Collider = { name: 'teeth', a: [-0.015, -0.015, -0.0015], b: [0.015, -0.015, -0.0015], up: [0, 0.03, 0], radius: 0.0005 };
    // The whole sheet is solved: its positions are written directly, and the active region takes skin outside it
    // to be at rest.
    const s = new SkinSolver(t, { colliders: [wall], activeRegion: false });
    for (let i = 2; i < t.rest.length; i += 3) s.buffers.positions[i] = -0.0045;
    s.wake();
    for (let f = 0; f < 400 && s.step(); f++);
    let farthest = 0;
    for (let i = 0; i < t.rest.length; i += 3) farthest = Math.max(farthest, Math.abs(s.buffers.positions[i + 2] - t.rest[i + 2]));
    expect(s.sleeping).toBe(true);
    expect(farthest).toBeLessThan(1e-5);
  });

  it('on the head, finds the eyelid skin around each eye as collision candidates', async () => {
    const head = await loadHeadSkin('low');
    const t = buildTopology(head.positions, head.indices);
    const colliders: Collider[] = ['eye-l', 'eye-r'].map((n) => ({ name: n, a: head.pivots[n], radius: head.eyeRadius }));
    const s = new SkinSolver(t, { colliders });
    expect(s.counts().collision).toBeGreaterThan(40);
  });
});
