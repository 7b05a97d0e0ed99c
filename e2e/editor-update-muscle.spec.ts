import { openFace } from './face';
import { expect, test } from './shared-app';

/**
 * Smiles with AU12, then moves the left zygomaticus major's insertion through the handle: the left lip corner comes
 * to rest elsewhere, without a reload, and undo brings the rig back exactly and the corner back to where it was.
 */
test("updateMuscle moves AU12's lip corner on the live skin, undo restores it, and bad values are refused", async ({ page }) => {
  test.setTimeout(120_000);
  await openFace(page, '/?resolution=low');
  const result = await page.evaluate(async () => {
    const face = window.face;
    (window as unknown as { marker: number }).marker = 1;
    const original = face.getRig();
    face.setActionUnit('AU12', 1);
    await face.settle(45_000);
    const { rest, positions } = face.getSkin();
    // The left lip corner: the vertex AU12 moved farthest on the subject's left (+x).
    let corner = -1;
    let farthest = 0;
    for (let v = 0; v < rest.length / 3; v++) {
      const d = Math.hypot(positions[3 * v] - rest[3 * v], positions[3 * v + 1] - rest[3 * v + 1], positions[3 * v + 2] - rest[3 * v + 2]);
      if (rest[3 * v] > 0.01 && d > farthest) [corner, farthest] = [v, d];
    }
    const at = (p: Float32Array, v: number) => [p[3 * v], p[3 * v + 1], p[3 * v + 2]];
    const smile = at(positions, corner);
    const mirrorVertex = (() => {
      let best = -1;
      let bestD = Infinity;
      for (let v = 0; v < rest.length / 3; v++) {
        const d = Math.hypot(
          rest[3 * v] + rest[3 * corner],
          rest[3 * v + 1] - rest[3 * corner + 1],
          rest[3 * v + 2] - rest[3 * corner + 2],
        );
        if (d < bestD) [best, bestD] = [v, d];
      }
      return best;
    })();
    const rightSmile = at(positions, mirrorVertex);

    const errors: string[] = [];
    for (const partial of [{ insertion: [Number.NaN, 0.66, 0.14] }, { insertion: [1e6, 0.66, 0.14] }, { strength: 'strong' }]) {
      try {
        face.updateMuscle('zygomaticus-major-l', partial as never);
      } catch (e) {
        errors.push((e as Error).message);
      }
    }
    const unchanged = JSON.stringify(face.getRig()) === JSON.stringify(original);

    // Half a centimetre lower and 1 cm farther out: the pull runs higher and toward the cheek.
    face.updateMuscle('zygomaticus-major-l', { insertion: [0.0355, 0.6558, 0.1399] });
    await face.settle(45_000);
    const edited = face.getSkin();
    const moved = at(edited.positions, corner);
    const rightMoved = at(edited.positions, mirrorVertex);
    const dist = (a: number[], b: number[]) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

    const undone = face.undo();
    await face.settle(45_000);
    const back = at(face.getSkin().positions, corner);
    return {
      undone,
      errors,
      unchanged,
      farthest,
      editChange: dist(smile, moved),
      rightChange: dist(rightSmile, rightMoved),
      undoChange: dist(smile, back),
      rigRestored: JSON.stringify(face.getRig()) === JSON.stringify(original),
      history: face.describeEditor().history,
      marker: (window as unknown as { marker?: number }).marker,
      finite: Array.from(face.getSkin().positions).every(Number.isFinite),
    };
  });
  console.log(
    `lip corner: AU12 moved it ${(result.farthest * 1000).toFixed(2)} mm; the edit ${(result.editChange * 1000).toFixed(2)} mm ` +
      `(right side ${(result.rightChange * 1000).toFixed(3)} mm); after undo ${(result.undoChange * 1000).toFixed(3)} mm from the smile`,
  );
  expect(result.undone).toBe(true);
  expect(result.errors).toHaveLength(3);
  expect(result.errors[0]).toMatch(/^updateMuscle: muscles\[\d+\]\.insertion\[0\]: expected a number, got NaN/);
  expect(result.errors[1]).toMatch(/^updateMuscle: muscles\[\d+\]\.insertion\[0\]: expected a coordinate within ±10 m, got 1000000/);
  expect(result.errors[2]).toMatch(/^updateMuscle: muscles\[\d+\]\.strength: expected a number, got "strong"/);
  expect(result.unchanged).toBe(true);
  expect(result.editChange).toBeGreaterThan(0.001);
  expect(result.rightChange).toBeLessThan(result.editChange / 10);
  expect(result.undoChange).toBeLessThan(0.0002);
  expect(result.rigRestored).toBe(true);
  expect(result.history).toEqual({ undo: 0, redo: 1 });
  expect(result.marker).toBe(1);
  expect(result.finite).toBe(true);
});
