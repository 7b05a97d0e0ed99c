import { beforeAll, describe, expect, it } from 'vitest';
import { LATE_MOTION } from '../src/core/solver/solver-schedule';
import { loadHeadSimulation, MAX_SETTLE_FRAMES, resetToRest, type Resolution } from './fixtures/head-simulation';
import { FrontSampler, foldLines, regionFolds, type FoldRegion, type RegionFolds } from './fixtures/region-folds';

// The high head (the medium one subdivided once) folded like paper where its mesh is finest: crow's feet 4.0 mm apart
// with 46 % of their power under 4 mm, the chin under AU17 3.3 mm and 67 %, under the lower lip with AU15 33 % (the
// medium head: 7.6 mm and 4 %, 5.7 mm and 16 %, 14 %). Bending two rings out where the first ring cannot bend stiffly
// enough (src/core/solver/second-ring.ts) gives 9.1 mm and 7 %, 6.7 mm and 15 %, 7 % (docs/solver-notes.md).
//
// Every region the folds are read in, under its Action Units. `folds`: the high head folds there (not left smooth);
// `sameSpacing`: its folds are within a quarter of the medium head's spacing. Where either is false it does not hold
// yet (high head, 2026-12-06): AU9 leaves the nose root all but smooth (0.02 mm; the medium head 0.10), disgust the
// skin under the lower lip nearly so (0.058 mm, 14.1 mm apart; the medium head 0.10 mm, 12.4 mm apart), and the
// nasolabial folds (14.0 and 14.2 mm against 10.8 and 10.7), the nose root (17.5 against 10.4) and above the upper lip
// under AU18 (19.8 against 10.4) are longer than the medium head's.
const CASES: { region: FoldRegion; under: string; folds: boolean; sameSpacing: boolean }[] = [
  { region: 'forehead', under: 'AU1+AU2', folds: true, sameSpacing: true },
  { region: 'glabella', under: 'AU4', folds: true, sameSpacing: true },
  { region: 'noseRoot', under: 'AU9', folds: false, sameSpacing: false },
  { region: 'crowsFeet', under: 'AU6', folds: true, sameSpacing: true },
  { region: 'crowsFeet', under: 'happiness', folds: true, sameSpacing: true },
  { region: 'nasolabial', under: 'AU12', folds: true, sameSpacing: false },
  { region: 'nasolabial', under: 'happiness', folds: true, sameSpacing: false },
  { region: 'chin', under: 'AU17', folds: true, sameSpacing: true },
  { region: 'underLowerLip', under: 'AU15', folds: true, sameSpacing: true },
  { region: 'underLowerLip', under: 'AU16', folds: true, sameSpacing: true },
  { region: 'underLowerLip', under: 'disgust', folds: false, sameSpacing: true },
  { region: 'aboveUpperLip', under: 'AU18', folds: true, sameSpacing: false },
];
/** Real wrinkles are at least this far apart (mm), and skin, not paper, keeps at most this share of its folds' power under 4 mm. */
const SHORTEST_WRINKLES = 6;
const MOST_GRAIN = 0.2;
/** Skin whose folds' root mean square is under this (mm) is smooth (as tests/wrinkles-by-region.test.ts reads it). */
const SMOOTH = 0.06;
/** The fine head's folds are within this share of the medium head's spacing. */
const SAME_SPACING = 0.25;

/** How an expression came to rest: frames solved, whether the solver slept, triangles turned over at the end. */
interface Settle {
  frames: number;
  sleeping: boolean;
  inverted: number;
}

/**
 * Each case's folds on a head, each expression at full intensity from rest (solved once), as the page solves it, and
 * how each expression came to rest.
 */
async function foldsOn(resolution: Resolution): Promise<{ folds: RegionFolds[]; settles: Map<string, Settle> }> {
  const sim = await loadHeadSimulation(resolution);
  const { rest, restNormals } = sim.host.topology;
  const sampler = new FrontSampler(rest, restNormals, sim.triangles);
  const lines = foldLines(rest, sim.triangles);
  const settled = new Map<string, Float32Array>();
  const settles = new Map<string, Settle>();
  const folds = CASES.map(({ region, under }) => {
    let x = settled.get(under);
    if (!x) {
      resetToRest(sim);
      for (const item of under.split('+')) {
        if (item.startsWith('AU')) sim.expression.setActionUnit(item, 1);
        else sim.expression.applyPreset(item, 1);
      }
      sim.apply();
      let frames = 0;
      while (frames < MAX_SETTLE_FRAMES && sim.host.step()) frames++;
      x = Float32Array.from(sim.host.solver.buffers.positions);
      settled.set(under, x);
      settles.set(under, { frames, sleeping: sim.host.solver.sleeping, inverted: sim.host.solver.turnedOverCount() });
    }
    return regionFolds(sampler, lines[region], x);
  });
  return { folds, settles };
}

describe('the high head folds as skin where its mesh is finest', () => {
  let medium: RegionFolds[];
  let high: RegionFolds[];
  let highSettles: Map<string, Settle>;
  beforeAll(async () => {
    medium = (await foldsOn('medium')).folds;
    ({ folds: high, settles: highSettles } = await foldsOn('high'));
  }, 240_000);

  // The same solves say how the high head came to rest under each expression (one it shares with
  // tests/expressions-settle-high-mouth-corners.test.ts, happiness, and ten the others leave out).
  it.each([...new Set(CASES.map((c) => c.under))])('%s on the high head comes to rest by converging, no triangle turned over', (under) => {
    const settle = highSettles.get(under)!;
    expect(settle).toMatchObject({ sleeping: true, inverted: 0 });
    expect(settle.frames, 'frames, not stopped by the safety net').toBeLessThan(LATE_MOTION);
  });

  it.each(CASES.map((c, k) => ({ ...c, k })))("$region under $under: real wrinkles' spacing, no crumpling", ({ k }) => {
    expect(high[k].wavelength, 'dominant wavelength (mm)').toBeGreaterThanOrEqual(SHORTEST_WRINKLES);
    expect(high[k].shortShare, 'share of the power under 4 mm').toBeLessThanOrEqual(MOST_GRAIN);
  });

  it.each(CASES.map((c, k) => ({ ...c, k })).filter((c) => c.folds))('$region under $under: folds, not skin left smooth', ({ k }) => {
    // The fold tests' smooth skin is under 0.06 mm; the crow's feet, chin and under the lower lip with AU15 fold 0.14,
    // 0.20 and 0.10 mm, against the medium head's 0.44, 0.43 and 0.33 (0.25, 0.22 and 0.11 before, crumpled).
    expect(high[k].amplitude, 'root mean square (mm)').toBeGreaterThanOrEqual(SMOOTH);
  });

  it.each(CASES.map((c, k) => ({ ...c, k })).filter((c) => c.sameSpacing))(
    '$region under $under: as far apart as on the medium head',
    ({ k }) => {
      expect(Math.abs(high[k].wavelength / medium[k].wavelength - 1), 'against the medium head').toBeLessThanOrEqual(SAME_SPACING);
    },
  );
});
