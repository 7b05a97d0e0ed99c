import { addElement, openEmbedPage, takeEvents } from './embed';
import { expect, test } from './fixtures';

test('<soft-face>: a bad attribute value fires an error naming it, and the face stays as it was', async ({ page }) => {
  await openEmbedPage(page);
  await addElement(page, 'f', { resolution: 'low', expression: 'AU12=0.6', background: '#203040' }, { inView: false });
  await takeEvents(page, 'f');
  const state = () =>
    page.evaluate(() => {
      const f = document.querySelector('soft-face')!.face!;
      return {
        units: f.getActionUnits(),
        presets: f.listPresets(),
        eyes: f.getEyeSimulation(),
        vertices: f.stats().vertices,
        mode: f.stats().mode,
      };
    });
  const before = await state();
  expect(before.units.AU12L).toBe(0.6);

  const bad: [string, string, RegExp][] = [
    ['resolution', 'ultra', /^<soft-face>: resolution: expected one of low, medium, high, got "ultra"$/],
    ['solver', 'gpu', /^<soft-face>: solver: expected one of auto, shared, transfer, main, got "gpu"$/],
    ['expression', 'AU99=1', /^<soft-face> expression: expected an Action Unit id like .*, got "AU99"$/],
    ['expression', 'AU12=lots', /^<soft-face> expression: AU12: expected a finite number, got "lots"$/],
    ['preset', 'joy:1', /^<soft-face> preset: expected one of the presets .*happiness.*, got "joy"$/],
    ['preset', 'happiness:x', /^<soft-face>: preset: expected a preset name and a weight, like "happiness:0.5", got "happiness:x"$/],
    ['panels', 'maybe', /^<soft-face>: panels: expected present \(on\), "true" or "false", got "maybe"$/],
    ['eye-simulation', 'yes', /^<soft-face>: eye-simulation: expected present \(on\), "true" or "false", got "yes"$/],
    ['background', 'blue', /^<soft-face>: background: expected a colour "#rrggbb" or "transparent", got "blue"$/],
  ];
  for (const [name, value, message] of bad) {
    await page.evaluate(([name, value]) => document.querySelector('soft-face')!.setAttribute(name, value), [name, value]);
    const events = await takeEvents(page, 'f');
    expect(events, `${name}="${value}"`).toHaveLength(1);
    expect(events[0].type).toBe('error');
    expect(events[0].what).toMatch(message);
  }
  // Nothing moved: the same head and solver (no rebuild), the same expression, no panels, the eyes still.
  expect(await state()).toEqual(before);
  await expect(page.locator('soft-face .softface-panels')).toHaveCount(0);
  // And the face still takes good values after bad ones.
  await page.evaluate(() => document.querySelector('soft-face')!.setAttribute('expression', 'AU4=0.2'));
  expect((await state()).units.AU4L).toBe(0.2);
  expect(await takeEvents(page, 'f')).toEqual([{ type: 'change', what: 'expression' }]);
});

test('<soft-face>: an error event nobody prevents also reaches the console as a warning', async ({ page }) => {
  const warnings: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'warning') warnings.push(m.text());
  });
  await openEmbedPage(page);
  // Checked as soon as the attribute is set, before any face is built: no head needs to load for this.
  await page.evaluate(() => document.createElement('soft-face').setAttribute('resolution', 'huge'));
  expect(warnings).toEqual(['<soft-face>: resolution: expected one of low, medium, high, got "huge"']);
});
