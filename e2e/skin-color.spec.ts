import { openFace } from './face';
import { expect, test } from './shared-app';
import { faceCrop, pictureDifference } from './panels';

test('setAppearance({ skinColor }) darkens the skin as asked, stays in the link, and the default gives the first picture back', async ({
  page,
}) => {
  await openFace(page, '/?resolution=low');
  const skin = (): Promise<string> => page.evaluate(() => window.face.describeMaterials().find((m) => m.name === 'skin')!.color);
  expect(await page.evaluate(() => window.face.getAppearance().skinColor)).toBe('#cba08b');
  const light = await faceCrop(page);

  await page.evaluate(() => window.face.setAppearance({ skinColor: '#6b4630' }));
  expect(await skin()).toBe('#6b4630');
  const dark = await faceCrop(page, light.rect);
  console.log(`face crop mean grey: default ${light.mean.toFixed(1)}, #6b4630 ${dark.mean.toFixed(1)}`);
  expect(dark.mean).toBeLessThan(0.75 * light.mean);
  // The link keeps it.
  await expect.poll(() => page.evaluate(() => decodeURIComponent(location.hash))).toContain('skinColor=#6b4630');

  const refused = await page.evaluate(() => {
    try {
      window.face.setAppearance({ skinColor: 'brown' });
      return 'accepted';
    } catch (error) {
      return (error as Error).message;
    }
  });
  expect(refused).toBe('setAppearance: skinColor: expected a colour "#rrggbb", got "brown"');
  expect(await skin()).toBe('#6b4630');

  await page.evaluate(() => window.face.setAppearance({ skinColor: '#cba08b' }));
  const back = await faceCrop(page, light.rect);
  expect(pictureDifference(light, back)).toBeLessThan(0.5);
});
