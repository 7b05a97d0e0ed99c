import { readFileSync } from 'node:fs';
import { openFace } from './face';
import { expect, test } from './fixtures';
import { sphereObj } from './meshes';
import { control, openFolder } from './panels';

const GLB = readFileSync(new URL('./assets/wide-jaw.glb', import.meta.url));

test('files that are not a usable head are refused with a message naming what is wrong, and the face keeps its head and rig', async ({
  page,
}) => {
  await openFace(page, '/?resolution=low');
  const before = await page.evaluate(() => ({
    head: window.face.describeHead(),
    rig: window.face.getRig(),
    rest: Array.from(window.face.getSkin().rest),
  }));
  const cases: { name: string; text?: string; bytes?: number[]; message: string }[] = [
    { name: 'notes.glb', text: 'these are not the bytes of a model', message: 'notes.glb: not a readable glTF file' },
    { name: 'cut.glb', bytes: Array.from(GLB.subarray(0, GLB.length >> 1)), message: 'cut.glb: not a readable glTF file' },
    { name: 'nan.obj', text: 'v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n', message: 'nan.obj: vertex 2 has a non-finite' },
    { name: 'points.obj', text: 'v 0 0 0\nv 1 0 0\nv 0 1 0\n', message: 'points.obj: not a readable OBJ file (it has no faces (f lines))' },
    { name: 'ball.obj', text: sphereObj(64), message: "ball.obj: no face was found on the mesh: the left eye's inner corner" },
    {
      name: 'dense.obj',
      text: sphereObj(317),
      message: 'dense.obj: the mesh has 200,978 triangles, more than the 200,000 a head may have',
    },
  ];
  for (const c of cases) {
    const error = await page.evaluate(async ({ name, text, bytes }) => {
      const data = bytes ? new Uint8Array(bytes) : new TextEncoder().encode(text);
      try {
        await window.face.loadHead(new File([data], name));
        return 'loaded';
      } catch (e) {
        return (e as Error).message;
      }
    }, c);
    expect(error, c.name).toContain(c.message);
  }
  // Through the panel: the message shows in the Head folder.
  await openFolder(page, 'Head');
  await control(page, 'head-file').setInputFiles({ name: 'ball.obj', mimeType: 'text/plain', buffer: Buffer.from(sphereObj(64)) });
  await expect(control(page, 'head-message')).toContainText('ball.obj: no face was found on the mesh');

  const after = await page.evaluate(() => ({
    head: window.face.describeHead(),
    rig: window.face.getRig(),
    rest: Array.from(window.face.getSkin().rest),
  }));
  expect(after).toEqual(before);
  expect(after.head.source).toBe('default');
  // And the face still moves.
  const moved = await page.evaluate(async () => {
    window.face.setActionUnit('AU12', 1);
    await window.face.settle(60_000);
    const { rest, positions } = window.face.getSkin();
    return positions.reduce((m, p, i) => Math.max(m, Math.abs(p - rest[i])), 0);
  });
  expect(moved).toBeGreaterThan(0.003);
});
