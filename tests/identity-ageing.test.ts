import { beforeAll, describe, expect, it } from 'vitest';
import { checkIdentity } from '../src/core/head/identity';
import { agedSkin } from '../src/core/head/identity-skin';
import { SKIN_DEFAULTS } from '../src/core/solver/skin-parameters';
import { foldDepth, foldMap } from './fixtures/fold-regions';
import { MAX_SETTLE_FRAMES, resetToRest } from './fixtures/head-simulation';
import { loadIdentitySimulation } from './fixtures/identity-simulation';

/** A visible crease and smooth skin, as tests/wrinkles-by-region.test.ts counts them (fold depth, mm). */
const FOLDED = 0.12;
const SMOOTH = 0.06;

/** The regions where expression lines form that an old face's resting pull reaches (see identity-skin.ts). */
const REGIONS = ['forehead', 'glabella', 'crowsFeet'] as const;
type Depths = Record<(typeof REGIONS)[number], number>;

/**
 * A 20- and a 70-year-old of the same sex and ancestry on the medium head, each with the skin its age gives it
 * (src/core/head/identity-skin.ts), settled at rest with its resting pull as the page shows it: the fold depth of
 * each region.
 */
function atRest(sex: number, ancestry: string): Record<20 | 70, Depths & { raised: number }> {
  const out = {} as Record<20 | 70, Depths & { raised: number }>;
  for (const age of [20, 70] as const) {
    const aged = agedSkin(age);
    const sim = loadIdentitySimulation(checkIdentity({ sex, age, ancestry: { [ancestry]: 1 } }, 'test'), 'medium', aged.parameters);
    const { rest, restNormals } = sim.host.topology;
    const map = foldMap(rest, restNormals, sim.triangles);
    const x = sim.host.solver.buffers.positions;
    const settle = () => {
      sim.apply();
      let frames = 0;
      while (frames < MAX_SETTLE_FRAMES && sim.host.step()) frames++;
    };
    resetToRest(sim);
    sim.expression.setResting(aged.tone);
    settle();
    const depths = Object.fromEntries(REGIONS.map((r) => [r, foldDepth(map, map.regions[r], rest, restNormals, x)])) as Depths;
    // Then the brows raised (AU1+AU2), from that rest.
    sim.expression.setActionUnit('AU1', 1);
    sim.expression.setActionUnit('AU2', 1);
    settle();
    out[age] = { ...depths, raised: foldDepth(map, map.regions.forehead, rest, restNormals, x) };
  }
  return out;
}

describe('skin that ages', () => {
  it('thins, loosens and loses its tension with age, and an old face keeps a pull at rest', () => {
    const young = agedSkin(20);
    const old = agedSkin(70);
    expect(old.parameters.wrinkleSpacing).toBeLessThan(0.85 * young.parameters.wrinkleSpacing);
    expect(young.parameters.wrinkleSpacing).toBe(SKIN_DEFAULTS.wrinkleSpacing);
    expect(old.parameters.positionStiffness).toBeLessThan(young.parameters.positionStiffness);
    expect(old.parameters.pretension).toBe(0);
    expect(young.parameters.pretension).toBe(0.15);
    expect(young.tone).toEqual({});
    expect(Object.keys(old.tone).sort()).toEqual(['AU1', 'AU2', 'AU4', 'AU6']);
  });

  // Two of the six pairs of sex and ancestry: each builds and settles two medium heads.
  for (const [sex, ancestry] of [
    [0, 'european'],
    [1, 'african'],
  ] as const) {
    describe(`${sex === 0 ? 'women' : 'men'} of ${ancestry} ancestry, 20 and 70 years`, () => {
      let f: ReturnType<typeof atRest>;
      beforeAll(() => {
        f = atRest(sex, ancestry);
      }, 120_000);

      it.each(REGIONS)('at rest the 70-year-old shows lines in the %s and the 20-year-old none', (region) => {
        expect(f[70][region]).toBeGreaterThan(FOLDED);
        expect(f[20][region]).toBeLessThan(SMOOTH);
      });

      it('under AU1+AU2 the 70-year-old’s forehead folds at least 1.5 times as deep as the 20-year-old’s', () => {
        console.log(`forehead fold depth under AU1+AU2: 20 years ${f[20].raised.toFixed(3)} mm, 70 years ${f[70].raised.toFixed(3)} mm`);
        expect(f[70].raised).toBeGreaterThanOrEqual(1.5 * f[20].raised);
        expect(f[20].raised).toBeGreaterThan(FOLDED);
      });
    });
  }
});
