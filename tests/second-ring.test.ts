import { describe, expect, it } from 'vitest';
import { createSecondRing } from '../src/core/solver/second-ring';
import { SkinSolver } from '../src/core/solver/solver';
import { buildTopology } from '../src/core/solver/topology';
import { draggedPatch, triangleGrid } from './fixtures/grids';
import { startPartnerThread } from './fixtures/partner';

describe('the second ring of each vertex', () => {
  const grid = triangleGrid(0.02, 0.02, 0.002);
  const t = buildTopology(grid.positions, grid.indices);
  const ring = createSecondRing(t, 'local');

  /** Graph distances from `v` along the mesh's edges, by a breadth-first search of the test's own. */
  function distances(v: number): Int32Array {
    const d = new Int32Array(t.vertexCount).fill(-1);
    d[v] = 0;
    const queue = [v];
    for (let q = 0; q < queue.length; q++) {
      const u = queue[q];
      for (let j = t.neighbourStart[u]; j < t.neighbourStart[u + 1]; j++) {
        const w = t.neighbours[j];
        if (d[w] < 0) {
          d[w] = d[u] + 1;
          queue.push(w);
        }
      }
    }
    return d;
  }

  it('lists exactly the vertices two edges away, once each, as xyz offsets', () => {
    for (let v = 0; v < t.vertexCount; v++) {
      const d = distances(v);
      const listed = Array.from(ring.offsets.subarray(ring.start[v], ring.start[v + 1]), (o) => o / 3).sort((a, b) => a - b);
      const expected: number[] = [];
      for (let w = 0; w < t.vertexCount; w++) if (d[w] === 2) expected.push(w);
      expect(listed).toEqual(expected);
      expect(ring.inverse[v]).toBeCloseTo(1 / expected.length, 6);
    }
  });

  it('lies about twice as far out as the first ring on an even grid, and its constraint is zero at rest', () => {
    // An interior vertex of the 11 x 11 grid: its first ring 2 to 2.8 mm away, its second 4 to 5.7 mm.
    const middle = Array.from({ length: t.vertexCount }, (_, v) => v).find(
      (v) => Math.abs(t.rest[3 * v]) < 1e-6 && Math.abs(t.rest[3 * v + 1]) < 1e-6,
    )!;
    expect(ring.ratio[middle]).toBeGreaterThan(1.7);
    expect(ring.ratio[middle]).toBeLessThan(2.3);
    for (let v = 0; v < t.vertexCount; v++) expect(ring.rest[v]).toBe(0); // a flat grid: every ring at the vertex's height
  });
  it('leaves out a vertex whose ring reaches across a crease: there its height measures the turn, not a fold', () => {
    // The grid folded at x = 0 by 90 degrees (the half at x > 0 turned to stand along z): 2 mm between columns.
    const folded = grid.positions.slice();
    for (let o = 0; o < folded.length; o += 3) {
      if (folded[o] > 0) {
        folded[o + 2] = -folded[o];
        folded[o] = 0;
      }
    }
    const ft = buildTopology(folded, grid.indices);
    const fring = createSecondRing(ft, 'local');
    let leftOut = 0;
    for (let v = 0; v < ft.vertexCount; v++) {
      // The column on the grid: the crease is column 0, the turned half's columns stand at x = 0 with z < 0.
      const column = Math.round((ft.rest[3 * v] < -1e-6 ? ft.rest[3 * v] : -ft.rest[3 * v + 2]) / 0.002);
      const interior = Math.abs(ft.rest[3 * v + 1]) < 0.006 && Math.abs(column) < 4;
      if (!interior) continue;
      // One column from the crease, the ring reaches the other face (normals 90 degrees apart); on the crease and two
      // columns out it reaches no further than 45 degrees (the crease's normal halfway between the faces').
      if (Math.abs(column) === 1) {
        expect(fring.ratio[v], `column ${column}`).toBe(0);
        leftOut++;
      } else expect(fring.ratio[v], `column ${column}`).toBeGreaterThan(1.5);
    }
    // Five rows (|y| < 6 mm) of the two columns beside the crease.
    expect(leftOut).toBe(10);
  });
});

describe('bending two rings out on a fine sheet', () => {
  /** A sheet 4 cm square meshed every 0.5 mm, a patch of it pushed sideways so the skin beside it folds. */
  async function solve(threads: 1 | 2): Promise<{ shape: Float32Array; steps: number; rest: Float32Array }> {
    const grid = triangleGrid(0.04, 0.04, 0.0005);
    const t = buildTopology(grid.positions, grid.indices);
    const solver = new SkinSolver(t, { memory: 'shared' });
    const partner = threads === 2 ? await startPartnerThread(solver) : null;
    try {
      const { vertices, targets } = draggedPatch(t.rest, -0.01, 0, 0.006, [0.004, 0, 0]);
      solver.setMuscleTargets(vertices, targets);
      for (let f = 0; f < 60; f++) solver.step();
      let steps = 0;
      const ring = solver.partArrays().secondRing;
      for (let v = 0; v < t.vertexCount; v++) if (ring.gain[v] > 0) steps++;
      return { shape: solver.buffers.positions.slice(), steps, rest: t.rest };
    } finally {
      await partner?.stop();
    }
  }

  it('applies on skin meshed finer than its folds, and two threads give what one gives', async () => {
    const one = await solve(1);
    const two = await solve(2);
    // Every vertex of a sheet this fine has a capped first ring folding at 4.2 mm by the balance.
    expect(one.steps).toBeGreaterThan(0.9 * (one.rest.length / 3));
    let moved = 0;
    let difference = 0;
    for (let i = 0; i < one.shape.length; i++) {
      moved = Math.max(moved, Math.abs(one.shape[i] - one.rest[i]));
      difference = Math.max(difference, Math.abs(one.shape[i] - two.shape[i]));
    }
    expect(moved).toBeGreaterThan(0.002);
    expect(difference).toBe(0);
  });
});
