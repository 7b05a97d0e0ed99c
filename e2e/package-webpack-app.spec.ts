import { rmSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';
import webpack from 'webpack';
import { expect, test } from './fixtures';
import { BUILD_TIMEOUT_MS, checkPackedApp, filesUnder, packedApp } from './packed-app';

/**
 * The package as a web developer uses it with webpack 5: `examples/webpack-app` with the package packed and installed,
 * built with its configuration (an entry and an output folder) and served without the isolation headers. The head
 * models, the rig and the environment are asset modules to webpack, found through the package's
 * `new URL('./…', import.meta.url)` and emitted beside its bundle.
 */
test.describe.configure({ timeout: 240_000 });

let app: string;
test.beforeAll(async () => {
  // A hook's timeout is the config's, not the describe's: webpack's build took over 60 s beside three browsers.
  test.setTimeout(BUILD_TIMEOUT_MS);
  app = packedApp('webpack-app');
  const config = (await import(pathToFileURL(join(app, 'webpack.config.js')).href)).default;
  // As `npx webpack` run in the app's folder would build it.
  const compiler = webpack({ ...config, context: app });
  await new Promise<void>((resolve, reject) =>
    compiler.run((error, stats) => {
      if (error) reject(error);
      else if (stats?.hasErrors()) reject(new Error(stats.toString('errors-only')));
      else compiler.close(() => resolve());
    }),
  );
});

test.afterAll(() => {
  if (app) rmSync(app, { recursive: true, force: true });
});

test('a fresh webpack 5 app that imports the packed library builds, shows a face that moves, and fetches nothing missing', async ({
  page,
}) => {
  // The app's build holds its own copies of the package's files (webpack names them by their hash).
  const files = filesUnder(join(app, 'dist'));
  for (const extension of ['.glb', '.bin', '.json', '.pmrem'])
    expect(
      files.some((f) => f.endsWith(extension)),
      extension,
    ).toBe(true);
  await checkPackedApp(page, 'http://localhost:4396', app);
});
