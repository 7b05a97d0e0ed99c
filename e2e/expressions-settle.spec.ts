import { openFace } from './face';
import { expect, test } from './fixtures';

/**
 * Every Action Unit and every preset at full intensity, on the low-resolution head as the page runs it (solver in the
 * worker): the skin comes to rest, with no NaN and no triangle turned over relative to rest. The medium head gets
 * the same check in Node (tests/expressions-settle-*.test.ts), where it runs without a browser's overhead.
 */
test('every Action Unit and preset at full intensity settles with no NaN and no triangle turned over', async ({ page }) => {
  test.setTimeout(600_000);
  await openFace(page, '/?resolution=low');
  const results = await page.evaluate(async () => {
    const face = window.face;
    const items = [...face.listActionUnits().map((au) => au.id), ...face.listPresets().map((p) => p.name)];
    const out: { item: string; settled: boolean; nan: number; inverted: number }[] = [];
    for (const item of items) {
      face.reset();
      if (item.startsWith('AU')) face.setActionUnit(item, 1);
      else face.applyPreset(item, 1);
      let settled = true;
      try {
        await face.settle(60_000);
      } catch {
        settled = false;
      }
      const { rest, positions, triangles } = face.getSkin();
      let nan = 0;
      for (const p of positions) if (!Number.isFinite(p)) nan++;
      let inverted = 0;
      const normal = (p: Float32Array, a: number, b: number, c: number) => {
        const u = [p[3 * b] - p[3 * a], p[3 * b + 1] - p[3 * a + 1], p[3 * b + 2] - p[3 * a + 2]];
        const v = [p[3 * c] - p[3 * a], p[3 * c + 1] - p[3 * a + 1], p[3 * c + 2] - p[3 * a + 2]];
        return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
      };
      for (let t = 0; t < triangles.length; t += 3) {
        const n0 = normal(rest, triangles[t], triangles[t + 1], triangles[t + 2]);
        const n1 = normal(positions, triangles[t], triangles[t + 1], triangles[t + 2]);
        if (n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2] < 0) inverted++;
      }
      out.push({ item, settled, nan, inverted });
    }
    return out;
  });
  // 45 Action Units and 12 presets.
  expect(results).toHaveLength(57);
  expect(results.filter((r) => !r.settled || r.nan > 0 || r.inverted > 0)).toEqual([]);
});
