import { openFace } from './face';
import { expect, test } from './fixtures';
import { setSlider, sliderValue } from './panels';

test('a link with an expression in its hash opens that face, and the hash follows the sliders', async ({ page }) => {
  test.setTimeout(90_000);
  // Count the page's hash writes, to check the throttle.
  await page.addInitScript(() => {
    const replace = history.replaceState.bind(history);
    (window as unknown as { hashWrites: number }).hashWrites = 0;
    history.replaceState = (...args: Parameters<History['replaceState']>) => {
      (window as unknown as { hashWrites: number }).hashWrites++;
      replace(...args);
    };
  });
  await openFace(page, '/?resolution=low#AU1L=0.6&AU1R=0.6&AU12L=0.8&preset:happiness=0.3&AU99=1');
  const opened = await page.evaluate(() => ({ units: window.face.getActionUnits(), presets: window.face.listPresets() }));
  expect(opened.units.AU1L).toBe(0.6);
  expect(opened.units.AU1R).toBe(0.6);
  expect(opened.units.AU12L).toBe(0.8);
  expect(opened.units.AU12R).toBe(0);
  expect(opened.presets.find((p) => p.name === 'happiness')?.weight).toBe(0.3);
  expect(await sliderValue(page, 'AU12L')).toBe(0.8);
  // The hash stays (the unknown AU99 dropped from it), so the link in the address bar is the face on screen.
  await expect.poll(() => page.evaluate(() => location.hash)).toBe('#AU1L=0.6&AU1R=0.6&AU12L=0.8&preset%3Ahappiness=0.3');
  expect(page.url()).toContain('?resolution=low#');

  // Moving a slider (AU4, linked: both sides) rewrites the hash.
  await setSlider(page, 'AU4L', 0.4);
  await expect.poll(() => page.evaluate(() => location.hash)).toContain('AU4L=0.4&AU4R=0.4');
  const link = page.url();
  expect(link).toContain('AU1L=0.6');

  // A burst of changes every 10 ms (a second or more: a busy machine stretches the timers) writes the hash at most
  // every 250 ms of the time it took, and ends on the last value.
  const burst = await page.evaluate(async () => {
    const w = window as unknown as { hashWrites: number };
    const before = w.hashWrites;
    const start = performance.now();
    for (let i = 1; i <= 100; i++) {
      window.face.setActionUnit('AU26', i / 100);
      await new Promise((r) => setTimeout(r, 10));
    }
    // The last value's write comes at most 250 ms later, or later still where the machine stretches the timers.
    const deadline = performance.now() + 10_000;
    while (!/[#&]AU26=1(&|$)/.test(location.hash) && performance.now() < deadline) await new Promise((r) => setTimeout(r, 20));
    return { writes: w.hashWrites - before, ms: performance.now() - start, hash: location.hash };
  });
  console.log(`hash writes during a burst of 100 changes over ${Math.round(burst.ms)} ms: ${burst.writes}`);
  expect(burst.writes).toBeGreaterThanOrEqual(2);
  expect(burst.writes).toBeLessThanOrEqual(Math.ceil(burst.ms / 250) + 1);
  expect(burst.hash).toMatch(/[#&]AU26=1(&|$)/);

  // The copied link reopens the same face, in a fresh page.
  const expected = await page.evaluate(() => window.face.getActionUnits());
  const copy = await page.context().newPage();
  await openFace(copy, page.url());
  expect(await copy.evaluate(() => window.face.getActionUnits())).toEqual(expected);
  expect(await copy.evaluate(() => window.face.listPresets().find((p) => p.name === 'happiness')?.weight)).toBe(0.3);
  await copy.close();

  // Typing another hash in the address bar applies it on a neutral face; the neutral face has no hash.
  await page.evaluate(() => (location.hash = '#AU26=0.5'));
  await expect.poll(() => page.evaluate(() => window.face.getActionUnits().AU26)).toBe(0.5);
  expect(await page.evaluate(() => window.face.getActionUnits().AU1L)).toBe(0);
  await page.evaluate(() => window.face.reset());
  await expect.poll(() => page.evaluate(() => location.href)).not.toContain('#');
  expect(link).not.toBe(page.url());
});
