/**
 * The browser the scripts render the app in, and the wait for the app's face to be up.
 */
import { chromium } from '@playwright/test';
import { chromiumPath } from './chromium-path.mjs';

/**
 * The features Playwright (1.65) switches off with its own `--disable-features`. Chromium reads only the last such
 * switch, so BROWSER_ARGS's own repeats these; `e2e/browser-switches.spec.ts` fails if Playwright's list grows.
 */
const PLAYWRIGHT_DISABLED_FEATURES = [
  'AvoidUnnecessaryBeforeUnloadCheckSync',
  'DestroyProfileOnBrowserClose',
  'HttpsUpgrades',
  'HttpsFirstBalancedModeAutoEnable',
  'LensOverlay',
  'MediaRouter',
  'PaintHolding',
  'ThirdPartyStoragePartitioning',
  'AvoidCorsURLLoaderRestartOnRedirect',
  'TcpPortRandomizationWin',
  'OptimizationHints',
  'NetworkTimeServiceQuerying',
  'AimEnabled',
  'PreconnectToSearch',
  'msForceBrowserSignIn',
  'msEdgeUpdateLaunchServicesPreferredVersion',
];

/**
 * The address bar's WebUI popups, which Chromium 156 loads into a renderer of their own for every new window, that is
 * for every test's page: 1.4 to 2.9 CPU-seconds each time on the 2-core machine, a fifth to a third of what a medium
 * page's own start costs.
 */
const OMNIBOX_POPUPS = ['WebUIOmniboxPopup', 'WebUIOmniboxAimPopup'];

/**
 * Headless Chromium's switches for the tests and scripts: WebGL through SwiftShader, so that no GPU is needed; no
 * background traffic toward hosts out of reach; no address-bar popups loaded behind each page.
 */
export const BROWSER_ARGS = [
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--no-first-run',
  `--disable-features=${[...PLAYWRIGHT_DISABLED_FEATURES, ...OMNIBOX_POPUPS].join(',')}`,
];

/** Launches headless Chromium (the one `chromiumPath` finds) with `BROWSER_ARGS`. */
export function launchBrowser() {
  return chromium.launch({ executablePath: chromiumPath(), args: BROWSER_ARGS });
}

/**
 * Opens the app at `url` in `page` and waits until its face is up; throws with the page's status line if it failed.
 * With `retries`, a failed load is tried again every `retryMs`, for a server that is still starting.
 */
export async function openApp(page, url, { timeout = 60_000, retries = 0, retryMs = 200 } = {}) {
  for (let i = 0; ; i++) {
    try {
      await page.goto(url);
      break;
    } catch (error) {
      if (i >= retries) throw error;
      await new Promise((r) => setTimeout(r, retryMs));
    }
  }
  // The app marks the page "ready" once window.face is up, or "error" with the reason in its status line.
  await page.waitForFunction(() => document.documentElement.dataset.state, null, { timeout });
  const state = await page.evaluate(() => document.documentElement.dataset.state);
  if (state !== 'ready') throw new Error(`the page reports "${state}": ${await page.locator('#status').textContent()}`);
  await page.evaluate(() => window.face.ready);
}

/**
 * Has the page's face draw its finished picture of the newest skin now (the still `savePNG` draws: full resolution,
 * antialiased) and waits until its canvas says it shows it (`data-quality="full"`). A fixed wait after `settle`
 * sometimes caught the moving face's last, lower picture on a busy machine (jagged edges, dotted brows).
 */
export async function finishedPicture(page, timeout = 30_000) {
  await page.evaluate(() => window.face?.savePNG?.());
  await page.waitForSelector('canvas[data-quality="full"]', { timeout });
}
