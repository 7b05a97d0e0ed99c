/**
 * The browser the scripts render the app in, and the wait for the app's face to be up.
 */
import { chromium } from '@playwright/test';
import { chromiumPath } from './chromium-path.mjs';

/** WebGL through SwiftShader, so that no GPU is needed, and no background traffic toward hosts out of reach. */
export const BROWSER_ARGS = ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-background-networking', '--no-first-run'];

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
