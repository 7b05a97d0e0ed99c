import { openFace } from './face';
import { expect, test } from './shared-app';
import { control } from './panels';

/** The left lip corner's settled position: the vertex the smile moved farthest on the subject's left. */
async function corner(page: import('@playwright/test').Page, vertex = -1): Promise<{ vertex: number; at: number[] }> {
  return page.evaluate(async (vertex) => {
    await window.face.settle(45_000);
    const { rest, positions } = window.face.getSkin();
    let v = vertex;
    if (v < 0) {
      let farthest = 0;
      for (let i = 0; i < rest.length / 3; i++) {
        const d = Math.hypot(
          positions[3 * i] - rest[3 * i],
          positions[3 * i + 1] - rest[3 * i + 1],
          positions[3 * i + 2] - rest[3 * i + 2],
        );
        if (rest[3 * i] > 0.01 && d > farthest) [v, farthest] = [i, d];
      }
    }
    return { vertex: v, at: [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]] };
  }, vertex);
}

test('dragging the gizmo with the mouse moves the muscle and the skin in one undo step, and Ctrl+Z brings the rig back exactly', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await openFace(page, '/?resolution=low');
  await page.evaluate(() => window.face.setActionUnit('AU12', 0.8));
  const before = await corner(page);
  const original = await page.evaluate(() => window.face.getRig());
  await page.evaluate(() => {
    window.face.setEditor(true);
    window.face.selectMuscle('zygomaticus-major-l');
  });
  const g = (await page.evaluate(() => window.face.describeEditor().gizmo))!;
  await page.mouse.move(g.x, g.y);
  await page.mouse.down();
  for (let i = 1; i <= 8; i++) await page.mouse.move(g.x + 4 * i, g.y - 3 * i);
  await page.mouse.up();

  const editor = await page.evaluate(() => window.face.describeEditor());
  expect(editor.history).toEqual({ undo: 1, redo: 0 });
  await expect(control(page, 'undo')).toContainText('undo (1)');
  const insertion = await page.evaluate(
    () => (window.face.getRig().muscles.find((m) => m.name === 'zygomaticus-major-l') as { insertion: number[] }).insertion,
  );
  const was = (original.muscles.find((m) => m.name === 'zygomaticus-major-l') as { insertion: number[] }).insertion;
  const shift = Math.hypot(insertion[0] - was[0], insertion[1] - was[1], insertion[2] - was[2]);
  // The gizmo followed the pointer: the point moved right and up on the screen, which is +x and +y on the face.
  expect(shift).toBeGreaterThan(0.003);
  expect(insertion[0]).toBeGreaterThan(was[0]);
  expect(insertion[1]).toBeGreaterThan(was[1]);
  // The panel shows the new value.
  await expect(control(page, 'muscle-insertion-x').locator('input')).toHaveValue(String(insertion[0]));

  const after = await corner(page, before.vertex);
  const moved = Math.hypot(after.at[0] - before.at[0], after.at[1] - before.at[1], after.at[2] - before.at[2]);
  console.log(`insertion moved ${(shift * 1000).toFixed(1)} mm; the lip corner ${(moved * 1000).toFixed(2)} mm`);
  expect(moved).toBeGreaterThan(0.0005);

  await page.keyboard.press('Control+z');
  expect(await page.evaluate(() => window.face.getRig())).toEqual(original);
  const back = await corner(page, before.vertex);
  expect(Math.hypot(back.at[0] - before.at[0], back.at[1] - before.at[1], back.at[2] - before.at[2])).toBeLessThan(0.0002);
  await page.keyboard.press('Control+Shift+z');
  expect(
    await page.evaluate(
      () => (window.face.getRig().muscles.find((m) => m.name === 'zygomaticus-major-l') as { insertion: number[] }).insertion,
    ),
  ).toEqual(insertion);
});
