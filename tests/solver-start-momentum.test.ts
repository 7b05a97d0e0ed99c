import { describe, expect, it } from 'vitest';
import type { SkinParameters } from '../src/core/solver/skin-parameters';
import { SkinSolver } from '../src/core/solver/solver';
import { START_MOMENTUM_FRAMES } from '../src/core/solver/solver-schedule';
import { buildTopology } from '../src/core/solver/topology';
import { draggedPatch, triangleGrid } from './fixtures/grids';
import { loadHeadSimulation } from './fixtures/head-simulation';

/** A 6 x 4 cm sheet at 2 mm spacing with a 1 cm patch dragged 3 mm sideways and 2 mm up; its shape after each frame. */
function dragSheet(parameters: Partial<SkinParameters>, frames: number): Float32Array[] {
  const g = triangleGrid(0.06, 0.04, 0.002);
  const t = buildTopology(g.positions, g.indices);
  const { vertices, targets } = draggedPatch(t.rest, -0.015, 0, 0.01, [0.003, 0, 0.002]);
  const solver = new SkinSolver(t, { parameters });
  solver.setMuscleTargets(vertices, targets, 1, 0);
  const shapes: Float32Array[] = [];
  for (let f = 0; f < frames; f++) {
    solver.wake();
    solver.step();
    shapes.push(Float32Array.from(solver.buffers.positions));
  }
  return shapes;
}

const same = (a: Float32Array, b: Float32Array) => a.every((x, i) => x === b[i]);

/**
 * thesis-laughing on the medium head: frames until every vertex is within 2 % (of the largest move) of where it comes to rest, and to
 * sleep.
 */
async function framesToShape(parameters: Partial<SkinParameters>) {
  const run = async () => {
    const sim = await loadHeadSimulation('medium', parameters);
    sim.expression.applyPreset('thesis-laughing', 1);
    sim.apply();
    return sim;
  };
  const first = await run();
  const start = Float32Array.from(first.host.solver.buffers.positions);
  let frames = 0;
  while (frames < 1000 && first.host.step()) frames++;
  const final = first.host.solver.buffers.positions;
  const farthest = (x: Float32Array) => {
    let worst = 0;
    for (let i = 0; i < x.length; i += 3)
      worst = Math.max(worst, Math.hypot(x[i] - final[i], x[i + 1] - final[i + 1], x[i + 2] - final[i + 2]));
    return worst;
  };
  const tolerance = 0.02 * farthest(start);
  const again = await run();
  let near = 0;
  // The same run again: it is at the first run's final shape by the frame that run stopped at, so the loop ends there.
  while (near < frames && farthest(again.host.solver.buffers.positions) > tolerance) {
    again.host.step();
    near++;
  }
  expect(farthest(again.host.solver.buffers.positions)).toBeLessThanOrEqual(tolerance);
  return { near, frames, sleeping: first.host.solver.sleeping };
}

describe("the start momentum (a larger carry in a motion's first frames)", () => {
  it('carries startMomentum along the surface for the first START_MOMENTUM_FRAMES frames and momentum after', () => {
    const frames = START_MOMENTUM_FRAMES + 3;
    const scheduled = dragSheet({ momentum: 0.5, startMomentum: 0.7 }, frames);
    const early = dragSheet({ momentum: 0.7, startMomentum: 0.7 }, frames);
    const late = dragSheet({ momentum: 0.5, startMomentum: 0.5 }, frames);
    // The first frame carries nothing (the skin starts at rest); from the second the carries differ.
    expect(same(scheduled[1], late[1])).toBe(false);
    for (let f = 0; f < START_MOMENTUM_FRAMES; f++) expect(same(scheduled[f], early[f])).toBe(true);
    expect(same(scheduled[START_MOMENTUM_FRAMES], early[START_MOMENTUM_FRAMES])).toBe(false);
  });

  it('brings the thesis laughing preset on the medium head to its shape in fewer frames', async () => {
    const scheduled = await framesToShape({});
    const flat = await framesToShape({ startMomentum: 0.5 });
    expect(scheduled.sleeping && flat.sleeping).toBe(true);
    // Measured: 25 frames against 43.
    expect(scheduled.near).toBeLessThan(0.75 * flat.near);
  });
});
