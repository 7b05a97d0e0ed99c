import { beforeAll, describe, expect, it } from 'vitest';
import type { HairStrands } from '../src/core/hair/hair';
import { placeBrows } from '../src/core/hair/hair-placement';
import { DEFAULT_LANDMARKS } from '../src/core/head/landmarks';
import { loadHeadSkin } from './fixtures/head';
import { rootsAndDirections } from './fixtures/hair';
import { loadHeadSimulation, resetToRest } from './fixtures/head-simulation';

/**
 * A brow hair grows from a follicle held in the skin, which turns it as the skin patch turns. The skin under the brow
 * stretches to up to three times its length as the lids close and shears where the corrugator bunches it, and a
 * triangle's edge turns with such stretch though the patch does not: hairs that followed their anchor triangle's
 * first edge hung down from the brow's head as a tuft under AU43 (51 of 1,040 turned more than 30 degrees, up to 42)
 * and one turned over under AU4 (158 degrees). Each brow hair's turn from its direction at rest, medium head.
 */
describe('brow hairs under the lids closing and the brows lowered (medium head)', () => {
  let brows: HairStrands;
  let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
  let render: (values: Float32Array) => Float32Array;
  let rest: Float32Array;
  beforeAll(async () => {
    const skin = await loadHeadSkin('medium');
    brows = placeBrows({ positions: skin.positions, normals: skin.normals, triangles: skin.indices }, DEFAULT_LANDMARKS);
    sim = await loadHeadSimulation('medium');
    const map = sim.host.topology.renderToSim;
    render = (values) => {
      const out = new Float32Array(3 * map.length);
      for (let r = 0; r < map.length; r++) out.set(values.subarray(3 * map[r], 3 * map[r] + 3), 3 * r);
      return out;
    };
    rest = rootsAndDirections(brows, render(sim.host.solver.buffers.positions), render(sim.host.solver.buffers.normals)).directions;
  });

  /** The largest turn of a brow hair, degrees, once `expression` at full intensity has settled from rest. */
  const largestTurn = (expression: string): number => {
    resetToRest(sim);
    if (expression.startsWith('AU')) sim.expression.setActionUnit(expression, 1);
    else sim.expression.applyPreset(expression, 1);
    sim.apply();
    sim.host.run(600);
    expect(sim.host.solver.sleeping).toBe(true);
    const now = rootsAndDirections(brows, render(sim.host.solver.buffers.positions), render(sim.host.solver.buffers.normals)).directions;
    let largest = 0;
    for (let k = 0; k < brows.count; k++) {
      const dot = rest[3 * k] * now[3 * k] + rest[3 * k + 1] * now[3 * k + 1] + rest[3 * k + 2] * now[3 * k + 2];
      largest = Math.max(largest, (Math.acos(Math.min(1, dot)) * 180) / Math.PI);
    }
    return largest;
  };

  it.each(['AU43', 'AU45'])('closing the lids (%s) turns no brow hair more than 30 degrees', (unit) => {
    expect(largestTurn(unit)).toBeLessThan(30);
  });

  it.each(['AU4', 'anger'])('%s turns the hairs at the brow head, none over (90 degrees or more)', (item) => {
    const largest = largestTurn(item);
    expect(largest).toBeGreaterThan(10); // the corrugator does turn them
    expect(largest).toBeLessThan(90);
  });
});
