import { openFace } from './face';
import { expect, test } from './shared-app';

/**
 * Every Action Unit and every preset at full intensity, on the low-resolution head as the page runs it (solver in the
 * worker): the skin comes to rest, with no NaN and no triangle turned over: its normal against its rest normal and
 * against its corners' solved vertex normals (crumpled skin). Against its rest normal alone would count the lid
 * margin's skin, which a closing lid rolls past edge-on at the eye's corners (src/core/solver/carried-frames.ts);
 * against its neighbours alone, the steep sides of the low head's coarse folds. The medium head gets the check in Node
 * (tests/expressions-settle-*.test.ts, against the frames the solver holds), where it runs without a browser's overhead.
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
      const { rest, positions, normals, triangles } = face.getSkin();
      let nan = 0;
      for (const p of positions) if (!Number.isFinite(p)) nan++;
      let inverted = 0;
      const normal = (p: Float32Array, a: number, b: number, c: number) => {
        const u = [p[b] - p[a], p[b + 1] - p[a + 1], p[b + 2] - p[a + 2]];
        const v = [p[c] - p[a], p[c + 1] - p[a + 1], p[c + 2] - p[a + 2]];
        return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
      };
      for (let t = 0; t < triangles.length; t += 3) {
        const [a, b, c] = [3 * triangles[t], 3 * triangles[t + 1], 3 * triangles[t + 2]];
        const n0 = normal(rest, a, b, c);
        const n1 = normal(positions, a, b, c);
        let againstRest = 0;
        let againstNeighbours = 0;
        for (let k = 0; k < 3; k++) {
          againstRest += n0[k] * n1[k];
          againstNeighbours += n1[k] * (normals[a + k] + normals[b + k] + normals[c + k]);
        }
        if (againstRest < 0 && againstNeighbours < 0) inverted++;
      }
      out.push({ item, settled, nan, inverted });
    }
    return out;
  });
  // 45 Action Units and 12 presets.
  expect(results).toHaveLength(57);
  expect(results.filter((r) => !r.settled || r.nan > 0 || r.inverted > 0)).toEqual([]);
});
