import { beforeAll, describe, expect, it } from 'vitest';
import { agedSkin } from '../src/core/head/identity-skin';
import { stockIdentities } from '../src/core/head/identity';
import { DEFAULT_LANDMARKS, type Landmarks, LANDMARK_NAMES } from '../src/core/head/landmarks';
import { type ThinPlateWarp, warpPoint } from '../src/core/head/thin-plate';
import { MAX_SETTLE_FRAMES, loadHeadSimulation, type simulationOf } from './fixtures/head-simulation';
import { loadIdentitySimulation } from './fixtures/identity-simulation';

/**
 * Every stock identity's head (built from the base mesh and MakeHuman's targets, the default rig carried over by the
 * warp, as the identity worker builds it) expresses as the default head does: AU12 lifts its lip corners and AU1 its
 * inner brows by amounts within 30 % of the default head's, relative to the size of the face (its height from the
 * brows to the chin), and up. Each head is measured at its own landmarks (the default head's, carried over by the
 * same warp as the rig, as `describeHead().landmarks` gives them in the page): the skin vertices nearest the mouth
 * corners and the chin, and the skin around the inner brows (the brow landmarks 40 % of the way to the midline). The
 * reference is the default head with the skin of the person's age (its parameters and resting pull), so that what is
 * compared is the shapes and the rig carried over to them. The low head: the comparison holds at every resolution
 * and this one settles the expressions fastest.
 */

/** How far around an inner brow's point its skin is taken (m): about a brow's height, over the low head's spacing. */
const BROW_RADIUS = 0.006;

type Simulation = ReturnType<typeof simulationOf>;
interface Lift {
  /** The mean movement of the pair of points over the face's height. */
  amount: number;
  /** The mean of their vertical movements (m). */
  up: number;
}
type Lifts = { au12: Lift; au1: Lift };

/** The default head's landmarks, carried over to a person's head by the warp that carries the rig (as the page does). */
function landmarksOf(warp: ThinPlateWarp | null): Landmarks {
  if (!warp) return DEFAULT_LANDMARKS as Landmarks;
  return Object.fromEntries(LANDMARK_NAMES.map((n) => [n, warpPoint(warp, DEFAULT_LANDMARKS[n])])) as Landmarks;
}

/** Steps until the skin sleeps; fails the test if it does not within MAX_SETTLE_FRAMES. */
function settle(sim: Simulation): void {
  sim.apply();
  let frames = 0;
  while (frames < MAX_SETTLE_FRAMES && sim.host.step()) frames++;
  expect(sim.host.solver.sleeping, 'the skin came to rest').toBe(true);
}

/** AU12's and AU1's lifts on a head with its age's resting pull, each from the face at rest with that pull. */
function lifts(sim: Simulation, l: Landmarks): Lifts {
  const rest = sim.host.topology.rest;
  const count = rest.length / 3;
  const distance = (v: number, p: readonly number[]) => Math.hypot(rest[3 * v] - p[0], rest[3 * v + 1] - p[1], rest[3 * v + 2] - p[2]);
  const nearest = (p: readonly number[]): number => {
    let best = 0;
    for (let v = 1; v < count; v++) if (distance(v, p) < distance(best, p)) best = v;
    return best;
  };
  // A mouth corner is one vertex; an inner brow is a patch of skin: the vertices within BROW_RADIUS of the point, each
  // weighted by how near it is (on the low head one vertex stands for 4 to 5 mm, and which one is nearest a point
  // moves with the head's shape).
  const around = (p: readonly number[]): [number, number][] => {
    const out: [number, number][] = [];
    for (let v = 0; v < count; v++) if (distance(v, p) < BROW_RADIUS) out.push([v, 1 - distance(v, p) / BROW_RADIUS]);
    return out.length > 0 ? out : [[nearest(p), 1]];
  };
  const inner = (p: readonly number[]): number[] => [0.6 * p[0], p[1], p[2]];
  const chin = nearest(l.chin);
  const height = Math.abs((l['brow-l'][1] + l['brow-r'][1]) / 2 - rest[3 * chin + 1]);
  const lift = (id: string, pair: [number, number][][]): Lift => {
    // From the head's rest shape: the unit at full intensity is its muscles fully contracted, an old face's resting
    // pull included.
    sim.expression.reset();
    sim.expression.setActionUnit(id, 1);
    settle(sim);
    const x = sim.host.solver.buffers.positions;
    const moves = pair.map((patch) => {
      const m = [0, 0, 0];
      let total = 0;
      for (const [v, w] of patch) {
        for (let k = 0; k < 3; k++) m[k] += w * (x[3 * v + k] - rest[3 * v + k]);
        total += w;
      }
      return m.map((c) => c / total);
    });
    const moved = moves.map((m) => Math.hypot(m[0], m[1], m[2]));
    return { amount: (moved[0] + moved[1]) / 2 / height, up: (moves[0][1] + moves[1][1]) / 2 };
  };
  return {
    au12: lift(
      'AU12',
      [l['mouth-l'], l['mouth-r']].map((p) => [[nearest(p), 1]]),
    ),
    au1: lift('AU1', [inner(l['brow-l']), inner(l['brow-r'])].map(around)),
  };
}

/** Gives a head its age's skin: the parameters it was made with, and the resting pull set and settled. */
function aged<S extends Simulation>(sim: S, age: number): S {
  sim.expression.setResting(agedSkin(age).tone);
  settle(sim);
  return sim;
}

describe('stock identities express as the default head does (low head)', () => {
  const people = stockIdentities();
  const references = new Map<number, Lifts>();
  beforeAll(async () => {
    for (const age of new Set(people.map((p) => p.identity.age))) {
      const sim = aged(await loadHeadSimulation('low', agedSkin(age).parameters), age);
      references.set(age, lifts(sim, landmarksOf(null)));
    }
  }, 120_000);

  it('has the twelve people and, on the default head of each age, AU12 and AU1 lift by a millimetre at least', () => {
    expect(people.length).toBeGreaterThanOrEqual(12);
    for (const [age, r] of references) {
      expect(r.au12.up, `AU12 at ${age}`).toBeGreaterThan(0.001);
      expect(r.au1.up, `AU1 at ${age}`).toBeGreaterThan(0.001);
    }
  });

  it.each(people.map((p) => [p.name, p.identity] as const))(
    '%s lifts its lip corners under AU12 and its inner brows under AU1 within 30 % of the default head',
    (_name, identity) => {
      const sim = aged(loadIdentitySimulation(identity, 'low', agedSkin(identity.age).parameters), identity.age);
      const m = lifts(sim, landmarksOf(sim.warp));
      const reference = references.get(identity.age)!;
      for (const id of ['au12', 'au1'] as const) {
        expect.soft(m[id].up, `${id} lifts`).toBeGreaterThan(0.5 * reference[id].up);
        expect.soft(m[id].amount / reference[id].amount, id).toBeGreaterThan(0.7);
        expect.soft(m[id].amount / reference[id].amount, id).toBeLessThan(1.3);
      }
    },
  );
});
