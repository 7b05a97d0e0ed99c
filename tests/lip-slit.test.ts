import { beforeAll, describe, expect, it } from 'vitest';
import { DEFAULT_LANDMARKS } from '../src/core/head/landmarks';
import { findLipSlit, type LipSlit } from '../src/core/head/lip-slit';
import { loadHeadSimulation, resetToRest } from './fixtures/head-simulation';

type Simulation = Awaited<ReturnType<typeof loadHeadSimulation>>;

/** The lips' gap (mm) at the slit's two vertices in the solved skin after `item` at full intensity. */
function gapUnder(sim: Simulation, slit: LipSlit, item: string): number {
  resetToRest(sim);
  sim.expression.setActionUnit(item, 1);
  sim.apply();
  for (let k = 0; k < 1500 && sim.host.step(); k++);
  const x = sim.host.solver.buffers.positions;
  const [u, l] = [3 * slit.upper, 3 * slit.lower];
  return 1000 * Math.hypot(x[u] - x[l], x[u + 1] - x[l + 1], x[u + 2] - x[l + 2]);
}

describe('the mouth slit: the lips at the midline', () => {
  let sim: Simulation;
  let slit: LipSlit;
  beforeAll(async () => {
    sim = await loadHeadSimulation('medium');
    // The simulation's rest in simulation order stands for the render vertices: the slit lies on no uv seam.
    slit = findLipSlit(sim.host.topology.rest, sim.host.topology.restNormals, DEFAULT_LANDMARKS['mouth-l'], DEFAULT_LANDMARKS['mouth-r'])!;
  }, 120_000);

  it('finds one vertex on each lip at the midline, the upper above the lower, under 2 mm apart at rest', () => {
    expect(slit).not.toBeNull();
    const x = sim.host.topology.rest;
    expect(Math.abs(x[3 * slit.upper])).toBeLessThan(0.002);
    expect(Math.abs(x[3 * slit.lower])).toBeLessThan(0.002);
    expect(x[3 * slit.upper + 1]).toBeGreaterThan(x[3 * slit.lower + 1]);
    const [u, l] = [3 * slit.upper, 3 * slit.lower];
    expect(1000 * Math.hypot(x[u] - x[l], x[u + 1] - x[l + 1], x[u + 2] - x[l + 2])).toBeLessThan(2);
  });

  it('opens as the lips part (AU25) and the jaw drops (AU26)', () => {
    expect(gapUnder(sim, slit, 'AU25')).toBeGreaterThan(3.5);
    expect(gapUnder(sim, slit, 'AU26')).toBeGreaterThan(10);
  });
});
