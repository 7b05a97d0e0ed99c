import { rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import webpack from 'webpack';
import { expect, test } from './fixtures';
import { appPage, checkPackedApp, filesUnder, packedApp } from './packed-app';

/**
 * The package as a web developer uses it with webpack 5: packed, installed in a fresh app, imported the ordinary way,
 * built with a minimal configuration (an entry and an output folder) and served without the isolation headers. The
 * head models, the rig and the environment are asset modules to webpack, found through the package's
 * `new URL('./…', import.meta.url)` and emitted into the build.
 */
test.describe.configure({ timeout: 240_000 });

let app: string;
test.beforeAll(async () => {
  app = packedApp('softface-webpack-app-');
  const compiler = webpack({
    mode: 'production',
    context: app,
    entry: './main.js',
    output: { path: join(app, 'dist'), filename: 'main.js' },
    performance: { hints: false },
  });
  await new Promise<void>((resolve, reject) =>
    compiler.run((error, stats) => {
      if (error) reject(error);
      else if (stats?.hasErrors()) reject(new Error(stats.toString('errors-only')));
      else compiler.close(() => resolve());
    }),
  );
  writeFileSync(join(app, 'dist', 'index.html'), appPage('<script src="./main.js"></script>'));
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
  await checkPackedApp(page, 'http://localhost:4396', join(app, 'dist'));
});
