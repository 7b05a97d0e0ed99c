import { expect, test } from '@playwright/test';

/**
 * The tests' Chromium (scripts/browser.mjs): the address bar's WebUI popups, which Chromium 156 loads in a renderer of
 * their own behind every new window, are not loaded; and Playwright's own switched-off features stay off. Chromium
 * reads only the last `--disable-features`, and ours comes after Playwright's, so it has to name all of Playwright's.
 */
test("the tests' browser loads no address-bar popup behind a page and keeps Playwright's switched-off features", async ({
  browser,
  page,
}) => {
  await page.goto('chrome://version');
  const commandLine = (await page.locator('#command_line').textContent()) ?? '';
  const lists = [...commandLine.matchAll(/--disable-features=(\S+)/g)].map((m) => m[1].split(','));
  expect(lists.length, 'a --disable-features switch of ours').toBeGreaterThanOrEqual(2);
  const last = new Set(lists[lists.length - 1]);
  for (const list of lists.slice(0, -1)) for (const feature of list) expect([...last], `${feature} stays off`).toContain(feature);

  const cdp = await browser.newBrowserCDPSession();
  const { targetInfos } = await cdp.send('Target.getTargets');
  await cdp.detach();
  expect(targetInfos.filter((t) => t.url.includes('omnibox')).map((t) => t.url)).toEqual([]);
  expect(targetInfos.some((t) => t.type === 'page' && t.url === 'chrome://version/')).toBe(true);
});
