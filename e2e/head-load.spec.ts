import { readFileSync } from 'node:fs';
import { NodeIO } from '@gltf-transform/core';
import type { HeadDescription } from '../src/face/head-loader';
import type { Page } from '@playwright/test';
import { openFace } from './face';
import { expect, test } from './fixtures';
import { control, openFolder } from './panels';

/**
 * How far AU12 lifts the mouth corners and AU1 the inner brows, relative to the head's size (the distance between
 * the outer eye corners), as the mean lift of the skin within a tenth of that size of the head's own landmarks (so
 * that meshes of different density are measured alike).
 */
async function lifts(page: Page): Promise<{ au12: number; au1: number; size: number; landmarks: HeadDescription['landmarks'] }> {
  return page.evaluate(async () => {
    const face = window.face;
    const { landmarks: L } = face.describeHead();
    const size = Math.hypot(...[0, 1, 2].map((k) => L['eye-outer-l'][k] - L['eye-outer-r'][k]));
    const { rest } = face.getSkin();
    const near = (p: number[]): number[] => {
      const out: number[] = [];
      for (let v = 0; v < rest.length / 3; v++) {
        if (Math.hypot(rest[3 * v] - p[0], rest[3 * v + 1] - p[1], rest[3 * v + 2] - p[2]) < 0.1 * size) out.push(v);
      }
      return out;
    };
    const lift = async (id: string, names: string[]): Promise<number> => {
      const vertices = names.flatMap((n) => near(L[n as keyof typeof L]));
      face.reset();
      face.setActionUnit(id, 1);
      await face.settle(120_000);
      const { positions } = face.getSkin();
      const up = vertices.reduce((s, v) => s + positions[3 * v + 1] - rest[3 * v + 1], 0) / vertices.length;
      face.reset();
      return up / size;
    };
    return { au12: await lift('AU12', ['mouth-l', 'mouth-r']), au1: await lift('AU1', ['brow-l', 'brow-r']), size, landmarks: L };
  });
}

test.describe.configure({ timeout: 300_000 });

test(
  'a GLB, a glTF with its buffer and an OBJ head with their own meshes and ' +
    'proportions load, and AU12 and AU1 move them as much as the default head',
  async ({ page }) => {
    await openFace(page, '/?resolution=low');
    const reference = await lifts(page);
    await openFolder(page, 'Head');
    let firstVertices = 0;
    for (const file of ['wide-jaw.glb', 'long-face.obj']) {
      await control(page, 'head-file').setInputFiles({
        name: file,
        mimeType: 'application/octet-stream',
        buffer: readFileSync(new URL(`./assets/${file}`, import.meta.url)),
      });
      await expect(control(page, 'head-message')).toContainText(`loaded ${file}`, { timeout: 60_000 });
      // The GLB brings its own eyes (nodes eye-l, eye-r); the OBJ has none, and gets the default head's, carried over.
      const parts = file.endsWith('.glb')
        ? { eyes: 'file', teeth: 'default', jaw: 'default' }
        : { eyes: 'default', teeth: 'default', jaw: 'default' };
      const head = await page.evaluate(() => window.face.describeHead());
      expect(head).toMatchObject({ source: 'loaded', name: file, parts });
      firstVertices ||= head.vertices;
      const m = await lifts(page);
      expect(m.au12).toBeGreaterThan(0.7 * reference.au12);
      expect(m.au12).toBeLessThan(1.3 * reference.au12);
      expect(m.au1).toBeGreaterThan(0.7 * reference.au1);
      expect(m.au1).toBeLessThan(1.3 * reference.au1);
    }

    // The GLB as a .gltf with its side file, given together: the same head.
    const glb = await page.evaluate(() => window.face.describeHead());
    expect(glb.name).toBe('long-face.obj');
    const io = new NodeIO();
    const { json, resources } = await io.writeJSON(
      await io.readBinary(new Uint8Array(readFileSync(new URL('./assets/wide-jaw.glb', import.meta.url)))),
    );
    const files = [
      { name: 'wide-jaw.gltf', mimeType: 'model/gltf+json', buffer: Buffer.from(JSON.stringify(json)) },
      ...Object.entries(resources).map(([name, bytes]) => ({ name, mimeType: 'application/octet-stream', buffer: Buffer.from(bytes) })),
    ];
    expect(files.length).toBeGreaterThan(1);
    await control(page, 'head-file').setInputFiles(files);
    await expect(control(page, 'head-message')).toContainText('loaded wide-jaw.gltf', { timeout: 60_000 });
    expect(await page.evaluate(() => window.face.describeHead())).toMatchObject({
      source: 'loaded',
      name: 'wide-jaw.gltf',
      vertices: firstVertices,
      parts: { eyes: 'file' },
    });

    // By URL, the default head's own model file: its eyes, teeth and jaw are taken from its named nodes, and its
    // landmarks are found where the default head has them.
    const own = await page.evaluate(async () => window.face.loadHead('models/head-low.glb'));
    expect(own).toMatchObject({ source: 'loaded', name: 'head-low.glb', parts: { eyes: 'file', teeth: 'file', jaw: 'file' } });
    for (const [name, p] of Object.entries(own.landmarks)) {
      const q = reference.landmarks[name as keyof typeof reference.landmarks];
      expect(Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]), name).toBeLessThan(0.001);
    }
  },
);
