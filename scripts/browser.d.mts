import type { Browser, Page } from '@playwright/test';

/** Headless Chromium's switches for the tests and scripts (see browser.mjs). */
export declare const BROWSER_ARGS: string[];
/** Launches headless Chromium (the one `chromiumPath` finds) with `BROWSER_ARGS`. */
export declare function launchBrowser(): Promise<Browser>;
/** Opens the app at `url` in `page` and waits until its face is up. */
export declare function openApp(page: Page, url: string, options?: { timeout?: number; retries?: number; retryMs?: number }): Promise<void>;
