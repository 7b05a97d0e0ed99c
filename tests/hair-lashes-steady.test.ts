import { describe, expect, it } from 'vitest';
import { placeLashes } from '../src/core/hair/hair-placement';
import { DEFAULT_LANDMARKS } from '../src/core/head/landmarks';
import { loadHeadSkin } from './fixtures/head';
import { rootsAndDirections } from './fixtures/hair';
import { loadHeadSimulation } from './fixtures/head-simulation';

/** Degrees between two unit vectors stored at `k` in `a` and `b` (xyz each). */
function angle(a: Float32Array, b: Float32Array, k: number): number {
  const dot = a[3 * k] * b[3 * k] + a[3 * k + 1] * b[3 * k + 1] + a[3 * k + 2] * b[3 * k + 2];
  return (Math.acos(Math.min(1, dot)) * 180) / Math.PI;
}

/**
 * Lashes grow from the lids' tarsal plates, which are stiff and slide over the eyeball: an Action Unit that bunches
 * the skin at the lid margin (AU4 pushes the upper lid down, AU7 tightens the lids, anger does both) turns a lash with
 * its lid, not its own way. Each lash's turn from its direction at rest is compared with its lid's turn there (its
 * root's turn about the eye's centre), on the medium head.
 */
describe('lashes under Action Units that bunch the lid margin (medium head)', () => {
  it.each([['AU4'], ['AU7'], ['anger']])(
    '%s turns no lash more than 25 degrees beyond its lid',
    async (expression) => {
      const skin = await loadHeadSkin('medium');
      const eyes = [skin.pivots['eye-l'], skin.pivots['eye-r']].map((centre) => ({ centre, radius: skin.eyeRadius }));
      const lashes = placeLashes({ positions: skin.positions, normals: skin.normals, triangles: skin.indices }, DEFAULT_LANDMARKS, eyes);
      expect(lashes.count).toBeGreaterThan(100);
      const sim = await loadHeadSimulation('medium');
      const map = sim.host.topology.renderToSim;
      const render = (values: Float32Array): Float32Array => {
        const out = new Float32Array(3 * map.length);
        for (let r = 0; r < map.length; r++) out.set(values.subarray(3 * map[r], 3 * map[r] + 3), 3 * r);
        return out;
      };
      const { positions, normals } = sim.host.solver.buffers;
      const rest = rootsAndDirections(lashes, render(positions), render(normals));
      if (expression.startsWith('AU')) sim.expression.setActionUnit(expression, 1);
      else sim.expression.applyPreset(expression, 1);
      sim.apply();
      sim.host.run(600);
      expect(sim.host.solver.sleeping).toBe(true);
      const now = rootsAndDirections(lashes, render(positions), render(normals));

      const radius = new Float32Array(3 * lashes.count);
      const radiusNow = new Float32Array(3 * lashes.count);
      for (let k = 0; k < lashes.count; k++) {
        const x = rest.roots[3 * k];
        const centre = eyes.reduce((a, b) => (Math.abs(a.centre[0] - x) < Math.abs(b.centre[0] - x) ? a : b)).centre;
        for (const [roots, into] of [
          [rest.roots, radius],
          [now.roots, radiusNow],
        ]) {
          const d = [0, 1, 2].map((c) => roots[3 * k + c] - centre[c]);
          const l = Math.hypot(d[0], d[1], d[2]);
          for (let c = 0; c < 3; c++) into[3 * k + c] = d[c] / l;
        }
      }
      let beyond = 0;
      let turned = 0;
      for (let k = 0; k < lashes.count; k++) {
        const lid = angle(radius, radiusNow, k);
        const lash = angle(rest.directions, now.directions, k);
        turned = Math.max(turned, lash);
        beyond = Math.max(beyond, lash - lid);
      }
      expect(turned).toBeGreaterThan(1); // the lids do move
      expect(beyond).toBeLessThan(25);
    },
    60_000,
  );
});
