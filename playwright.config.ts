import { defineConfig, devices } from '@playwright/test';
import { BROWSER_ARGS } from './scripts/browser.mjs';
import { chromiumPath } from './scripts/chromium-path.mjs';

/**
 * The built app is served twice: as it should be (with COOP/COEP) and as a host that sends no such headers would.
 * `SOFTFACE_E2E_PORT` moves both (to it and the port after), so that two checkouts can run their tests at once.
 */
export const ISOLATED_PORT = Number(process.env.SOFTFACE_E2E_PORT ?? 4173);
export const PLAIN_PORT = ISOLATED_PORT + 1;

/** Tests that run by themselves after the others (see `projects`). */
const ALONE = ['**/tracking-fake-camera.spec.ts'];
/** What the tests that run alone need made first: the fake camera's clip (e2e/tracking-clip.ts). */
const CLIP = ['**/tracking-clip.setup.ts'];

export default defineConfig({
  testDir: 'e2e',
  timeout: 60_000,
  expect: { timeout: 20_000 },
  fullyParallel: false,
  // Two browsers at once on a 2-core machine: the tests wait for what they check, never for a time, so they hold
  // under the load (npm run test:e2e:loaded runs them beside a busy core); SOFTFACE_E2E_WORKERS=1 runs one at a time.
  workers: Number(process.env.SOFTFACE_E2E_WORKERS ?? 2),
  retries: 0,
  forbidOnly: !!process.env.CI,
  reporter: [['list']],
  outputDir: 'test-results',
  use: {
    ...devices['Desktop Chrome'],
    baseURL: `http://127.0.0.1:${ISOLATED_PORT}`,
    viewport: { width: 1024, height: 768 },
    launchOptions: {
      executablePath: chromiumPath(),
      // WebGL through SwiftShader, no background traffic, no address-bar popups (see scripts/browser.mjs).
      args: BROWSER_ARGS,
    },
  },
  projects: [
    // Recording the fake camera's clip needs no quiet machine: `npm run test:e2e` runs it beside the others (listed
    // first, so that it starts first and leaves no tail).
    { name: 'clip', testMatch: CLIP },
    { name: 'parallel', testIgnore: [...ALONE, ...CLIP] },
    // The tests whose numbers a second browser beside them would change: `npm run test:e2e` runs them after the
    // others, by themselves (the webcam tracker's latency, printed: a median of 32 to 45 ms alone, about 290 ms
    // beside a busy core), with --no-deps, as the clip was made then; run on their own, they make the clip first.
    { name: 'alone', testMatch: ALONE, dependencies: ['clip'] },
  ],
  webServer: [
    {
      // `npm run test:e2e` builds dist/ first; both servers serve that build.
      command: `npx vite preview --host 127.0.0.1 --port ${ISOLATED_PORT} --strictPort`,
      url: `http://127.0.0.1:${ISOLATED_PORT}`,
      reuseExistingServer: !process.env.CI,
      timeout: 180_000,
    },
    {
      command: `npx vite preview --host 127.0.0.1 --port ${PLAIN_PORT} --strictPort`,
      env: { SOFTFACE_NO_ISOLATION: '1' },
      url: `http://127.0.0.1:${PLAIN_PORT}`,
      reuseExistingServer: !process.env.CI,
      timeout: 180_000,
    },
  ],
});
