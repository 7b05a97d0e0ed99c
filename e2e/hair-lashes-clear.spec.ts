import { readFileSync } from 'node:fs';
import { NodeIO } from '@gltf-transform/core';
import { openFace } from './face';
import { expect, test } from './shared-app';

/**
 * The lashes stay out of the eyeballs and out of the lids' skin: with the lids wide open (AU5), closed (AU43) and at
 * rest, no lash vertex is inside an eyeball (the model's eye pivots and radius), and no point of a lash's centre line
 * past its root is behind the skin near it (within 1.5 mm of a skin vertex, on the inner side of that vertex's normal
 * by more than 0.1 mm).
 */
test.describe.configure({ timeout: 300_000 });

async function eyes(): Promise<{ centres: number[][]; radius: number }> {
  const doc = await new NodeIO().readBinary(new Uint8Array(readFileSync('public/models/head-medium.glb')));
  const extras = doc.getRoot().getDefaultScene()!.getExtras() as { softface: { pivots: Record<string, number[]>; eyeRadius: number } };
  return { centres: [extras.softface.pivots['eye-l'], extras.softface.pivots['eye-r']], radius: extras.softface.eyeRadius };
}

for (const expression of ['neutral', 'AU5', 'AU43']) {
  test(`no lash enters an eyeball or the skin (${expression})`, async ({ page }) => {
    const eye = await eyes();
    await openFace(page, '/');
    const r = await page.evaluate(
      async ({ expression, eye }) => {
        const face = window.face;
        face.reset();
        if (expression !== 'neutral') face.setActionUnit(expression, 1);
        await face.settle(150_000);
        await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
        const { positions: skin, normals } = face.getSkin();
        const lashes = face.getHair().lashes;
        const p = lashes.positions;
        // Skin vertices around the eyes only: the lashes are nowhere else.
        const near: number[] = [];
        for (let v = 0; v < skin.length / 3; v++) {
          if (eye.centres.some((c) => Math.hypot(skin[3 * v] - c[0], skin[3 * v + 1] - c[1], skin[3 * v + 2] - c[2]) < 0.03)) near.push(v);
        }
        let inEye = Infinity;
        let behindSkin = -Infinity;
        const per = lashes.verticesPerHair;
        for (let i = 0; i < p.length; i += 3) {
          for (const c of eye.centres) inEye = Math.min(inEye, Math.hypot(p[i] - c[0], p[i + 1] - c[1], p[i + 2] - c[2]) - eye.radius);
        }
        // A lash's centre line: the middle of each pair of its ribbon's vertices. The root and the first point out
        // stand on the lid's rounded margin, where the nearest vertex's normal says little about which side of the
        // skin a point is: the free part of the lash is checked.
        for (let i = 0; i < p.length; i += 6) {
          if ((i / 3) % per < 4) continue;
          const m = [0, 1, 2].map((k) => (p[i + k] + p[i + 3 + k]) / 2);
          let best = -1;
          let bestD = 0.0015;
          for (const v of near) {
            const d = Math.hypot(m[0] - skin[3 * v], m[1] - skin[3 * v + 1], m[2] - skin[3 * v + 2]);
            if (d < bestD) {
              bestD = d;
              best = v;
            }
          }
          if (best < 0) continue;
          const depth = -(
            (m[0] - skin[3 * best]) * normals[3 * best] +
            (m[1] - skin[3 * best + 1]) * normals[3 * best + 1] +
            (m[2] - skin[3 * best + 2]) * normals[3 * best + 2]
          );
          behindSkin = Math.max(behindSkin, depth);
        }
        return { lashes: lashes.count, inEye, behindSkin };
      },
      { expression, eye },
    );
    expect(r.lashes).toBeGreaterThan(200);
    // Distances in metres: the nearest lash vertex to an eyeball's surface (positive: outside it), and the deepest
    // one behind the skin near it.
    expect(r.inEye).toBeGreaterThan(0);
    expect(r.behindSkin).toBeLessThan(0.0001);
  });
}
