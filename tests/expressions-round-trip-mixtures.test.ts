import { beforeAll, describe, expect, it } from 'vitest';
import { ACTION_UNITS } from '../src/core/expression/facs';
import { mulberry32 } from '../src/core/random';
import { loadHeadSimulation, MAX_SETTLE_FRAMES, returnToRest } from './fixtures/head-simulation';

// Seeded random mixtures of Action Units (sides set apart) and a preset on the medium head: each settles, and after a
// reset every vertex is back exactly at rest with the active region empty, whatever the mixture pressed against the
// eyes and teeth.
describe('random expression mixtures on the medium head', () => {
  let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
  beforeAll(async () => {
    sim = await loadHeadSimulation('medium');
  });

  it.each([1, 2, 3])('mixture with seed %i settles and returns to rest', (seed) => {
    const random = mulberry32(seed);
    const { expression, apply, host, rig } = sim;
    expression.reset();
    for (const au of ACTION_UNITS) {
      if (random() > 0.35) continue;
      const ids = au.bilateral ? [`${au.id}L`, `${au.id}R`] : [au.id];
      for (const id of ids) expression.setActionUnit(id, 0.3 + 0.7 * random());
    }
    expression.applyPreset(rig.presets[Math.floor(random() * rig.presets.length)].name, random());
    apply();
    let frames = 0;
    while (frames < MAX_SETTLE_FRAMES && host.step()) frames++;
    expect(host.solver.sleeping).toBe(true);
    const back = returnToRest(sim);
    expect(back).toMatchObject({ sleeping: true, offRest: 0, farthest: 0, activeVertices: 0 });
  });
});
