import { addFaces, openEmbedPage } from './embed';
import { expect, test } from './fixtures';

test('two faces on one page have a worker each, and a change to one never moves the other', async ({ page }) => {
  await openEmbedPage(page);
  await addFaces(page, { a: { resolution: 'low' }, b: { resolution: 'low' } }, { inView: false });
  expect(page.workers()).toHaveLength(2);
  expect(await page.locator('#a canvas').count()).toBe(1);
  expect(await page.locator('#b canvas').count()).toBe(1);

  const r = await page.evaluate(async () => {
    const { a, b } = window.faces;
    await Promise.all([a.settle(45_000), b.settle(45_000)]);
    const told: string[] = [];
    b.onChange((change) => told.push(change));
    const bBefore = b.getSkin();
    const bFrames = b.stats().frames;
    a.setActionUnit('AU12', 1);
    a.applyPreset('surprise', 0.5);
    a.setLight({ keyAzimuth: 200 });
    a.setRenderOptions({ wireframe: true });
    await Promise.all([a.settle(45_000), b.settle(45_000)]);
    const aSkin = a.getSkin();
    let aMoved = 0;
    for (let i = 0; i < aSkin.rest.length; i += 3) {
      aMoved = Math.max(
        aMoved,
        Math.hypot(
          aSkin.positions[i] - aSkin.rest[i],
          aSkin.positions[i + 1] - aSkin.rest[i + 1],
          aSkin.positions[i + 2] - aSkin.rest[i + 2],
        ),
      );
    }
    const bAfter = b.getSkin();
    let bChanged = 0;
    for (let i = 0; i < bBefore.positions.length; i++) bChanged = Math.max(bChanged, Math.abs(bAfter.positions[i] - bBefore.positions[i]));
    return {
      aMoved,
      bChanged,
      bFramesSolved: b.stats().frames - bFrames,
      told,
      aAU12L: a.getActionUnits().AU12L,
      bNonZero: Object.entries(b.getActionUnits()).filter(([, v]) => v !== 0),
      bPresets: b.listPresets().filter((p) => p.weight !== 0),
      bLight: b.getLight().keyAzimuth,
      aLight: a.getLight().keyAzimuth,
      bWireframe: b.getRenderOptions().wireframe,
    };
  });
  // The change moved the first face by millimetres, so an unmoved second face is not a face that moves nothing.
  expect(r.aAU12L).toBe(1);
  expect(r.aMoved).toBeGreaterThan(0.003);
  expect(r.aLight).toBe(200);
  expect(r.bChanged).toBe(0);
  expect(r.bFramesSolved).toBe(0);
  expect(r.told).toEqual([]);
  expect(r.bNonZero).toEqual([]);
  expect(r.bPresets).toEqual([]);
  expect(r.bLight).not.toBe(200);
  expect(r.bWireframe).toBe(false);
});
