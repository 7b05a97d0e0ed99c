import { expect, test } from './fixtures';
import { OTHER_ORIGIN, STATIC_ORIGIN, serveStatic } from './static-host';

/** Waits for the framed page's `<soft-face>`, opens its jaw and reports how it runs and how far the skin moved. */
async function framedFace(
  page: import('@playwright/test').Page,
): Promise<{ isolated: boolean; mode: string; moved: number; framed: boolean }> {
  await expect(page.frameLocator('#frame').locator('html')).toHaveAttribute('data-state', 'ready');
  const inner = page.frames().find((f) => f.url().startsWith(STATIC_ORIGIN))!;
  return inner.evaluate(async () => {
    const element = document.querySelector('soft-face')!;
    if (!element.face) await new Promise((resolve) => element.addEventListener('ready', resolve, { once: true }));
    const face = element.face!;
    face.setActionUnit('AU26', 1);
    await face.settle(45_000);
    const { rest, positions } = face.getSkin();
    let moved = 0;
    for (let i = 0; i < rest.length; i++) moved = Math.max(moved, Math.abs(positions[i] - rest[i]));
    return { isolated: crossOriginIsolated, mode: face.stats().mode, moved, framed: window.top !== window };
  });
}

test("a face in another site's iframe runs, in transfer mode where nothing is isolated", async ({ page }) => {
  await serveStatic(page);
  await page.goto(`${OTHER_ORIGIN}/iframe.html`);
  const r = await framedFace(page);
  expect(r).toMatchObject({ isolated: false, mode: 'transfer', framed: true });
  // AU26 opens the jaw by centimetres: the face solves, it does not just show.
  expect(r.moved).toBeGreaterThan(0.005);
});

test('Document-Isolation-Policy isolates a framed face on its own, for shared mode, where COOP/COEP cannot', async ({ page }) => {
  // The embedding page sends nothing; only the framed page asks for isolation, for itself.
  await serveStatic(page, { 'Document-Isolation-Policy': 'isolate-and-require-corp' });
  await page.goto(`${OTHER_ORIGIN}/iframe.html`);
  expect(await page.evaluate(() => crossOriginIsolated)).toBe(false);
  const r = await framedFace(page);
  expect(r).toMatchObject({ isolated: true, mode: 'shared', framed: true });
  expect(r.moved).toBeGreaterThan(0.005);
});
