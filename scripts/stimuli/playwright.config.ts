import { defineConfig, devices } from '@playwright/test';
import { BROWSER_ARGS } from '../browser.mjs';
import { chromiumPath } from '../chromium-path.mjs';

/**
 * Renders the stimuli of `npm run stimuli` (see run.ts): one test per stimulus. The built app is served on
 * `STIMULI_PORT` (4190) unless `STIMULI_BASE_URL` names a server that already serves it.
 */
const PORT = Number(process.env.STIMULI_PORT ?? 4190);
const given = process.env.STIMULI_BASE_URL;

export default defineConfig({
  testDir: '.',
  testMatch: 'render.spec.ts',
  timeout: 300_000,
  fullyParallel: true,
  workers: 1,
  retries: 0,
  reporter: [['list']],
  outputDir: `${process.env.STIMULI_OUT ?? '.'}/.playwright`,
  use: {
    ...devices['Desktop Chrome'],
    baseURL: given ?? `http://127.0.0.1:${PORT}`,
    deviceScaleFactor: 1,
    launchOptions: {
      executablePath: chromiumPath(),
      args: BROWSER_ARGS,
    },
  },
  webServer: given
    ? undefined
    : {
        command: `npx vite preview --host 127.0.0.1 --port ${PORT} --strictPort`,
        url: `http://127.0.0.1:${PORT}`,
        reuseExistingServer: true,
        timeout: 180_000,
      },
});
