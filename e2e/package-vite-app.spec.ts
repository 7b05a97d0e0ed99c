import { join } from 'node:path';
import { expect, test } from './fixtures';
import { builtViteApp, checkPackedApp, filesUnder } from './packed-app';

/**
 * The package as a web developer uses it with Vite: `examples/vite-app` with the package packed and installed, built
 * (its config only keeps the package out of the dev server's pre-bundling) and served without the isolation headers.
 * The head models, the rig and the environment are found by Vite through the package's
 * `new URL('./…', import.meta.url)` and copied into the build.
 */
test.describe.configure({ timeout: 240_000 });

const app = builtViteApp('vite-app');

test('a fresh Vite app that imports the packed library builds, shows a face that moves, and fetches nothing missing', async ({ page }) => {
  // The app's build holds its own copies of the package's files, under hashed names.
  const files = filesUnder(join(app(), 'dist'));
  for (const stem of ['head-low', 'default', 'room'])
    expect(
      files.some((f) => f.includes(stem)),
      stem,
    ).toBe(true);
  await checkPackedApp(page, 'http://localhost:4395', join(app(), 'dist'));
});
