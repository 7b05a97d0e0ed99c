import { expect, test, waitForHead } from './fixtures';

// A face used to fetch its rig, then look for a kept head, then fetch the head model: on a link with 100 ms of latency
// at 20 Mbit/s it showed its head 0.6 to 0.75 s later than when all three go at once (docs/page-notes.md).
test('a face asks for its head model and room light while its rig is still on the way', async ({ page }) => {
  const asked = new Set<string>();
  let sendRig!: () => void;
  const rigHeld = new Promise<void>((resolve) => {
    sendRig = resolve;
  });
  await page.route('**/rigs/default.json', async (route) => {
    await rigHeld;
    await route.continue();
  });
  page.on('request', (request) => asked.add(new URL(request.url()).pathname.split('/').pop() ?? ''));
  await page.goto('/');
  await expect
    .poll(() => ['default.json', 'head-medium.glb', 'room.pmrem'].filter((f) => asked.has(f)))
    .toEqual(['default.json', 'head-medium.glb', 'room.pmrem']);
  sendRig();
  await waitForHead(page);
});
