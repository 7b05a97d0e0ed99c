import { existsSync, statSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import type { Page } from '@playwright/test';

/**
 * A static host the tests play: it serves files as they are, with the headers a test gives it. On localhost, which
 * browsers trust as they trust HTTPS, so that its isolation headers count; nothing listens there, the test answers.
 */
export const STATIC_ORIGIN = 'http://localhost:4391';
/** Another site (another port is another origin), for pages that embed the static host's pages in an iframe. */
export const OTHER_ORIGIN = 'http://localhost:4392';

const root = (p: string): string => fileURLToPath(new URL(`../${p}`, import.meta.url));

/** Where each folder of the hosts comes from: the library build, the page's own three.js, and the test pages. */
const FOLDERS: [prefix: string, folder: string][] = [
  ['/lib/', root('dist-lib/')],
  ['/three/', root('node_modules/three/')],
  ['/', root('e2e/pages/static/')],
];

/** A strict policy: scripts only from the host itself, workers from Blob URLs, no inline script or style, no eval. */
export const STRICT_CSP = [
  "default-src 'self'",
  "script-src 'self'",
  'worker-src blob:',
  "style-src 'self'",
  "img-src 'self' data: blob:",
  "connect-src 'self'",
  "object-src 'none'",
  "base-uri 'none'",
].join('; ');

export const ISOLATION_HEADERS = { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' };

/**
 * Serves the static host and the other site to `page` (through request interception: no server) and returns the
 * paths asked of the static host, in order. The static host's HTML pages get `pageHeaders`, the other site's none;
 * every file is served as it is on disk, with the content type of its extension, and a missing one is a 404.
 */
export async function serveStatic(page: Page, pageHeaders: Record<string, string> = {}): Promise<string[]> {
  const asked: string[] = [];
  for (const origin of [STATIC_ORIGIN, OTHER_ORIGIN]) {
    await page.route(`${origin}/**`, (route) => {
      const { pathname } = new URL(route.request().url());
      if (origin === STATIC_ORIGIN) asked.push(pathname);
      const [prefix, folder] = FOLDERS.find(([p]) => pathname.startsWith(p))!;
      const file = folder + decodeURIComponent(pathname.slice(prefix.length));
      if (!existsSync(file) || !statSync(file).isFile()) return route.fulfill({ status: 404, body: 'not found' });
      return route.fulfill({ path: file, headers: origin === STATIC_ORIGIN && file.endsWith('.html') ? pageHeaders : {} });
    });
  }
  return asked;
}
