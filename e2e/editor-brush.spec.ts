import { openFace } from './face';
import { expect, test } from './shared-app';
import { control } from './panels';

/** How far AU12 moved the left lip corner once settled (the vertex it moves farthest on the subject's left). */
async function cornerMove(page: import('@playwright/test').Page, vertex = -1): Promise<{ vertex: number; moved: number }> {
  return page.evaluate(async (vertex) => {
    await window.face.settle(45_000);
    const { rest, positions } = window.face.getSkin();
    const d = (i: number) =>
      Math.hypot(positions[3 * i] - rest[3 * i], positions[3 * i + 1] - rest[3 * i + 1], positions[3 * i + 2] - rest[3 * i + 2]);
    let v = vertex;
    if (v < 0) for (let i = 0; i < rest.length / 3; i++) if (rest[3 * i] > 0.01 && (v < 0 || d(i) > d(v))) v = i;
    return { vertex: v, moved: d(v) };
  }, vertex);
}

test(
  'the vertex brush paints skin out of a muscle with the mouse: ' + 'stored at rest in the rig, one undo step, the lip corner follows',
  async ({ page }) => {
    test.setTimeout(120_000);
    await openFace(page, '/?resolution=low');
    await page.evaluate(() => window.face.setActionUnit('AU12', 1));
    const before = await cornerMove(page);
    await page.evaluate(() => {
      window.face.setEditor(true);
      window.face.selectMuscle('zygomaticus-major-l');
    });
    // Where the gizmo holds the insertion: by the lip corner. The brush then replaces the gizmo.
    const p = (await page.evaluate(() => window.face.describeEditor().gizmo))!;
    await control(page, 'brush-mode').locator('select').selectOption('remove');
    const radius = control(page, 'brush-radius').locator('input');
    await radius.fill('12');
    await radius.press('Enter');
    expect(await page.evaluate(() => window.face.describeEditor().gizmo)).toBeNull();
    const history = await page.evaluate(() => window.face.describeEditor().history);

    await page.mouse.move(p.x, p.y);
    await page.mouse.down();
    for (let i = 1; i <= 6; i++) await page.mouse.move(p.x + 3 * Math.cos(i), p.y + 3 * Math.sin(i));
    await page.mouse.up();

    const rig = await page.evaluate(() => window.face.getRig());
    const zygomaticus = rig.muscles.find((m) => m.name === 'zygomaticus-major-l')!;
    expect(zygomaticus.brush!.remove.length).toBeGreaterThan(0);
    expect(zygomaticus.brush!.add).toEqual([]);
    const insertion = (zygomaticus as { insertion: number[] }).insertion;
    for (const s of zygomaticus.brush!.remove) {
      expect(s[3]).toBe(0.012);
      // At rest on the skin near the insertion, whatever the smile did to the skin under the pointer.
      expect(Math.hypot(s[0] - insertion[0], s[1] - insertion[1], s[2] - insertion[2])).toBeLessThan(0.02);
    }
    expect((await page.evaluate(() => window.face.describeEditor().history)).undo).toBe(history.undo + 1);
    const after = await cornerMove(page, before.vertex);
    console.log(
      `lip corner: ${(before.moved * 1000).toFixed(2)} mm with the muscle whole, ` +
        `${(after.moved * 1000).toFixed(2)} mm with the brushed skin removed`,
    );
    expect(after.moved).toBeLessThan(0.6 * before.moved);

    await page.keyboard.press('Control+z');
    expect(await page.evaluate(() => window.face.getRig().muscles.find((m) => m.name === 'zygomaticus-major-l')!.brush)).toBeUndefined();
    const back = await cornerMove(page, before.vertex);
    expect(Math.abs(back.moved - before.moved)).toBeLessThan(0.0002);
  },
);
