import { openFace } from './face';
import { expect, test } from './fixtures';
import { control } from './panels';

test('the outputs show frames per second, solver time, the skin and the worker mode', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const value = async (name: string): Promise<string> => control(page, `output-${name}`).locator('input').inputValue();
  // Wake the solver so that it has a solve time to show.
  await page.evaluate(() => window.face.setActionUnit('AU12', 0.5));
  // Software WebGL on a busy machine may take seconds for a frame, and the rate needs a few frames or 3 s.
  await expect.poll(async () => Number(await value('fps')), { timeout: 30_000 }).toBeGreaterThan(0);
  await expect.poll(async () => Number(await value('solverMs')), { timeout: 10_000 }).toBeGreaterThan(0);
  const shown = {
    fps: Number(await value('fps')),
    solverMs: Number(await value('solverMs')),
    vertices: await value('vertices'),
    edges: await value('edges'),
    muscle: Number(await value('muscle')),
    position: await value('position'),
    mode: await value('mode'),
  };
  console.log(`outputs: ${JSON.stringify(shown)}`);
  // The panel's rate agrees with frames counted here over 3 s (loosely: the page's frame time varies), while the
  // camera turns a little at every animation frame, so that the view draws at each.
  await page.evaluate(() => {
    let yaw = 0;
    const turn = (): void => {
      yaw = (yaw + 0.5) % 10;
      window.face.setCamera({ yaw });
      requestAnimationFrame(turn);
    };
    requestAnimationFrame(turn);
  });
  await page.waitForTimeout(3500);
  const counted = await page.evaluate(
    () =>
      new Promise<number>((resolve) => {
        let frames = 0;
        const start = performance.now();
        const count = (now: number): void => {
          frames++;
          if (now - start < 3000) requestAnimationFrame(count);
          else resolve((1000 * frames) / (now - start));
        };
        requestAnimationFrame(count);
      }),
  );
  const fpsNow = Number(await value('fps'));
  console.log(`fps: panel ${fpsNow}, counted ${counted.toFixed(2)}`);
  expect(fpsNow).toBeGreaterThan(counted / 2);
  expect(fpsNow).toBeLessThan(counted * 2);
  expect(shown.vertices).toBe('4284');
  expect(shown.edges).toBe('12807');
  expect(shown.position).toBe('4284');
  expect(shown.mode).toBe(await page.evaluate(() => window.face.stats().mode));
  expect(['shared', 'transfer', 'main']).toContain(shown.mode);
  // The smile holds skin with muscle constraints, and the panel says how many.
  await expect.poll(async () => Number(await value('muscle')), { timeout: 10_000 }).toBeGreaterThan(0);
});
