import { beforeAll, describe, expect, it } from 'vitest';
import type { Collider } from '../src/core/solver/colliders';
import { SkinSolver } from '../src/core/solver/solver';
import { buildTopology } from '../src/core/solver/topology';
import { draggedPatch, triangleGrid } from './fixtures/grids';
import { loadHeadSimulation } from './fixtures/head-simulation';

type Simulation = Awaited<ReturnType<typeof loadHeadSimulation>>;

/** Solves `frames` frames, waking the solver each time: past settling, both solves compare at the same frame. */
function solve(solver: { wake(): void; step(): boolean }, frames: number): void {
  for (let f = 0; f < frames; f++) {
    solver.wake();
    solver.step();
  }
}

/** Steps until the solver sleeps (at most `maxFrames`). */
function settle(solver: { step(): boolean }, maxFrames = 1500): void {
  for (let f = 0; f < maxFrames && solver.step(); f++);
}

/** Vertex v's xyz in `a` equal those in `b` bit for bit. */
const sameAt = (a: Float32Array, b: Float32Array, v: number): boolean =>
  a[3 * v] === b[3 * v] && a[3 * v + 1] === b[3 * v + 1] && a[3 * v + 2] === b[3 * v + 2];

/**
 * How near the region's solve keeps to the whole-mesh one, times the mesh size: the region leaves out skin the
 * whole-mesh solve moves by less than ACTIVE_GROW (5e-5), and the two differ by a few times that at most.
 */
const MATCH = 1e-4;

function largestDistance(a: Float32Array, b: Float32Array): number {
  let worst = 0;
  for (let i = 0; i < a.length; i += 3) worst = Math.max(worst, Math.hypot(a[i] - b[i], a[i + 1] - b[i + 1], a[i + 2] - b[i + 2]));
  return worst;
}

// The chin raiser (AU17) at 0.2 on the low head, solved as the worker solves it, with and without the active region:
// a fifth of the chin raise, a local move, so that the region stays a part of the skin; the full raise (5 mm on
// the medium head) wakes most of the face.
describe('the active region on the head', () => {
  let region: Simulation;
  let whole: Simulation;
  beforeAll(async () => {
    region = await loadHeadSimulation('low');
    whole = await loadHeadSimulation('low', {}, { activeRegion: false });
    for (const sim of [region, whole]) {
      sim.expression.setActionUnit('AU17', 0.2);
      sim.apply();
      // Settled (it sleeps within about 150 frames), and on: both stop at the same frame, however slowly the last
      // millionths still creep.
      solve(sim.host.solver, 300);
    }
  });

  it('gives the shape of the whole-mesh solve, within 1e-4 of the mesh size, solving part of the skin', () => {
    const t = region.host.topology;
    const x = region.host.solver.buffers.positions;
    expect(largestDistance(whole.host.solver.buffers.positions, t.rest)).toBeGreaterThan(1e-3 * t.size); // it did move
    expect(largestDistance(x, whole.host.solver.buffers.positions)).toBeLessThan(MATCH * t.size);
    expect(region.host.solver.activeVertexCount).toBeGreaterThan(0);
    expect(region.host.solver.activeVertexCount).toBeLessThan(0.6 * t.vertexCount);
    // The skin it did not solve is exactly at rest, positions and normals.
    let atRest = 0;
    for (let v = 0; v < t.vertexCount; v++)
      if (sameAt(x, t.rest, v) && sameAt(region.host.solver.buffers.normals, t.restNormals, v)) atRest++;
    expect(atRest).toBeGreaterThan(0.3 * t.vertexCount);
  });

  it('empties once the muscles are released, and the whole skin is back exactly at rest', () => {
    region.expression.reset();
    region.apply();
    settle(region.host.solver);
    const s = region.host.solver;
    const t = region.host.topology;
    expect(s.sleeping).toBe(true);
    expect(s.activeVertexCount).toBe(0);
    let off = 0;
    for (let v = 0; v < t.vertexCount; v++)
      if (!sameAt(s.buffers.positions, t.rest, v) || !sameAt(s.buffers.normals, t.restNormals, v)) off++;
    expect(off).toBe(0);
  });

  it('is the whole mesh when switched off', () => {
    expect(whole.host.solver.activeVertexCount).toBe(whole.host.topology.vertexCount);
  });
});

// A flat 24 x 8 cm sheet at 2 mm spacing; a muscle drags a 1 cm patch near one end (x = -10 cm).
/** A 24 cm sheet of the given height at 2 mm spacing, and muscle targets dragging a 1 cm patch at x = -10 cm. */
function sheetWithDraggedPatch(height: number) {
  const g = triangleGrid(0.24, height, 0.002);
  const t = buildTopology(g.positions, g.indices);
  return { t, ...draggedPatch(t.rest, -0.1, 0, 0.01, [0.003, 0.002, 0]) };
}

describe('the active region on a sheet', () => {
  const { t, vertices, targets } = sheetWithDraggedPatch(0.08);

  it('leaves the far end exactly at rest, and matches the whole-mesh solve', () => {
    const region = new SkinSolver(t);
    const whole = new SkinSolver(t, { activeRegion: false });
    for (const s of [region, whole]) {
      s.setMuscleTargets(vertices, targets, 1, 0);
      solve(s, 300);
    }
    expect(largestDistance(region.buffers.positions, whole.buffers.positions)).toBeLessThan(MATCH * t.size);
    let far = 0;
    for (let v = 0; v < t.vertexCount; v++) {
      if (t.rest[3 * v] < 0.04) continue; // 14 cm and more from the patch's centre
      far++;
      expect(sameAt(region.buffers.positions, t.rest, v) && sameAt(region.buffers.normals, t.restNormals, v)).toBe(true);
    }
    expect(far).toBeGreaterThan(0.3 * t.vertexCount);
    expect(region.activeVertexCount).toBeLessThan(0.6 * t.vertexCount);
  });
});

// Opening the jaw turns the lower teeth's colliders into skin at rest; the region takes in what they reach.
describe('the active region and colliders that move', () => {
  it('opening the jaw (AU26, AU27) on the head gives the shape of the whole-mesh solve', async () => {
    for (const au of ['AU26', 'AU27']) {
      const region = await loadHeadSimulation('low');
      const whole = await loadHeadSimulation('low', {}, { activeRegion: false });
      for (const sim of [region, whole]) {
        sim.expression.setActionUnit(au, 1);
        sim.apply();
        solve(sim.host.solver, 250);
      }
      const t = region.host.topology;
      expect(largestDistance(whole.host.solver.buffers.positions, t.rest)).toBeGreaterThan(1e-2 * t.size);
      expect(largestDistance(region.host.solver.buffers.positions, whole.host.solver.buffers.positions)).toBeLessThan(MATCH * t.size);
    }
  });

  it('takes in skin at rest that a collider which moved with an input change now reaches', () => {
    // A 24 x 4 cm sheet at 2 mm spacing; a muscle drags a patch at x = -10 cm; a sphere 0.5 mm under the sheet at
    // x = +9 cm, far outside the region, rises 3 mm into it when the inputs next change.
    const { t, vertices, targets } = sheetWithDraggedPatch(0.04);
    const sphere: Collider = { name: 'ball', a: [0.09, 0, -0.0065], radius: 0.006 };
    const region = new SkinSolver(t, { colliders: [sphere] });
    const whole = new SkinSolver(t, { colliders: [sphere], activeRegion: false });
    for (const s of [region, whole]) {
      s.setMuscleTargets(vertices, targets, 1, 0);
      solve(s, 100);
    }
    // The skin over the sphere is outside the region, exactly at rest.
    let over = 0;
    for (let v = 0; v < t.vertexCount; v++) {
      if (Math.abs(t.rest[3 * v] - 0.09) > 0.01) continue;
      over++;
      expect(sameAt(region.buffers.positions, t.rest, v)).toBe(true);
    }
    expect(over).toBeGreaterThan(100);
    expect(region.activeVertexCount).toBeLessThan(0.6 * t.vertexCount);
    sphere.a[2] = -0.0035;
    for (const s of [region, whole]) {
      s.updateMuscles();
      solve(s, 300);
    }
    let lifted = 0;
    for (let v = 0; v < t.vertexCount; v++) lifted = Math.max(lifted, whole.buffers.positions[3 * v + 2] - t.rest[3 * v + 2]);
    expect(lifted).toBeGreaterThan(0.002);
    expect(largestDistance(region.buffers.positions, whole.buffers.positions)).toBeLessThan(MATCH * t.size);
  });
});
