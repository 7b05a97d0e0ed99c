import { rmSync } from 'node:fs';
import { join } from 'node:path';
import { build } from 'vite';
import { test } from './fixtures';
import { checkPackedApp, packedApp } from './packed-app';

/**
 * The package as a React developer uses it: `examples/react-app`, whose `<SoftFace>` component wraps `<soft-face>` and
 * drives its handle, with the package packed and installed, built by Vite (which turns JSX into calls of React's
 * automatic runtime by itself) and served without the isolation headers. The page's element is the component's.
 */
test.describe.configure({ timeout: 240_000 });

let app: string;
test.beforeAll(async () => {
  app = packedApp('react-app', ['react', 'react-dom']);
  await build({
    root: app,
    logLevel: 'silent',
    configFile: join(app, 'vite.config.js'),
    build: { outDir: join(app, 'dist'), target: 'es2022' },
  });
});

test.afterAll(() => {
  if (app) rmSync(app, { recursive: true, force: true });
});

test('a fresh React app wrapping <soft-face> builds, shows a face that moves, and fetches nothing missing', async ({ page }) => {
  await checkPackedApp(page, 'http://localhost:4398', join(app, 'dist'));
});
