import { openFace } from './face';
import { expect, test } from './fixtures';

/**
 * Action Units move the skin where FACS says they do. Landmarks are the skin vertices nearest points on the default
 * head (metres): the lip corners (the zygomaticus major's insertions), the inner brows (the inner frontalis'), the chin.
 */
const LANDMARKS = {
  lipCornerL: [0.0255, 0.6608, 0.1419],
  lipCornerR: [-0.0255, 0.6608, 0.1419],
  innerBrowL: [0.017, 0.753, 0.1496],
  innerBrowR: [-0.017, 0.753, 0.1496],
  chin: [0, 0.625, 0.1466],
} as const;
type Landmark = keyof typeof LANDMARKS;

/** Sets one Action Unit to full on a neutral face, settles, and returns each landmark's movement (dx, dy, dz in mm). */
async function actionUnitMoves(page: import('@playwright/test').Page, id: string): Promise<Record<Landmark, number[]>> {
  return page.evaluate(
    async ({ id, landmarks }) => {
      const face = window.face;
      face.reset();
      face.setActionUnit(id, 1);
      await face.settle(60_000);
      const { rest, positions } = face.getSkin();
      const out: Record<string, number[]> = {};
      for (const [name, p] of Object.entries(landmarks)) {
        let best = 0;
        let bestD = Infinity;
        for (let v = 0; v < rest.length / 3; v++) {
          const d = Math.hypot(rest[3 * v] - p[0], rest[3 * v + 1] - p[1], rest[3 * v + 2] - p[2]);
          if (d < bestD) {
            bestD = d;
            best = v;
          }
        }
        out[name] = [0, 1, 2].map((k) => 1000 * (positions[3 * best + k] - rest[3 * best + k]));
      }
      return out as Record<Landmark, number[]>;
    },
    { id, landmarks: LANDMARKS },
  );
}

test.beforeEach(async ({ page }) => {
  await openFace(page, '/');
});

test('AU12L lifts the left lip corner up and outward while the right one stays', async ({ page }) => {
  const m = await actionUnitMoves(page, 'AU12L');
  expect(m.lipCornerL[1]).toBeGreaterThan(1); // up, mm
  expect(m.lipCornerL[0]).toBeGreaterThan(0.5); // outward: the subject's left is +x
  expect(Math.hypot(...m.lipCornerR)).toBeLessThan(0.5);
  expect(await page.evaluate(() => window.face.getActionUnits())).toMatchObject({ AU12L: 1, AU12R: 0 });
});

test('AU1 raises both inner brows', async ({ page }) => {
  const m = await actionUnitMoves(page, 'AU1');
  expect(m.innerBrowL[1]).toBeGreaterThan(1);
  expect(m.innerBrowR[1]).toBeGreaterThan(1);
});

test('AU26 lowers the chin', async ({ page }) => {
  const m = await actionUnitMoves(page, 'AU26');
  expect(m.chin[1]).toBeLessThan(-4);
});

test('an unknown Action Unit or a NaN intensity throws naming it and changes nothing', async ({ page }) => {
  const result = await page.evaluate(() => {
    const face = window.face;
    face.setActionUnit('AU2', 0.5);
    const errors: string[] = [];
    for (const call of [() => face.setActionUnit('AU99', 1), () => face.setActionUnit('AU4', Number.NaN)]) {
      try {
        call();
      } catch (e) {
        errors.push((e as Error).message);
      }
    }
    return { errors, units: face.getActionUnits() };
  });
  expect(result.errors).toHaveLength(2);
  expect(result.errors[0]).toContain('AU99');
  expect(result.errors[1]).toContain('NaN');
  expect(result.units).toMatchObject({ AU2L: 0.5, AU2R: 0.5, AU4L: 0, AU4R: 0 });
});
