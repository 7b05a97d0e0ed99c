import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, test } from './fixtures';
import { failedRequests, serveFiles } from './packed-app';

/**
 * `examples/static-html`: a plain page on a static host without a bundler or the isolation headers, with the library's
 * build copied beside it as `softface/`, shows a `<soft-face>` that answers an Action Unit, and fetches nothing missing.
 */
const ORIGIN = 'http://localhost:4397';
const root = (p: string): string => fileURLToPath(new URL(`../${p}`, import.meta.url));

test('the static HTML example shows a face from the standalone module that moves, fetching nothing missing', async ({ page }) => {
  test.setTimeout(120_000);
  const failed = failedRequests(page);
  await serveFiles(page, ORIGIN, (path) =>
    path.startsWith('/softface/') ? join(root('dist-lib'), path.slice('/softface/'.length)) : join(root('examples/static-html'), path),
  );
  await page.goto(`${ORIGIN}/`);
  await expect.poll(() => page.evaluate(() => document.querySelector('soft-face')?.face !== undefined), { timeout: 90_000 }).toBe(true);
  const moved = await page.evaluate(async () => {
    const face = document.querySelector('soft-face')!.face!;
    await face.ready;
    const { rest } = face.getSkin();
    face.setActionUnit('AU4', 1);
    await face.settle(60_000);
    const after = face.getSkin().positions;
    let most = 0;
    for (let i = 0; i < after.length; i++) most = Math.max(most, Math.abs(after[i] - rest[i]));
    return { isolated: crossOriginIsolated, mm: 1000 * most };
  });
  expect(moved.isolated).toBe(false);
  expect(moved.mm).toBeGreaterThan(2);
  expect(failed).toEqual([]);
});
