import { readFileSync } from 'node:fs';
import { NodeIO } from '@gltf-transform/core';
import { beforeAll, describe, expect, it } from 'vitest';
import { DEEP_MOUTH_LIGHT, mouthLight, SKIN_TINT_DEFAULTS, skinTint } from '../src/render/skin-tint';

describe('the light inside the mouth', () => {
  it('is whole just behind the lips and falls smoothly to DEEP_MOUTH_LIGHT 5 cm in', () => {
    const front = 0.15;
    expect(mouthLight(front, front)).toBe(1);
    expect(mouthLight(front - 0.005, front)).toBe(1);
    expect(mouthLight(front - 0.05, front)).toBeCloseTo(DEEP_MOUTH_LIGHT, 12);
    expect(mouthLight(front - 0.2, front)).toBeCloseTo(DEEP_MOUTH_LIGHT, 12);
    let last = Infinity;
    for (let z = front; z >= front - 0.06; z -= 0.001) {
      const light = mouthLight(z, front);
      expect(light).toBeLessThanOrEqual(last);
      last = light;
    }
  });
});

describe('the default head’s skin tint', () => {
  let positions: Float32Array;
  let tint: Float32Array;
  beforeAll(async () => {
    const doc = await new NodeIO().readBinary(new Uint8Array(readFileSync(new URL('../public/models/head-medium.glb', import.meta.url))));
    const prim = doc
      .getRoot()
      .listMeshes()
      .find((m) => m.getName() === 'skin')!
      .listPrimitives()[0];
    positions = Float32Array.from(prim.getAttribute('POSITION')!.getArray()!);
    tint = skinTint(positions, prim.getAttribute('TEXCOORD_0')!.getArray()!);
  });

  it('darkens the whole inside of the mouth, the throat most', () => {
    const [, my, front] = SKIN_TINT_DEFAULTS.mouth;
    const throat: number[] = [];
    const behindLips: number[] = [];
    for (let v = 0; v < positions.length / 3; v++) {
      const [x, y, z] = [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
      if (Math.abs(x) > 0.02 || Math.abs(y - my) > 0.035 || z < 0.02) continue;
      // 3.5 cm or more behind the slit, within 2 cm of the midline, is the mouth's inside (the face's skin there lies
      // farther forward): every vertex tinted and dark. The deep palate and throat were once left untinted and shone
      // as bright as the cheeks.
      if (z < front - 0.035) {
        expect(tint[3 * v], `vertex ${v} at z ${z.toFixed(3)}`).toBeLessThan(0.4);
        throat.push(tint[3 * v]);
      } else if (z < front - 0.006 && z > front - 0.012 && Math.abs(y - my) < 0.008 && tint[3 * v] < 0.9) behindLips.push(tint[3 * v]);
    }
    const mean = (a: number[]): number => a.reduce((s, t) => s + t, 0) / a.length;
    expect(throat.length).toBeGreaterThan(300);
    expect(behindLips.length).toBeGreaterThan(10);
    // Just behind the lips the inner mouth keeps most of its light: over twice the throat's.
    expect(mean(behindLips)).toBeGreaterThan(2 * mean(throat));
  });
});
