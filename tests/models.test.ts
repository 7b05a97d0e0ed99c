import { readFileSync } from 'node:fs';
import { NodeIO, type Document } from '@gltf-transform/core';
import { beforeAll, describe, expect, it } from 'vitest';

/** The committed head models, read as a user of the files would: with a glTF reader. */
const FILES = [
  { name: 'low', min: 3_500, max: 5_000 },
  { name: 'medium', min: 15_000, max: 19_000 },
  { name: 'high', min: 60_000, max: 75_000 },
];

describe.each(FILES)('public/models/head-$name.glb', ({ name, min, max }) => {
  let doc: Document;
  let positions: Float32Array;
  let indices: Uint32Array;
  beforeAll(async () => {
    doc = await new NodeIO().readBinary(new Uint8Array(readFileSync(`public/models/head-${name}.glb`)));
    const skin = doc
      .getRoot()
      .listMeshes()
      .find((m) => m.getName() === 'skin')!;
    const prim = skin.listPrimitives()[0];
    positions = prim.getAttribute('POSITION')!.getArray() as Float32Array;
    indices = Uint32Array.from(prim.getIndices()!.getArray()!);
  });

  it(`has about ${min}..${max} skin vertices (distinct positions), as stated in its extras`, () => {
    const distinct = new Set<string>();
    for (let i = 0; i < positions.length; i += 3) distinct.add(`${positions[i]},${positions[i + 1]},${positions[i + 2]}`);
    expect(distinct.size).toBeGreaterThanOrEqual(min);
    expect(distinct.size).toBeLessThanOrEqual(max);
    const extras = doc.getRoot().getDefaultScene()!.getExtras() as { softface: { level: { skinVertices: number; name: string } } };
    expect(extras.softface.level).toMatchObject({ name, skinVertices: distinct.size });
  });

  it('is a head-sized, finite surface in metres whose only open edge is one loop around the neck', () => {
    expect(positions.findIndex((x) => !Number.isFinite(x))).toBe(-1);
    let minY = Infinity;
    let maxY = -Infinity;
    for (let i = 1; i < positions.length; i += 3) {
      minY = Math.min(minY, positions[i]);
      maxY = Math.max(maxY, positions[i]);
    }
    expect(maxY - minY).toBeGreaterThan(0.2);
    expect(maxY - minY).toBeLessThan(0.35);
    // Weld by position, then count edges used by one triangle only.
    const id = new Map<string, number>();
    const weld = new Uint32Array(positions.length / 3);
    for (let v = 0; v < weld.length; v++) {
      const key = `${positions[3 * v]},${positions[3 * v + 1]},${positions[3 * v + 2]}`;
      if (!id.has(key)) id.set(key, id.size);
      weld[v] = id.get(key)!;
    }
    const uses = new Map<number, number>();
    for (let t = 0; t < indices.length; t += 3) {
      for (let k = 0; k < 3; k++) {
        const a = weld[indices[t + k]];
        const b = weld[indices[t + ((k + 1) % 3)]];
        const key = a < b ? a * 2 ** 24 + b : b * 2 ** 24 + a;
        uses.set(key, (uses.get(key) ?? 0) + 1);
      }
    }
    const open = [...uses.entries()].filter(([, n]) => n === 1).map(([k]) => k);
    expect([...uses.values()].every((n) => n <= 2)).toBe(true);
    // Every open edge is low on the head (the neck), and they form one closed loop: each end vertex used twice.
    const ends = new Map<number, number>();
    for (const k of open) for (const v of [Math.floor(k / 2 ** 24), k % 2 ** 24]) ends.set(v, (ends.get(v) ?? 0) + 1);
    expect(open.length).toBeGreaterThan(10);
    expect([...ends.values()].every((n) => n === 2)).toBe(true);
    expect(ends.size).toBe(open.length);
  });

  it('has eyes at the eye pivots (left at +x), upper and lower teeth, a tongue under the jaw, and named pivots', () => {
    const node = (n: string) =>
      doc
        .getRoot()
        .listNodes()
        .find((x) => x.getName() === n);
    const extras = doc.getRoot().getDefaultScene()!.getExtras() as { softface: { pivots: Record<string, number[]> } };
    expect(node('eye-l')!.getTranslation()).toEqual(extras.softface.pivots['eye-l']);
    expect(node('eye-l')!.getTranslation()[0]).toBeGreaterThan(0.02);
    expect(node('eye-r')!.getTranslation()[0]).toBeLessThan(-0.02);
    expect(
      node('eye-l')!
        .getMesh()!
        .listPrimitives()
        .map((p) => p.getMaterial()!.getName()),
    ).toEqual(['sclera', 'iris', 'cornea']);
    for (const n of ['teeth-upper', 'teeth-lower', 'tongue'])
      expect(node(n)!.getMesh()!.listPrimitives()[0].getAttribute('POSITION')!.getCount()).toBeGreaterThan(100);
    expect(
      node('jaw')!
        .listChildren()
        .map((c) => c.getName()),
    ).toEqual(['teeth-lower', 'tongue']);
    for (const p of ['eye-l', 'eye-r', 'upperlid-l', 'lowerlid-r', 'jaw-hinge', 'chin']) expect(node(`pivot-${p}`)).toBeDefined();
  });

  it('places the lower teeth under the upper teeth and the tongue inside the arch, in world space', () => {
    const worldBox = (n: string) => {
      const node = doc
        .getRoot()
        .listNodes()
        .find((x) => x.getName() === n)!;
      const m = node.getWorldMatrix(); // translations only: column-major, translation in 12..14
      const p = node.getMesh()!.listPrimitives()[0].getAttribute('POSITION')!.getArray()!;
      const min = [Infinity, Infinity, Infinity];
      const max = [-Infinity, -Infinity, -Infinity];
      for (let i = 0; i < p.length; i += 3) {
        for (let k = 0; k < 3; k++) {
          min[k] = Math.min(min[k], p[i + k] + m[12 + k]);
          max[k] = Math.max(max[k], p[i + k] + m[12 + k]);
        }
      }
      return { min, max, centre: min.map((v, k) => (v + max[k]) / 2) };
    };
    const upper = worldBox('teeth-upper');
    const lower = worldBox('teeth-lower');
    const tongue = worldBox('tongue');
    expect(Math.abs(lower.centre[0])).toBeLessThan(0.001);
    expect(upper.centre[1] - lower.centre[1]).toBeGreaterThan(0.005);
    expect(upper.centre[1] - lower.centre[1]).toBeLessThan(0.03);
    expect(Math.abs(upper.centre[2] - lower.centre[2])).toBeLessThan(0.01);
    expect(tongue.centre[1]).toBeGreaterThan(lower.min[1]);
    expect(tongue.centre[1]).toBeLessThan(upper.max[1]);
    expect(tongue.centre[2]).toBeGreaterThan(lower.min[2] - 0.01);
    expect(tongue.centre[2]).toBeLessThan(lower.max[2]);
  });

  it('is listed in CREDITS.md with its counts', () => {
    const credits = readFileSync('public/models/CREDITS.md', 'utf8');
    const extras = doc.getRoot().getDefaultScene()!.getExtras() as { softface: { level: { skinVertices: number; triangles: number } } };
    const row = credits.split('\n').find((l) => l.startsWith(`| \`head-${name}.glb\``));
    expect(row).toContain(extras.softface.level.skinVertices.toLocaleString('en-US'));
    expect(row).toContain((indices.length / 3).toLocaleString('en-US'));
    expect(credits).toMatch(/MakeHuman/);
    expect(credits).toMatch(/CC0/);
  });
});
