import { beforeAll, describe, expect, it } from 'vitest';
import { computeMuscleTargets } from '../src/core/rig/muscles';
import type { LinearMuscle, Muscle } from '../src/core/rig/rig-types';
import { loadHeadSimulation } from './fixtures/head-simulation';

/** The muscle inputs a fresh rig of `muscles` computes for `contractions` over `rest`. */
function expected(rest: Float32Array, muscles: Muscle[], contractions: Float32Array) {
  const n = rest.length / 3;
  const out = { targets: new Float32Array(3 * n), weights: new Float32Array(n), normalWeights: new Float32Array(n) };
  computeMuscleTargets(rest, muscles, contractions, out);
  return out;
}

// The low head as the worker solves it: rig edits must give exactly the inputs a rig built from the edited muscles gives.
describe('SolverHost rig edits', () => {
  let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
  beforeAll(async () => {
    sim = await loadHeadSimulation('low');
  });

  it('a one-muscle edit recomputes the targets with the last contractions, as a rebuilt rig would', () => {
    const { host, rig, expression, apply } = sim;
    expression.reset();
    expression.setActionUnit('AU12', 1);
    apply();
    const contractions = expression.muscleContractions(rig, new Float32Array(rig.muscles.length));
    const before = host.solver.buffers.targets.slice();
    const index = rig.muscles.findIndex((m) => m.name === 'zygomaticus-major-l');
    const moved = { ...(rig.muscles[index] as LinearMuscle) };
    moved.insertion = [moved.insertion[0] + 0.01, moved.insertion[1] - 0.01, moved.insertion[2]];
    const muscles = rig.muscles.map((m, i) => (i === index ? moved : m));
    host.editRig(1, { index, muscle: moved });
    expect(host.rigRevision).toBe(1);
    const want = expected(host.topology.rest, muscles, contractions);
    expect(Array.from(host.solver.buffers.targets)).toEqual(Array.from(want.targets));
    expect(Array.from(host.solver.buffers.weights)).toEqual(Array.from(want.weights));
    let changed = 0;
    for (let i = 0; i < before.length; i++) if (before[i] !== host.solver.buffers.targets[i]) changed++;
    expect(changed).toBeGreaterThan(30);
    // The skin follows: it is awake and comes to rest elsewhere.
    let frames = 0;
    while (frames < 400 && host.step()) frames++;
    for (const x of host.solver.buffers.positions) expect(Number.isFinite(x)).toBe(true);
    host.editRig(2, { index, muscle: rig.muscles[index] });
  });

  it('a new muscle list takes the contractions of the next batch, and the teeth go back to rest without a jaw', () => {
    const { host, rig, expression, apply, colliders } = sim;
    const restTeeth = structuredClone(colliders.filter((c) => c.name.startsWith('teeth-lower')));
    expression.reset();
    expression.setActionUnit('AU26', 1);
    apply();
    const turned = colliders.find((c) => c.name.startsWith('teeth-lower'))!;
    expect(turned.a).not.toEqual(restTeeth[0].a);
    const muscles = rig.muscles.filter((m) => m.type !== 'jaw' && m.name !== 'mentalis');
    host.editRig(3, { muscles });
    expect(colliders.filter((c) => c.name.startsWith('teeth-lower'))).toEqual(restTeeth);
    const contractions = new Float32Array(256);
    muscles.forEach((m, i) => (contractions[i] = m.name.startsWith('zygomaticus') ? 0.7 : 0));
    host.apply(100, null, null, contractions);
    const want = expected(host.topology.rest, muscles, contractions.subarray(0, muscles.length));
    expect(Array.from(host.solver.buffers.targets)).toEqual(Array.from(want.targets));
  });
});
