import { openFace } from './face';
import { expect, test } from './shared-app';

test('the skin has a pore normal map, sheen and the subsurface look; eyes, teeth, gums and tongue have their own materials', async ({
  page,
}) => {
  await openFace(page, '/?resolution=low');
  const materials = await page.evaluate(() => window.face.describeMaterials());
  const byName = Object.fromEntries(materials.map((m) => [m.name, m]));
  expect(Object.keys(byName).sort()).toEqual(['cornea', 'eyebrows', 'eyelashes', 'gums', 'iris', 'sclera', 'skin', 'teeth', 'tongue']);

  const skin = byName.skin;
  expect(skin.type).toBe('MeshPhysicalMaterial');
  expect(skin.normalMap).not.toBeNull();
  const pores = skin.normalMap!;
  expect(pores.width).toBeGreaterThanOrEqual(256);
  expect(pores.seed).not.toBeNull();
  // Pore detail: a share of texels lean away from flat, and the map averages out flat (no tilt of the whole skin).
  expect(pores.detail).toBeGreaterThan(0.05);
  expect(Math.abs(pores.mean[0])).toBeLessThan(0.02);
  expect(Math.abs(pores.mean[1])).toBeLessThan(0.02);
  expect(pores.normalScale[0]).toBeGreaterThan(0);
  // Tiled finely: pores are millimetres on a head whose uvs span about a metre.
  expect(pores.repeat[0]).toBeGreaterThanOrEqual(4);
  expect(skin.sheen).toBeGreaterThan(0);
  // The subsurface look: diffuse light wraps past the terminator, red furthest.
  expect(skin.subsurface).not.toBeNull();
  const [r, g, b] = skin.subsurface!.wrap;
  expect(r).toBeGreaterThan(g);
  expect(g).toBeGreaterThanOrEqual(b);
  expect(b).toBeGreaterThan(0);

  expect(byName.iris.map).not.toBeNull();
  expect(byName.sclera.map).not.toBeNull();
  expect(byName.cornea.transparent).toBe(true);
  expect(byName.cornea.clearcoat).toBeGreaterThan(0.5);
  expect(byName.cornea.roughness).toBeLessThan(0.1);
  // Teeth: off-white (light, but not pure white), warm, glossy enamel.
  const teeth = [1, 3, 5].map((i) => parseInt(byName.teeth.color.slice(i, i + 2), 16));
  expect(Math.max(...teeth)).toBeLessThan(0xf0);
  expect(Math.min(...teeth)).toBeGreaterThan(0xb0);
  expect(teeth[0]).toBeGreaterThan(teeth[2]);
  expect(byName.teeth.roughness).toBeGreaterThan(0.2);
  expect(byName.teeth.roughness).toBeLessThan(0.4);
  // Gums: pink, redder than the teeth and far less bright.
  const gums = [1, 3, 5].map((i) => parseInt(byName.gums.color.slice(i, i + 2), 16));
  expect(gums[0]).toBeGreaterThan(1.4 * gums[1]);
  expect(gums[0]).toBeGreaterThan(gums[2]);
  expect(gums[1]).toBeLessThan(teeth[1] - 0x30);
  // Tongue: pinkish red and rough.
  const tongue = [1, 3, 5].map((i) => parseInt(byName.tongue.color.slice(i, i + 2), 16));
  expect(tongue[0]).toBeGreaterThan(1.5 * tongue[1]);
  expect(byName.tongue.roughness).toBeGreaterThan(0.3);

  // Wireframe still reaches every one of the new materials but the hair's (drawn as their edges, the lashes turned to
  // black blots), and comes back.
  await page.evaluate(() => window.face.setRenderOptions({ wireframe: true }));
  const hair = ['eyebrows', 'eyelashes'];
  const wired = await page.evaluate(() => window.face.describeMaterials());
  expect(wired.filter((m) => !hair.includes(m.name)).every((m) => m.wireframe)).toBe(true);
  expect(wired.filter((m) => hair.includes(m.name)).some((m) => m.wireframe)).toBe(false);
  await page.evaluate(() => window.face.setRenderOptions({ wireframe: false }));
  expect((await page.evaluate(() => window.face.describeMaterials())).some((m) => m.wireframe)).toBe(false);
});

test('the brows and lashes are dark hair by default and take the colours setAppearance gives them', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const colour = (name: string): Promise<string> =>
    page.evaluate((name) => window.face.describeMaterials().find((m) => m.name === name)!.color, name);
  for (const name of ['eyebrows', 'eyelashes']) {
    const rgb = [1, 3, 5].map(async (i) => parseInt((await colour(name)).slice(i, i + 2), 16));
    const [r, g, b] = await Promise.all(rgb);
    // Dark, and warm (brown to black, not grey-blue).
    expect(Math.max(r, g, b)).toBeLessThan(0x60);
    expect(r).toBeGreaterThanOrEqual(b);
  }
  await page.evaluate(() => window.face.setAppearance({ browColor: '#a07850', lashColor: '#302010' }));
  expect(await colour('eyebrows')).toBe('#a07850');
  expect(await colour('eyelashes')).toBe('#302010');
});
