import { readFileSync } from 'node:fs';
import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, openFolder, sliderValue } from './panels';

/**
 * AU12 rises linearly from 0 to 1 over 2 s; AU6 goes through an action (up over 0.5 s from 0.5 s, 1 s at 0.6, down
 * over 0.5 s); the happiness preset eases in over the 3 s. Short enough for the URL hash.
 */
const TIMELINE = {
  format: 'softface-timeline',
  version: 1,
  duration: 3,
  tracks: {
    AU12: {
      keys: [
        { time: 0, value: 0 },
        { time: 2, value: 1 },
      ],
    },
    'preset:happiness': {
      keys: [
        { time: 0, value: 0, easing: 'ease-in-out' },
        { time: 3, value: 0.4 },
      ],
    },
  },
  actions: [{ target: 'AU6', start: 0.5, intensity: 0.6, onset: 0.5, apex: 1, offset: 0.5 }],
};

test('the handle plays, pauses and seeks a timeline; the face and the sliders follow it', async ({ page }) => {
  test.setTimeout(120_000);
  await openFace(page, '/?resolution=low');
  await page.evaluate((t) => window.face.setTimeline(t), TIMELINE);
  const loaded = await page.evaluate(() => ({ state: window.face.timelineState(), units: window.face.getActionUnits() }));
  expect(loaded.state).toEqual({ loaded: true, playing: false, time: 0, duration: 3, loop: false });
  expect(loaded.units.AU12L).toBe(0);

  // Play: the clock runs and AU12 rises on both sides.
  await page.evaluate(() => window.face.play());
  await expect.poll(() => page.evaluate(() => window.face.getActionUnits().AU12L), { timeout: 20_000 }).toBeGreaterThan(0.3);
  await page.evaluate(() => window.face.pause());
  const paused = await page.evaluate(() => ({ state: window.face.timelineState(), units: window.face.getActionUnits() }));
  expect(paused.state.playing).toBe(false);
  expect(paused.state.time).toBeGreaterThan(0.6);
  // The sliders hold what the timeline set: AU12 follows its track at the clock's time.
  expect(paused.units.AU12L).toBeCloseTo(paused.state.time / 2, 6);
  expect(paused.units.AU12R).toBeCloseTo(paused.state.time / 2, 6);
  // The face moved with it (a lip corner moves about 10 mm at full AU12).
  const moved = await page.evaluate(async () => {
    await window.face.settle(45_000);
    const { rest, positions } = window.face.getSkin();
    let m = 0;
    for (let i = 0; i < rest.length; i += 3)
      m = Math.max(m, Math.hypot(positions[i] - rest[i], positions[i + 1] - rest[i + 1], positions[i + 2] - rest[i + 2]));
    return m;
  });
  expect(moved).toBeGreaterThan(0.002);

  // Paused, it holds: over animation frames (a playing clock moves on at each), neither the clock nor the values move.
  await page.evaluate(async () => {
    for (let i = 0; i < 10; i++) await new Promise((resolve) => requestAnimationFrame(resolve));
  });
  const held = await page.evaluate(() => ({ state: window.face.timelineState(), units: window.face.getActionUnits() }));
  expect(held).toEqual(paused);

  // Seek: the values of that time, in the handle and on the panel's sliders.
  await page.evaluate(() => window.face.seek(1.5));
  const sought = await page.evaluate(() => ({
    state: window.face.timelineState(),
    units: window.face.getActionUnits(),
    happiness: window.face.listPresets().find((p) => p.name === 'happiness')!.weight,
  }));
  expect(sought.state.time).toBe(1.5);
  expect(sought.units.AU12L).toBeCloseTo(0.75, 9);
  expect(sought.units.AU6L).toBeCloseTo(0.6, 9);
  expect(sought.units.AU6R).toBeCloseTo(0.6, 9);
  // ease-in-out at half way: half the weight.
  expect(sought.happiness).toBeCloseTo(0.2, 9);
  // Units the timeline does not name are left alone.
  expect(sought.units.AU26).toBe(0);
  await expect.poll(() => sliderValue(page, 'AU12L')).toBe(0.75);
  await expect.poll(() => sliderValue(page, 'AU6R')).toBe(0.6);

  // Played to the end without loop, it stops there.
  await page.evaluate(() => window.face.seek(2.9));
  await page.evaluate(() => window.face.play());
  await expect.poll(() => page.evaluate(() => window.face.timelineState().playing), { timeout: 20_000 }).toBe(false);
  const ended = await page.evaluate(() => ({ state: window.face.timelineState(), units: window.face.getActionUnits() }));
  expect(ended.state.time).toBe(3);
  expect(ended.units.AU12L).toBe(1);
  expect(ended.units.AU6L).toBe(0);
});

test('a bad timeline is refused with its path-named message and changes nothing, from the handle and from a file', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  await page.evaluate((t) => {
    window.face.setTimeline(t);
    window.face.seek(1);
  }, TIMELINE);
  const before = await page.evaluate(() => ({
    timeline: window.face.getTimeline(),
    state: window.face.timelineState(),
    units: window.face.getActionUnits(),
  }));

  const bad = structuredClone(TIMELINE);
  bad.tracks.AU12.keys.push({ time: 1, value: 0.5 });
  const message = await page.evaluate((t) => {
    try {
      window.face.setTimeline(JSON.stringify(t));
      return 'accepted';
    } catch (error) {
      return (error as Error).message;
    }
  }, bad);
  expect(message).toBe("setTimeline: tracks.AU12.keys[2].time: keys out of order: expected a time after the previous key's 2 s, got 1");
  const nan = await page.evaluate((t) => {
    try {
      window.face.setTimeline({ ...t, actions: [{ ...t.actions[0], intensity: Number.NaN }] });
      return 'accepted';
    } catch (error) {
      return (error as Error).message;
    }
  }, TIMELINE);
  expect(nan).toBe('setTimeline: actions[0].intensity: expected a number, got NaN');
  expect(
    await page.evaluate(() => ({
      timeline: window.face.getTimeline(),
      state: window.face.timelineState(),
      units: window.face.getActionUnits(),
    })),
  ).toEqual(before);

  // The same through the panel's import: the message shows in the folder, and the timeline stays.
  await openFolder(page, 'Timeline');
  const wrong = structuredClone(TIMELINE) as Record<string, unknown>;
  (wrong.tracks as Record<string, unknown>).AU99 = { keys: [{ time: 0, value: 1 }] };
  await control(page, 'timeline-file').setInputFiles({
    name: 'wrong.json',
    mimeType: 'application/json',
    buffer: Buffer.from(JSON.stringify(wrong)),
  });
  await expect(control(page, 'timeline-message')).toContainText('wrong.json: tracks.AU99: expected an Action Unit id like');
  expect(
    await page.evaluate(() => ({
      timeline: window.face.getTimeline(),
      state: window.face.timelineState(),
      units: window.face.getActionUnits(),
    })),
  ).toEqual(before);
});

test('the Timeline panel adds an action, plays and pauses, seeks with its slider, imports and exports files', async ({ page }) => {
  test.setTimeout(90_000);
  await openFace(page, '/?resolution=low');
  await openFolder(page, 'Timeline');
  await expect(control(page, 'timeline-keys')).toHaveText('no timeline');

  // An onset / apex / offset action for AU26 at time 0.
  await control(page, 'timeline-target').locator('select').selectOption('AU26');
  await control(page, 'timeline-add-action').locator('button').click();
  const t = await page.evaluate(() => window.face.getTimeline());
  expect(t?.actions).toEqual([{ target: 'AU26', start: 0, intensity: 0.8, onset: 0.5, apex: 1, offset: 0.8 }]);
  await expect(control(page, 'timeline-keys')).toContainText('AU26 0.8 at 0 s: onset 0.5 s, apex 1 s, offset 0.8 s');

  // Loop on, then play: the jaw opens; pause holds it.
  await control(page, 'timeline-loop').locator('input').check();
  expect(await page.evaluate(() => window.face.getTimeline()?.loop)).toBe(true);
  await control(page, 'timeline-play').locator('button').click();
  await expect(control(page, 'timeline-play')).toContainText('pause');
  await expect.poll(() => page.evaluate(() => window.face.getActionUnits().AU26), { timeout: 20_000 }).toBeGreaterThan(0.1);
  await control(page, 'timeline-play').locator('button').click();
  await expect(control(page, 'timeline-play')).toContainText('play');
  expect(await page.evaluate(() => window.face.timelineState().playing)).toBe(false);

  // The time slider seeks: at 1 s the action is at its apex.
  const time = control(page, 'timeline-time').locator('input');
  await time.fill('1');
  await time.press('Enter');
  await expect.poll(() => page.evaluate(() => window.face.timelineState().time)).toBe(1);
  expect(await page.evaluate(() => window.face.getActionUnits().AU26)).toBeCloseTo(0.8, 9);

  // Importing a file replaces the timeline.
  await control(page, 'timeline-file').setInputFiles({
    name: 'smile.json',
    mimeType: 'application/json',
    buffer: Buffer.from(JSON.stringify(TIMELINE)),
  });
  await expect(control(page, 'timeline-message')).toHaveText('imported smile.json');
  expect(await page.evaluate(() => window.face.getTimeline())).toEqual(TIMELINE);
  await expect(control(page, 'timeline-keys')).toContainText('AU12: 0 s 0 → 2 s 1');

  // Export downloads the timeline as a file that imports back to the same document.
  const download = page.waitForEvent('download');
  await control(page, 'timeline-export').locator('button').click();
  const file = await download;
  expect(file.suggestedFilename()).toBe('timeline.json');
  expect(JSON.parse(readFileSync(await file.path(), 'utf8'))).toEqual(TIMELINE);

  // Clear: no timeline, the face keeps its values.
  await control(page, 'timeline-clear').locator('button').click();
  expect(await page.evaluate(() => window.face.timelineState().loaded)).toBe(false);
  await expect(control(page, 'timeline-keys')).toHaveText('no timeline');
});

test('a short timeline round-trips through the URL hash', async ({ page }) => {
  test.setTimeout(90_000);
  await openFace(page, '/?resolution=low');
  await page.evaluate((t) => window.face.setTimeline(t), TIMELINE);
  await expect.poll(() => page.evaluate(() => location.hash)).toContain('timeline=');
  const link = page.url();
  const copy = await page.context().newPage();
  await openFace(copy, link);
  expect(await copy.evaluate(() => window.face.getTimeline())).toEqual(TIMELINE);
  expect(await copy.evaluate(() => window.face.timelineState())).toEqual({
    loaded: true,
    playing: false,
    time: 0,
    duration: 3,
    loop: false,
  });
  await copy.close();

  // A long timeline stays out of the link (the expression still goes in).
  const long = await page.evaluate(() => {
    const keys = Array.from({ length: 120 }, (_, i) => ({ time: i / 10, value: (i % 10) / 10 }));
    window.face.setTimeline({ format: 'softface-timeline', tracks: { AU26: { keys } } });
    window.face.seek(0.5);
    return JSON.stringify(window.face.getTimeline()).length;
  });
  expect(long).toBeGreaterThan(1500);
  await expect.poll(() => page.evaluate(() => location.hash)).toBe('#AU26=0.5');
});
