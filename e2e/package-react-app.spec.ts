import { join } from 'node:path';
import { test } from './fixtures';
import { builtViteApp, checkPackedApp } from './packed-app';

/**
 * The package as a React developer uses it: `examples/react-app`, whose `<SoftFace>` component wraps `<soft-face>` and
 * drives its handle, with the package packed and installed, built by Vite (which turns JSX into calls of React's
 * automatic runtime by itself) and served without the isolation headers. The page's element is the component's.
 */
test.describe.configure({ timeout: 240_000 });

const app = builtViteApp('react-app', ['react', 'react-dom']);

test('a fresh React app wrapping <soft-face> builds, shows a face that moves, and fetches nothing missing', async ({ page }) => {
  await checkPackedApp(page, 'http://localhost:4398', join(app(), 'dist'));
});
