import { beforeAll, describe, expect, it } from 'vitest';
import { SkinSolver } from '../src/core/solver/solver';
import { buildTopology, type SkinTopology } from '../src/core/solver/topology';
import { loadHeadSkin } from './fixtures/head';
import { triangleGrid } from './fixtures/grids';

function maxDistanceFromRest(s: SkinSolver): number {
  const x = s.buffers.positions;
  const X = s.topology.rest;
  let worst = 0;
  for (let i = 0; i < x.length; i += 3) worst = Math.max(worst, Math.hypot(x[i] - X[i], x[i + 1] - X[i + 1], x[i + 2] - X[i + 2]));
  return worst;
}

/** Vertices within `radius` of the vertex nearest `at`, and targets that move them all by `offset`. */
function patch(t: SkinTopology, at: number[], radius: number, offset: number[]) {
  const vertices: number[] = [];
  const targets: number[] = [];
  for (let v = 0; v < t.vertexCount; v++) {
    const p = [0, 1, 2].map((k) => t.rest[3 * v + k]);
    if (Math.hypot(p[0] - at[0], p[1] - at[1], p[2] - at[2]) < radius) {
      vertices.push(v);
      targets.push(p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]);
    }
  }
  return { vertices, targets };
}

describe.each([
  { name: 'a curved grid', load: async () => triangleGrid(0.08, 0.04, 0.001, 0.05) },
  { name: 'the low-resolution head', load: async () => loadHeadSkin('low') },
])('the solver on $name', ({ load }) => {
  let topology: SkinTopology;
  beforeAll(async () => {
    const mesh = await load();
    topology = buildTopology(mesh.positions, mesh.indices);
  });

  it('leaves every vertex within 1e-6 (of the mesh size) of rest after 1,000 frames with no input', () => {
    const s = new SkinSolver(topology);
    for (let f = 0; f < 1000; f++) {
      s.wake(); // solve every frame even though nothing asks it to
      expect(s.step()).toBe(true);
    }
    expect(maxDistanceFromRest(s)).toBeLessThan(1e-6 * topology.size);
  });

  it('returns within 1e-4 of rest within 120 frames after the targets are released', () => {
    const s = new SkinSolver(topology);
    const centre = [0, 1, 2].map((k) => topology.rest[3 * Math.floor(topology.vertexCount / 2) + k]);
    const { vertices, targets } = patch(topology, centre, 0.02, [0.004, 0.006, -0.003]);
    expect(vertices.length).toBeGreaterThan(20);
    s.setMuscleTargets(vertices, targets, 1);
    for (let f = 0; f < 300 && s.step(); f++);
    expect(maxDistanceFromRest(s)).toBeGreaterThan(0.003);
    s.clearMuscleTargets();
    for (let f = 0; f < 120; f++) s.step();
    expect(maxDistanceFromRest(s)).toBeLessThan(1e-4 * topology.size);
  });
});
