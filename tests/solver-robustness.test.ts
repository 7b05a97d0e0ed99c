import { describe, expect, it } from 'vitest';
import { SkinSolver } from '../src/core/solver/solver';
import { buildTopology } from '../src/core/solver/topology';
import { triangleGrid } from './fixtures/grids';

const grid = triangleGrid(0.04, 0.03, 0.002, 0.05);
const topology = buildTopology(grid.positions, grid.indices);

function allFinite(a: Float32Array): boolean {
  for (const v of a) if (!Number.isFinite(v)) return false;
  return true;
}

describe('solver robustness', () => {
  it('never produces NaN or Infinity, and stays bounded, under extreme targets', () => {
    const s = new SkinSolver(topology);
    // Drag half the patch 100 m away and the other half 100 m the other way (1,000x the patch size).
    const vertices: number[] = [];
    const targets: number[] = [];
    for (let v = 0; v < topology.vertexCount; v++) {
      const side = topology.rest[3 * v] > 0 ? 1 : -1;
      vertices.push(v);
      targets.push(side * 100, -side * 100, 100);
    }
    s.setMuscleTargets(vertices, targets, 1);
    for (let f = 0; f < 300; f++) s.step();
    expect(allFinite(s.buffers.positions)).toBe(true);
    expect(allFinite(s.buffers.normals)).toBe(true);
    // No vertex goes further than its target (the solver only averages rest, targets and its neighbours).
    for (let i = 0; i < s.buffers.positions.length; i++) expect(Math.abs(s.buffers.positions[i])).toBeLessThan(101);
  });

  it('rejects a non-finite target with a message naming it, and keeps its last good state', () => {
    const s = new SkinSolver(topology);
    s.setMuscleTargets([0, 1], [0.01, 0, 0, 0.01, 0, 0], 1);
    for (let f = 0; f < 50; f++) s.step();
    const before = Float32Array.from(s.buffers.positions);
    const targetsBefore = Float32Array.from(s.buffers.targets);
    expect(() => s.setMuscleTargets([2, 3], [0, 0, 0, NaN, 0, 0], 1)).toThrow(
      'the target of vertex 3 (entry 1) has a non-finite x coordinate: NaN',
    );
    expect(() => s.setMuscleTargets([2], [Infinity, 0, 0], 1)).toThrow(/non-finite x coordinate: Infinity/);
    expect(() => s.setMuscleTargets([2], [0, 0, 0], NaN)).toThrow('weight must be a finite number from 0 to 1, got NaN');
    expect(() => s.setMuscleTargets([topology.vertexCount], [0, 0, 0], 1)).toThrow(
      `vertex 0 is ${topology.vertexCount}, not one of the ${topology.vertexCount} skin vertices`,
    );
    expect(Array.from(s.buffers.targets)).toEqual(Array.from(targetsBefore));
    expect(Array.from(s.buffers.positions)).toEqual(Array.from(before));
  });

  it('rejects a non-finite or out-of-range parameter by name and keeps the old one', () => {
    const s = new SkinSolver(topology);
    expect(() => s.setParameters({ positionStiffness: NaN })).toThrow(
      'skin parameters: positionStiffness: expected a number from 0 to 1, got NaN',
    );
    expect(() => s.setParameters({ lengthIterations: 2.5 })).toThrow(
      'skin parameters: lengthIterations: expected an integer from 0 to 64, got 2.5',
    );
    expect(() => s.setParameters({ muscleStiffness: 3 })).toThrow('skin parameters: muscleStiffness: expected a number from 0 to 1, got 3');
    expect(s.parameters().positionStiffness).toBeGreaterThan(0);
    expect(s.parameters().lengthIterations).toBe(3);
  });

  it('handles a mesh with degenerate, duplicate and non-manifold triangles without NaN', () => {
    const positions = Float32Array.from([...grid.positions, 0.001, 0.001, 0.03]);
    const [a, b, c] = Array.from(grid.indices.subarray(0, 3));
    const apex = grid.positions.length / 3;
    const indices = Uint32Array.from([...grid.indices, a, a, b, a, b, c, a, c, apex]);
    const t = buildTopology(positions, indices);
    const s = new SkinSolver(t);
    s.setMuscleTargets([a, b, c, apex], [0, 0.02, 0.01, 0, 0.02, 0.01, 0, 0.02, 0.01, 0.01, 0.01, 0.04], 1);
    for (let f = 0; f < 200; f++) s.step();
    expect(allFinite(s.buffers.positions)).toBe(true);
    expect(allFinite(s.buffers.normals)).toBe(true);
  });
});

describe('determinism', () => {
  it('gives bit-identical positions for the same inputs', () => {
    const run = () => {
      const s = new SkinSolver(topology);
      const vertices = [10, 11, 12, 40, 41, 42];
      const targets = vertices.flatMap((v) => [topology.rest[3 * v] - 0.004, topology.rest[3 * v + 1] + 0.002, topology.rest[3 * v + 2]]);
      s.setMuscleTargets(vertices, targets, 0.8, 0.2);
      for (let f = 0; f < 200 && s.step(); f++);
      return s.buffers.positions;
    };
    const a = run();
    const b = run();
    expect(Buffer.from(a.buffer).equals(Buffer.from(b.buffer))).toBe(true);
    expect(a.some((v, i) => v !== topology.rest[i])).toBe(true);
  });
});
