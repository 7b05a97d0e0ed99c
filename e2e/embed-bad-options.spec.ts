import { openEmbedPage } from './embed';
import { expect, test } from './fixtures';

test('createFace rejects bad options, naming them, and leaves nothing behind', async ({ page }) => {
  await openEmbedPage(page);
  const results = await page.evaluate(async () => {
    const container = document.createElement('div');
    Object.assign(container.style, { position: 'absolute', left: '-10000px', width: '200px', height: '200px' });
    document.body.append(container);
    const attempt = async (options: object): Promise<string> => {
      try {
        await window.softface.createFace(container, options);
        return 'resolved';
      } catch (error) {
        return `${(error as Error).message} | left ${container.childElementCount}`;
      }
    };
    return [
      // Checked before anything is built.
      await attempt({ resolution: 'huge' }),
      // Checked once the rig is loaded: the head, the worker and the canvas were built and are taken back.
      await attempt({ resolution: 'low', expression: 'AU12=0.5&AU99=1' }),
      await attempt({ resolution: 'low', expression: 'preset:joy=1' }),
      await attempt({ model: 'models/no-such-head.glb' }),
      await attempt({ resolution: 'low', rig: 'rigs/no-such-rig.json' }),
      await attempt({ resolution: 'low', rig: { muscles: 'none' } }),
    ];
  });
  expect(results[0]).toBe('createFace: resolution: expected one of low, medium, high, got "huge" | left 0');
  expect(results[1]).toMatch(/^createFace: expression: expected an Action Unit id like .*, got "AU99" \| left 0$/);
  expect(results[2]).toMatch(/^createFace: expression: expected one of the presets .*, got "joy" \| left 0$/);
  // Relative to the page. (The preview server answers unknown paths with the app's page, so the reason varies.)
  expect(results[3]).toMatch(/^the head could not be loaded from http:\/\/[^ ]*\/e2e\/pages\/models\/no-such-head\.glb: .+ \| left 0$/);
  expect(results[4]).toMatch(/\/e2e\/pages\/rigs\/no-such-rig\.json.* \| left 0$/);
  expect(results[5]).toContain('createFace: rig: muscles: expected an array of muscles, got "none"');
  expect(results[5]).toMatch(/ \| left 0$/);
  await expect.poll(() => page.workers().length).toBe(0);
});
