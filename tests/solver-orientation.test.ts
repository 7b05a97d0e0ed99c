import { describe, expect, it } from 'vitest';
import { MIN_PROJECTED_AREA } from '../src/core/solver/orientation-kernel';
import { SkinSolver } from '../src/core/solver/solver';
import { buildTopology } from '../src/core/solver/topology';
import { triangleGrid } from './fixtures/grids';
import { invertedTriangles } from './fixtures/head-simulation';

describe('orientation constraints', () => {
  // A 2 x 2 cm sheet at 1 mm spacing. A muscle drags a 3 mm band of skin 5 mm to the right, across the band
  // beside it, and holds it firmly along the normal too, so the skin cannot fold out of the way.
  const g = triangleGrid(0.02, 0.02, 0.001);
  const t = buildTopology(g.positions, g.indices);
  const vertices: number[] = [];
  const targets: number[] = [];
  for (let v = 0; v < t.vertexCount; v++) {
    const [x, y, z] = [t.rest[3 * v], t.rest[3 * v + 1], t.rest[3 * v + 2]];
    if (x > -0.0035 && x < -0.0005 && Math.abs(y) < 0.006) {
      vertices.push(v);
      targets.push(x + 0.005, y, z);
    }
  }

  it('asks for a shape with turned-over triangles', () => {
    const wanted = Float32Array.from(t.rest);
    vertices.forEach((v, i) => wanted.set(targets.slice(3 * i, 3 * i + 3), 3 * v));
    expect(invertedTriangles(t.rest, wanted, t.triangles)).toBeGreaterThan(10);
  });

  it('keeps every triangle facing its rest side, with at least its least projected area', () => {
    const solver = new SkinSolver(t);
    solver.setMuscleTargets(vertices, targets, 1, 1);
    for (let f = 0; f < 600 && solver.step(); f++);
    const x = solver.buffers.positions;
    expect(invertedTriangles(t.rest, x, t.triangles)).toBe(0);
    // The skin did move: the dragged band went most of the way it was asked to.
    const moved = vertices.map((v) => x[3 * v] - t.rest[3 * v]);
    expect(Math.max(...moved)).toBeGreaterThan(0.002);
    // Each triangle's area along its rest normal stays near the bound or above (a little under: the other constraints
    // act after it within an iteration).
    let smallest = Infinity;
    const T = t.triangles;
    for (let k = 0; k < T.length; k += 3) {
      const area = (p: Float32Array) => {
        const [a, b, c] = [3 * T[k], 3 * T[k + 1], 3 * T[k + 2]];
        return (p[b] - p[a]) * (p[c + 1] - p[a + 1]) - (p[b + 1] - p[a + 1]) * (p[c] - p[a]);
      };
      smallest = Math.min(smallest, area(x) / area(t.rest));
    }
    expect(smallest).toBeGreaterThan(0.5 * MIN_PROJECTED_AREA);
  });
});
