import { describe, expect, it } from 'vitest';
import { archCapsules, colliderDistance, type Collider } from '../src/core/colliders';
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

  it('builds a capsule chain that follows the dental arch', () => {
    // A U-shaped arch of points: x = 2 cm sin(a), z = 2 cm cos(a) for a in -90..90 degrees, 6 mm tall.
    const pts: number[] = [];
    for (let i = 0; i <= 40; i++) {
      const a = -Math.PI / 2 + (Math.PI * i) / 40;
      for (const y of [-0.003, 0.003]) pts.push(0.02 * Math.sin(a), y, 0.02 * Math.cos(a));
    }
    const capsules = archCapsules('teeth', pts, 6);
    expect(capsules.length).toBe(6);
    const dir = [0, 0, 0];
    // Every arch point lies inside or near the chain, and the arch's centre (behind the teeth) well outside it.
    for (let i = 0; i < pts.length; i += 3) {
      const d = Math.min(...capsules.map((c) => colliderDistance(c, pts[i], pts[i + 1], pts[i + 2], dir)));
      expect(d).toBeLessThan(0.003);
    }
    const centre = Math.min(...capsules.map((c) => colliderDistance(c, 0, 0, 0.0, dir)));
    expect(centre).toBeGreaterThan(0.008);
  });

  it('on the head, finds the eyelid skin around each eye as collision candidates', async () => {
    const head = await loadHeadSkin('low');
    const t = buildTopology(head.positions, head.indices);
    const colliders: Collider[] = ['eye-l', 'eye-r'].map((n) => ({ name: n, a: head.pivots[n], radius: head.eyeRadius }));
    const s = new SkinSolver(t, { colliders });
    expect(s.counts().collision).toBeGreaterThan(40);
  });
});
