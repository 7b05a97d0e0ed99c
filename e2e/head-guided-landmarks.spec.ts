import { openFace } from './face';
import { expect, test } from './fixtures';
import { sphereObj } from './meshes';
import { control, openFolder } from './panels';

type Vec3 = [number, number, number];

test('a head whose landmarks are not found gets them by guided clicks and then loads with them; cancelling keeps the current head', async ({
  page,
}) => {
  await openFace(page, '/?resolution=low');
  const before = await page.evaluate(() => window.face.describeHead());
  await openFolder(page, 'Head');
  const ball = { name: 'ball.obj', mimeType: 'text/plain', buffer: Buffer.from(sphereObj(64)) };
  await control(page, 'head-file').setInputFiles(ball);
  await expect(control(page, 'head-message')).toContainText('ball.obj: no face was found on the mesh');

  // Where each landmark goes on the ball: the default head's, turned about its middle onto the ball's surface.
  const spot = (p: readonly number[]): Vec3 => {
    const d = [p[0], p[1] - 0.72, p[2] - 0.05];
    const l = Math.hypot(d[0], d[1], d[2]);
    return [(0.0995 * d[0]) / l, 0.7 + (0.0995 * d[1]) / l, (0.0995 * d[2]) / l];
  };
  const defaults = before.landmarks;

  // A dispatched click: Playwright's hit test trips over the folder's height transition here.
  await control(page, 'guide-landmarks').locator('button').dispatchEvent('click');
  await expect(control(page, 'head-message')).toHaveText("ball.obj: click the left eye's inner corner (1 of 13)");
  // Two real clicks on the shown skin, each placing the landmark asked for where it was clicked.
  for (const [name, next] of [
    ['eye-inner-l', "the left eye's outer corner (2 of 13)"],
    ['eye-outer-l', "the right eye's inner corner (3 of 13)"],
  ] as const) {
    const target = spot(defaults[name]);
    const at = await page.evaluate((p) => window.face.locateLandmarkPoint(p), target);
    await page.mouse.click(at!.x, at!.y);
    await expect(control(page, 'head-message')).toHaveText(`ball.obj: click ${next}`);
    const placed = await page.evaluate((n) => window.face.describeLandmarkGuide()!.placed[n], name);
    expect(Math.hypot(placed![0] - target[0], placed![1] - target[1], placed![2] - target[2]), name).toBeLessThan(0.002);
  }
  // A click beside the ball places nothing.
  const box = (await page.locator('canvas').boundingBox())!;
  await page.mouse.click(box.x + 20, box.y + 20);
  expect(await page.evaluate(() => Object.keys(window.face.describeLandmarkGuide()!.placed))).toEqual(['eye-inner-l', 'eye-outer-l']);

  await control(page, 'cancel-landmarks').locator('button').dispatchEvent('click');
  await expect(control(page, 'head-message')).toHaveText('ball.obj: placing the landmarks was cancelled');
  expect(await page.evaluate(() => window.face.describeHead())).toEqual(before);

  // Again, placing every missing landmark: the head loads with them.
  const loading = page.evaluate((text) => window.face.guideLandmarks(new File([text], 'ball.obj')).then((h) => h.landmarks), sphereObj(64));
  await expect.poll(() => page.evaluate(() => window.face.describeLandmarkGuide()?.next ?? null)).toBe('eye-inner-l');
  const missing = await page.evaluate(() => window.face.describeLandmarkGuide()!.missing);
  for (const name of missing) await page.evaluate(({ p }) => window.face.placeLandmark(p), { p: spot(defaults[name]) });
  const landmarks = await loading;
  for (const name of missing) expect(landmarks[name]).toEqual(spot(defaults[name]));
  expect(await page.evaluate(() => window.face.describeHead())).toMatchObject({ source: 'loaded', name: 'ball.obj' });
});
