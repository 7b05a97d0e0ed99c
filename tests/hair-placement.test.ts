import { beforeAll, describe, expect, it } from 'vitest';
import { poseHair, type HairStrands } from '../src/core/hair/hair';
import { placeBrows, placeLashes } from '../src/core/hair/hair-placement';
import { DEFAULT_LANDMARKS } from '../src/core/head/landmarks';
import { loadHeadSkin } from './fixtures/head';
import { faceLandmarks } from './fixtures/face-landmarks';

/** The hairs posed at rest: per hair, its root (the midpoint of the ribbon's first two vertices) and its tip. */
function rootsAndTips(h: HairStrands, positions: Float32Array, normals: Float32Array) {
  const out = new Float32Array(3 * h.count * h.verticesPerHair);
  poseHair(h, positions, normals, out, new Float32Array(out.length));
  const per = h.verticesPerHair;
  const at = (hair: number, v: number, k: number): number => out[3 * (hair * per + v) + k];
  return {
    out,
    roots: Array.from({ length: h.count }, (_, i) => [0, 1, 2].map((k) => (at(i, 0, k) + at(i, 1, k)) / 2)),
    tips: Array.from({ length: h.count }, (_, i) => [0, 1, 2].map((k) => (at(i, per - 2, k) + at(i, per - 1, k)) / 2)),
  };
}

describe.each(['low', 'medium', 'high'] as const)('hair placed on the %s head', (resolution) => {
  let skin: Awaited<ReturnType<typeof loadHeadSkin>>;
  let surface: { positions: Float32Array; normals: Float32Array; triangles: Uint32Array };
  let eyes: { centre: [number, number, number]; radius: number }[];
  beforeAll(async () => {
    skin = await loadHeadSkin(resolution);
    surface = { positions: skin.positions, normals: skin.normals, triangles: skin.indices };
    eyes = [skin.pivots['eye-l'], skin.pivots['eye-r']].map((centre) => ({ centre, radius: skin.eyeRadius }));
  });

  it('grows brows above each eye: as many on each side, their roots half to one eye width over the corners', () => {
    const brows = placeBrows(surface, DEFAULT_LANDMARKS);
    const { roots } = rootsAndTips(brows, skin.positions, skin.normals);
    const left = roots.filter((r) => r[0] > 0);
    expect(left.length).toBe(roots.length / 2);
    expect(roots.length).toBeGreaterThan(800);
    const [inner, outer] = [DEFAULT_LANDMARKS['eye-inner-l'], DEFAULT_LANDMARKS['eye-outer-l']];
    const width = outer[0] - inner[0];
    for (const r of roots) {
      const x = Math.abs(r[0]);
      const above = (r[1] - (inner[1] + outer[1]) / 2) / width;
      expect(above).toBeGreaterThan(0.4);
      expect(above).toBeLessThan(0.95);
      expect(x).toBeGreaterThan(inner[0] - 0.2 * width);
      expect(x).toBeLessThan(outer[0] + 0.3 * width);
    }
  });

  it('keeps every lash out of the eyeballs at rest', () => {
    const lashes = placeLashes(surface, DEFAULT_LANDMARKS, eyes);
    const { out } = rootsAndTips(lashes, skin.positions, skin.normals);
    let nearest = Infinity;
    for (let v = 0; v < out.length; v += 3) {
      for (const eye of [skin.pivots['eye-l'], skin.pivots['eye-r']])
        nearest = Math.min(nearest, Math.hypot(out[v] - eye[0], out[v + 1] - eye[1], out[v + 2] - eye[2]));
    }
    expect(nearest).toBeGreaterThan(skin.eyeRadius);
  });

  it('places the same hairs every time (seeded)', () => {
    const a = placeBrows(surface, DEFAULT_LANDMARKS);
    const b = placeBrows(surface, DEFAULT_LANDMARKS);
    expect(Array.from(a.local)).toEqual(Array.from(b.local));
    expect(Array.from(a.corners)).toEqual(Array.from(b.corners));
  });
});

// The margin vertices are found by a search that takes 20 s on the high head, whose lids are the medium's subdivided:
// the low and medium heads are checked against it.
describe.each(['low', 'medium'] as const)('lashes placed on the %s head', (resolution) => {
  let skin: Awaited<ReturnType<typeof loadHeadSkin>>;
  let surface: { positions: Float32Array; normals: Float32Array; triangles: Uint32Array };
  let eyes: { centre: [number, number, number]; radius: number }[];
  beforeAll(async () => {
    skin = await loadHeadSkin(resolution);
    surface = { positions: skin.positions, normals: skin.normals, triangles: skin.indices };
    eyes = [skin.pivots['eye-l'], skin.pivots['eye-r']].map((centre) => ({ centre, radius: skin.eyeRadius }));
  });

  it('roots the lashes on the lid margins (within 1 mm of the margin vertices) and points them away from the eye', () => {
    const lashes = placeLashes(surface, DEFAULT_LANDMARKS, eyes);
    expect(lashes.count).toBeGreaterThan(200);
    const { roots, tips } = rootsAndTips(lashes, skin.positions, skin.normals);
    const eyeY = skin.pivots['eye-l'][1];
    const columns = faceLandmarks(skin.positions, skin.indices).lidColumns;
    const meanOf = (list: number[], k: number): number => list.reduce((s, i) => s + skin.positions[3 * i + k], 0) / list.length;
    let checked = 0;
    for (const c of columns) {
      const x = meanOf(c.upper, 0);
      for (const [i, r] of roots.entries()) {
        if (Math.abs(r[0] - x) > 0.0005) continue;
        const upper = r[1] > eyeY;
        // The low head's coarse lids leave some columns without margin vertices.
        if ((upper ? c.upper : c.lower).length === 0) continue;
        const margin = meanOf(upper ? c.upper : c.lower, 1);
        expect(Math.abs(r[1] - margin)).toBeLessThan(0.001);
        // Upper lashes end above their roots and in front of them; lower lashes lie down the lid, ending below.
        expect(Math.sign(tips[i][1] - r[1])).toBe(upper ? 1 : -1);
        if (upper) expect(tips[i][2]).toBeGreaterThan(r[2]);
        checked++;
      }
    }
    expect(checked).toBeGreaterThan(20);
  });
});
