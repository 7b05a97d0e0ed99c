import { describe, expect, it } from 'vitest';
import { LID_FIRM, LID_SLACK, LidSlack } from '../src/core/rig/lid-slack';
import type { LidMuscle, Muscle } from '../src/core/rig/rig-types';
import { SkinSolver } from '../src/core/solver/solver';
import { buildTopology } from '../src/core/solver/topology';
import { triangleGrid } from './fixtures/grids';

// A flat patch in the xy plane, facing +z, with a closing lid above its middle: the lid's hinge along x, so the skin
// above it unfolds along y.
const grid = triangleGrid(0.04, 0.04, 0.002);
const topology = buildTopology(grid.positions, grid.indices);
const lid: LidMuscle = {
  name: 'lid',
  side: 'left',
  type: 'lid',
  center: [0.02, 0.01, 0],
  rotation: [0, 0, 0],
  radii: [0.01, 0.004, 0.01],
  maxAngle: 40,
  innerFraction: 0.6,
};
const FREE = { positionStiffness: 0, wrinkleSpacing: 0, momentum: 0, startMomentum: 0, foldMomentum: 0 };

/** Each edge's direction: |dx| and |dy| over its length. */
function direction(e: number): { x: number; y: number } {
  const a = 3 * topology.edges[2 * e];
  const b = 3 * topology.edges[2 * e + 1];
  const r = topology.restLength[e];
  return { x: Math.abs(topology.rest[b] - topology.rest[a]) / r, y: Math.abs(topology.rest[b + 1] - topology.rest[a + 1]) / r };
}

describe('the upper lid unfolds as it closes (LidSlack)', () => {
  it('leaves every edge its rest length, exactly, while the lid is open', () => {
    const slack = new LidSlack(topology, [lid]);
    const lengths = topology.restLength.slice().fill(1);
    slack.compute([0], lengths);
    expect(slack.edgeCount).toBeGreaterThan(20);
    let changed = 0;
    for (let e = 0; e < lengths.length; e++) if (lengths[e] !== 1 && lengths[e] !== topology.restLength[e]) changed++;
    expect(changed).toBe(0);
  });

  it('unfolds the edges above the lid across its hinge only, by up to LID_SLACK, in proportion to its closing', () => {
    const slack = new LidSlack(topology, [lid]);
    const half = topology.restLength.slice();
    const full = topology.restLength.slice();
    slack.compute([0.5], half);
    slack.compute([1], full);
    let acrossGrew = 0;
    let alongGrew = 0;
    let below = 0;
    for (let e = 0; e < full.length; e++) {
      const growth = full[e] / topology.restLength[e] - 1;
      expect(growth).toBeGreaterThanOrEqual(0);
      expect(growth).toBeLessThanOrEqual(LID_SLACK + 1e-6);
      expect(half[e]).toBeLessThanOrEqual(full[e]);
      const d = direction(e);
      const a = 3 * topology.edges[2 * e];
      const b = 3 * topology.edges[2 * e + 1];
      const midY = (topology.rest[a + 1] + topology.rest[b + 1]) / 2;
      if (growth > 0 && midY < lid.center[1]) below++;
      if (d.y < 1e-6 && growth > 1e-6) alongGrew++;
      if (d.x < 1e-6 && growth > 0.9 * LID_SLACK) acrossGrew++;
    }
    // Nothing below the lid's centre unfolds, and an edge along the hinge keeps its length.
    expect(below).toBe(0);
    expect(alongGrew).toBe(0);
    expect(acrossGrew).toBeGreaterThan(5);
  });

  it('lets an unfolding edge stretch up to its unfolded length without pulling, and pulls it back from beyond', () => {
    const s = new SkinSolver(topology, { activeRegion: false });
    s.setParameters(FREE);
    const slack = new LidSlack(topology, [lid]);
    slack.compute([1], s.buffers.unfoldedLengths);
    s.updateMuscles();
    // The whole patch stretched along y by a tenth (within every unfolding edge's band) and, elsewhere, by two.
    const x = s.buffers.positions;
    let e0 = -1;
    for (let e = 0; e < topology.restLength.length && e0 < 0; e++)
      if (direction(e).x < 1e-6 && s.buffers.unfoldedLengths[e] > 1.6 * topology.restLength[e]) e0 = e;
    expect(e0).toBeGreaterThanOrEqual(0);
    const a = 3 * topology.edges[2 * e0];
    const b = 3 * topology.edges[2 * e0 + 1];
    const length = (): number => Math.hypot(x[b] - x[a], x[b + 1] - x[a + 1], x[b + 2] - x[a + 2]);
    for (let i = 1; i < x.length; i += 3) x[i] *= 1.3;
    const stretched = length();
    s.wake();
    s.step();
    // Within its band: the edge is left 30 % long (a free edge there would be pulled most of the way back).
    expect(length() / stretched).toBeGreaterThan(0.97);
    // Past its unfolded length: pulled back to it.
    for (let i = 1; i < x.length; i += 3) x[i] *= 3;
    for (let f = 0; f < 200; f++) {
      s.wake();
      s.step();
    }
    expect(length()).toBeLessThan(1.02 * s.buffers.unfoldedLengths[e0]);
  });

  it('unfolds nothing while the lid is turned no more than LID_FIRM, and where two lids overlap takes the longer', () => {
    const firm = topology.restLength.slice().fill(1);
    new LidSlack(topology, [lid]).compute([LID_FIRM], firm);
    let changed = 0;
    for (let e = 0; e < firm.length; e++) if (firm[e] !== 1 && firm[e] !== topology.restLength[e]) changed++;
    expect(changed).toBe(0);
    // A second lid over the same skin, open: the first one's unfolding stands, in either order.
    const alone = topology.restLength.slice();
    new LidSlack(topology, [lid]).compute([1], alone);
    for (const order of [
      [lid, { ...lid, name: 'other' }],
      [{ ...lid, name: 'other' }, lid],
    ]) {
      const both = topology.restLength.slice();
      new LidSlack(topology, order).compute(order[0] === lid ? [1, 0] : [0, 1], both);
      expect(Array.from(both)).toEqual(Array.from(alone));
    }
  });

  it('takes no edge of an opening lid or of another muscle type', () => {
    const opening: Muscle = { ...lid, maxAngle: -12 };
    expect(new LidSlack(topology, [opening]).edgeCount).toBe(0);
    expect(new LidSlack(topology, []).edgeCount).toBe(0);
  });
});
