import { openFace } from './face';
import { expect, test } from './shared-app';

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
      await face.settle(150_000);
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

/** The left eye's centre on the default head (metres). */
const EYE_L = [0.0308, 0.7284, 0.1245] as const;

// The medium head solves a frame in about 35 ms here and an expression may take a few hundred frames to settle.
test.describe.configure({ timeout: 240_000 });

// One page of the app as it opens (the default head) for the five units: each starts from a reset, and a page load of
// the medium head is 5 s of the machine's time.
test('Action Units move the skin where FACS says: AU12L, AU1, AU26, AU18 and AU43 on the default head', async ({ page }) => {
  await openFace(page, '/');
  await test.step('AU12L lifts the left lip corner up and outward while the right one stays', async () => {
    const m = await actionUnitMoves(page, 'AU12L');
    expect(m.lipCornerL[1]).toBeGreaterThan(1); // up, mm
    expect(m.lipCornerL[0]).toBeGreaterThan(0.5); // outward: the subject's left is +x
    expect(Math.hypot(...m.lipCornerR)).toBeLessThan(0.5);
    expect(await page.evaluate(() => window.face.getActionUnits())).toMatchObject({ AU12L: 1, AU12R: 0 });
  });
  await test.step('AU1 raises both inner brows', async () => {
    const m = await actionUnitMoves(page, 'AU1');
    expect(m.innerBrowL[1]).toBeGreaterThan(1);
    expect(m.innerBrowR[1]).toBeGreaterThan(1);
  });
  await test.step('AU26 lowers the chin', async () => {
    const m = await actionUnitMoves(page, 'AU26');
    expect(m.chin[1]).toBeLessThan(-4);
  });
  await test.step('AU18 draws both lip corners toward the middle of the mouth', async () => {
    const m = await actionUnitMoves(page, 'AU18');
    expect(m.lipCornerL[0]).toBeLessThan(-2); // the left corner (+x) moves toward x = 0
    expect(m.lipCornerR[0]).toBeGreaterThan(2);
  });
  await test.step('AU43 brings the upper lids down to the lower lids', () => lidsClose(page));
});

/** AU43 brings the upper lids down to the lower lids (see the test above). */
async function lidsClose(page: import('@playwright/test').Page): Promise<void> {
  // Across the middle of the left eye (every 4 mm from 4 mm inside to 4 mm outside its centre), the vertical opening
  // between the lid margins: the two skin vertices at rest either side of the widest gap in front of the eye.
  const openings = await page.evaluate(
    async ({ eye }) => {
      const face = window.face;
      const measure = () => {
        const { rest, positions } = face.getSkin();
        return [-0.004, 0, 0.004].map((dx) => {
          const near: number[] = [];
          for (let v = 0; v < rest.length / 3; v++) {
            if (
              Math.abs(rest[3 * v] - eye[0] - dx) < 0.0015 &&
              rest[3 * v + 2] > eye[2] + 0.005 &&
              Math.abs(rest[3 * v + 1] - eye[1]) < 0.006
            )
              near.push(v);
          }
          near.sort((a, b) => rest[3 * a + 1] - rest[3 * b + 1]);
          let gap = 0;
          let upper = -1;
          let lower = -1;
          for (let k = 1; k < near.length; k++) {
            const g = rest[3 * near[k] + 1] - rest[3 * near[k - 1] + 1];
            if (g > gap) [gap, upper, lower] = [g, near[k], near[k - 1]];
          }
          return 1000 * (positions[3 * upper + 1] - positions[3 * lower + 1]);
        });
      };
      face.reset();
      await face.settle(150_000);
      const open = measure();
      face.setActionUnit('AU43', 1);
      await face.settle(150_000);
      return { open, closed: measure() };
    },
    { eye: EYE_L },
  );
  for (const mm of openings.open) expect(mm).toBeGreaterThan(5);
  // Closed: the margins meet within a millimetre and a half (a little overlap is a closed eye too).
  for (const mm of openings.closed) expect(Math.abs(mm)).toBeLessThan(1.5);
}

test('an unknown Action Unit or a NaN intensity throws naming it and changes nothing', async ({ page }) => {
  await openFace(page, '/?resolution=low');
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
