import { addElement, openEmbedPage, takeEvents } from './embed';
import { expect, test } from './fixtures';

test('<soft-face identity="...">: the face starts as that person, a new value switches live, a bad one is reported', async ({ page }) => {
  test.setTimeout(120_000);
  await openEmbedPage(page);
  await addElement(page, 'f', { resolution: 'low', identity: 'old-asian-man', expression: 'AU12=0.6' });
  expect(await takeEvents(page, 'f')).toEqual([{ type: 'ready' }]);
  const shown = () =>
    page.evaluate(() => {
      const f = document.querySelector('soft-face')!.face!;
      const h = f.describeHead();
      return { source: h.source, name: h.name, identity: f.getIdentity(), au12: f.getActionUnits().AU12L };
    });
  expect(await shown()).toEqual({
    source: 'identity',
    name: 'old-asian-man',
    identity: { sex: 1, age: 72, ancestry: { african: 0, asian: 1, european: 0 } },
    au12: 0.6,
  });
  await page.evaluate(() => document.querySelector('soft-face')!.setAttribute('identity', 'sex:0,age:30,african:1'));
  await expect.poll(async () => (await shown()).name, { timeout: 30_000 }).toBe('sex:0,age:30,african:1');
  expect((await shown()).au12).toBe(0.6);
  const events = await takeEvents(page, 'f');
  expect(events).toContainEqual({ type: 'change', what: 'head' });
  // A bad value: an error event naming it, and the person stays.
  await page.evaluate(() => document.querySelector('soft-face')!.setAttribute('identity', 'sex:1,age:200'));
  // Checked as the attribute changes: the error comes at once.
  expect(await takeEvents(page, 'f')).toEqual([
    { type: 'error', what: '<soft-face> identity: age: expected a number from 1 to 90, got 200' },
  ]);
  expect((await shown()).name).toBe('sex:0,age:30,african:1');
  // Removed: the default head.
  await page.evaluate(() => document.querySelector('soft-face')!.removeAttribute('identity'));
  await expect.poll(async () => (await shown()).source, { timeout: 30_000 }).toBe('default');
});
