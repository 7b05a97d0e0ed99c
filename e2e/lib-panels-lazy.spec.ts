import { expect, test } from './fixtures';
import { ISOLATION_HEADERS, STATIC_ORIGIN, serveStatic } from './static-host';

test('the library fetches the panels (and lil-gui) only when a face first shows them: face.setPanels(on) shows and removes them', async ({
  page,
}) => {
  const asked = await serveStatic(page, ISOLATION_HEADERS);
  await page.goto(`${STATIC_ORIGIN}/modules.html`);
  await expect(page.locator('html')).toHaveAttribute('data-state', 'ready');
  const panelsModules = () => [...new Set(asked)].filter((f) => /^\/lib\/panels-[\w-]+\.js$/.test(f));
  const before = await page.evaluate(async () => {
    const element = document.querySelector('soft-face')!;
    if (!element.face) await new Promise((resolve) => element.addEventListener('ready', resolve, { once: true }));
    const face = element.face!;
    return { hasPanels: face.hasPanels(), shown: document.querySelectorAll('.softface-panels').length, background: face.getBackground() };
  });
  expect(before).toEqual({ hasPanels: false, shown: 0, background: expect.stringMatching(/^(#[0-9a-f]{6}|transparent)$/) });
  expect(panelsModules()).toEqual([]);

  const shown = await page.evaluate(async () => {
    const face = document.querySelector('soft-face')!.face!;
    await face.setPanels(true);
    return { hasPanels: face.hasPanels(), shown: document.querySelectorAll('soft-face .softface-panels').length };
  });
  expect(shown).toEqual({ hasPanels: true, shown: 1 });
  expect(panelsModules()).toHaveLength(1);

  const removed = await page.evaluate(async () => {
    const face = document.querySelector('soft-face')!.face!;
    await face.setPanels(false);
    face.setBackground('#102030');
    return { hasPanels: face.hasPanels(), shown: document.querySelectorAll('.softface-panels').length, background: face.getBackground() };
  });
  expect(removed).toEqual({ hasPanels: false, shown: 0, background: '#102030' });

  // A bad value is refused, naming it, and changes nothing.
  const refused = await page.evaluate(async () => {
    const face = document.querySelector('soft-face')!.face!;
    const messages: string[] = [];
    // @ts-expect-error: a value of the wrong type, as a script might pass
    await face.setPanels('yes').catch((e: Error) => messages.push(e.message));
    try {
      face.setBackground('red');
    } catch (e) {
      messages.push((e as Error).message);
    }
    return { messages, hasPanels: face.hasPanels(), background: face.getBackground() };
  });
  expect(refused.messages).toHaveLength(2);
  expect(refused.messages[0]).toContain('setPanels');
  expect(refused.messages[1]).toContain('setBackground');
  expect(refused).toMatchObject({ hasPanels: false, background: '#102030' });
});
