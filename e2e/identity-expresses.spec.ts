import type { Page } from '@playwright/test';
import { agedSkin } from '../src/core/head/identity-skin';
import { openFace } from './face';
import { expect, test } from './fixtures';

/**
 * Every stock identity's head (built in the page from the base mesh and MakeHuman's targets) expresses as the default
 * head does: AU12 lifts its lip corners and AU1 its inner brows by amounts within 30 % of the default head's, relative
 * to the size of the face (its height from the brows to the chin), and up. Each head is measured at its own landmarks
 * (`describeHead().landmarks`: found on the default head, carried over to a person's by the same warp as the rig): the
 * skin vertices nearest the mouth corners and the chin, and the skin around the inner brows (the brow landmarks 40 % of
 * the way to the midline).
 */

/** How far around an inner brow's point its skin is taken (m): about a brow's height, over the low head's spacing. */
const BROW_RADIUS = 0.006;

/**
 * How far a pair of points moves under an Action Unit (the mean), over the face's height (brows to chin), and the
 * mean of their vertical movements (m).
 */
async function lift(page: Page, id: string, points: 'mouth' | 'brows'): Promise<{ amount: number; up: number }> {
  return page.evaluate(
    async ({ id, points, radius }) => {
      const face = window.face;
      const l = face.describeHead().landmarks;
      const { rest } = face.getSkin();
      const nearest = (p: readonly number[]): number => {
        let best = 0;
        let bestD = Infinity;
        for (let v = 0; v < rest.length / 3; v++) {
          const d = Math.hypot(rest[3 * v] - p[0], rest[3 * v + 1] - p[1], rest[3 * v + 2] - p[2]);
          if (d < bestD) [best, bestD] = [v, d];
        }
        return best;
      };
      // A mouth corner is one vertex; an inner brow is a patch of skin: the vertices within BROW_RADIUS of the point,
      // each weighted by how near it is (on the low head one vertex stands for 4 to 5 mm, and which one is nearest a
      // point moves with the head's shape).
      const around = (p: readonly number[]): [number, number][] => {
        const out: [number, number][] = [];
        for (let v = 0; v < rest.length / 3; v++) {
          const d = Math.hypot(rest[3 * v] - p[0], rest[3 * v + 1] - p[1], rest[3 * v + 2] - p[2]);
          if (d < radius) out.push([v, 1 - d / radius]);
        }
        return out.length > 0 ? out : [[nearest(p), 1]];
      };
      const inner = (p: readonly number[]): number[] => [0.6 * p[0], p[1], p[2]];
      const pair =
        points === 'mouth'
          ? [l['mouth-l'], l['mouth-r']].map((p) => [[nearest(p), 1]] as [number, number][])
          : [inner(l['brow-l']), inner(l['brow-r'])].map(around);
      const chin = nearest(l.chin);
      // From the head's rest shape: the unit at full intensity is its muscles fully contracted, an old face's resting
      // pull (src/core/head/identity-skin.ts) included.
      const neutral = rest;
      face.reset();
      face.setActionUnit(id, 1);
      await face.settle(120_000);
      const { positions } = face.getSkin();
      // Each point's move: the weighted mean of its vertices' (FACS's AU12 pulls the corners up and out, AU1 the inner
      // brows up and in).
      const moves = pair.map((patch) => {
        const m = [0, 0, 0];
        let total = 0;
        for (const [v, w] of patch) {
          for (let k = 0; k < 3; k++) m[k] += w * (positions[3 * v + k] - neutral[3 * v + k]);
          total += w;
        }
        return m.map((x) => x / total);
      });
      const moved = moves.map((m) => Math.hypot(m[0], m[1], m[2]));
      const browHeight = (l['brow-l'][1] + l['brow-r'][1]) / 2;
      const up = (moves[0][1] + moves[1][1]) / 2;
      return { amount: (moved[0] + moved[1]) / 2 / Math.abs(browHeight - rest[3 * chin + 1]), up };
    },
    { id, points, radius: BROW_RADIUS },
  );
}

test.describe.configure({ timeout: 600_000 });

test('every stock identity lifts its lip corners under AU12 and its inner brows under AU1 as the default head does, within 30 %', async ({
  page,
}) => {
  await openFace(page, '/?resolution=low');
  type Moves = { au12: { amount: number; up: number }; au1: { amount: number; up: number } };
  const measure = async (): Promise<Moves> => ({ au12: await lift(page, 'AU12', 'mouth'), au1: await lift(page, 'AU1', 'brows') });
  const people = await page.evaluate(() => window.face.listIdentities());
  expect(people.length).toBeGreaterThanOrEqual(12);
  // The default head with the skin of each age (its parameters, and its resting pull as an overlay): what a person's
  // head of that age is compared with, so that the comparison is of the shapes and the rig carried over to them.
  const references = new Map<number, Moves>();
  for (const age of new Set(people.map((p) => p.identity.age))) {
    const skin = agedSkin(age);
    await page.evaluate((skin) => {
      window.face.setSkinParameters(skin.parameters);
      window.face.setOverlay(Object.keys(skin.tone), Object.values(skin.tone));
    }, skin);
    const reference = await measure();
    // Up by a millimetre at least on the default head.
    expect(reference.au12.up).toBeGreaterThan(0.001);
    expect(reference.au1.up).toBeGreaterThan(0.001);
    references.set(age, reference);
  }
  await page.evaluate(() => window.face.clearOverlay());
  const rows: string[] = [];
  for (const { name, identity } of people) {
    const head = await page.evaluate(async (name) => {
      const h = await window.face.setIdentity(name);
      return { source: h.source, name: h.name, level: h.level };
    }, name);
    expect(head).toEqual({ source: 'identity', name, level: 'low' });
    const reference = references.get(identity.age)!;
    const m = await measure();
    const ratio = { au12: m.au12.amount / reference.au12.amount, au1: m.au1.amount / reference.au1.amount };
    rows.push(`${name}: AU12 ${ratio.au12.toFixed(2)}, AU1 ${ratio.au1.toFixed(2)} of the default head's`);
    for (const id of ['au12', 'au1'] as const) {
      expect.soft(m[id].up, `${name} ${id} lifts`).toBeGreaterThan(0.5 * reference[id].up);
      expect.soft(ratio[id], `${name} ${id}`).toBeGreaterThan(0.7);
      expect.soft(ratio[id], `${name} ${id}`).toBeLessThan(1.3);
    }
  }
  console.log(rows.join('\n'));
});
