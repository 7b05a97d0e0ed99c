import { describe, expect, it } from 'vitest';
import { archSlabs, colliderDistance, type Collider } from '../src/core/colliders';
import { SkinSolver } from '../src/core/solver';
import { buildTopology } from '../src/core/topology';
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

  it('on the head, finds the eyelid skin around each eye as collision candidates', async () => {
    const head = await loadHeadSkin('low');
    const t = buildTopology(head.positions, head.indices);
    const colliders: Collider[] = ['eye-l', 'eye-r'].map((n) => ({ name: n, a: head.pivots[n], radius: head.eyeRadius }));
    const s = new SkinSolver(t, { colliders });
    expect(s.counts().collision).toBeGreaterThan(40);
  });
});
