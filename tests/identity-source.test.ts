import { readFileSync } from 'node:fs';
import { NodeIO } from '@gltf-transform/core';
import { beforeAll, describe, expect, it } from 'vitest';
import { writeGlb } from '../scripts/model/glb';
import { buildHeadLevels, type BuiltHead, cutHead, neckCutStart, sourceMesh } from '../src/core/head/build/head-build';
import type { TriGeometry } from '../src/core/head/build/head-spec';
import { buildIdentityHead, identitySkinPositions } from '../src/core/head/build/identity-head';
import { ETHNIC_TARGETS, type IdentitySource, readIdentitySource, writeIdentitySource } from '../src/core/head/build/identity-source';
import { parseObj } from '../src/core/head/build/obj';
import { applyMacroTargets, type MacroTarget, macroTargetWeights, STOCK_IDENTITIES } from '../src/core/head/identity';
import { mulberry32 } from '../src/core/random';
import { syntheticHm08Obj } from './fixtures/synthetic-hm08';

const BYTES = new Uint8Array(readFileSync('public/models/identity-source.bin'));

/** The skin's geometry of a built head. */
const skinOf = (head: BuiltHead): TriGeometry => head.root.children![0].parts![0].geometry;

/** Largest distance (metres) between matching points of two xyz lists, after taking out the mean of each. */
function shapeChange(a: ArrayLike<number>, b: ArrayLike<number>): number {
  const n = a.length / 3;
  const mean = (p: ArrayLike<number>, k: number): number => {
    let s = 0;
    for (let i = k; i < p.length; i += 3) s += p[i];
    return s / n;
  };
  const shift = [0, 1, 2].map((k) => mean(b, k) - mean(a, k));
  let max = 0;
  for (let i = 0; i < a.length; i += 3)
    max = Math.max(max, Math.hypot(b[i] - a[i] - shift[0], b[i + 1] - a[i + 1] - shift[1], b[i + 2] - a[i + 2] - shift[2]));
  return max;
}

describe('public/models/identity-source.bin', () => {
  let source: IdentitySource;
  beforeAll(() => {
    source = readIdentitySource(BYTES);
  });

  it('holds the 24 ethnic targets, the cut head and the groups the builder reads, below 1.2 MB', () => {
    expect(BYTES.length).toBeLessThan(1.2e6);
    expect([...source.targets.keys()].sort()).toEqual([...ETHNIC_TARGETS].sort());
    expect(source.skinRenderVertex.length).toBe(4475);
    expect(source.neckLoop.length).toBeGreaterThan(20);
  });

  it.each(['low', 'medium'] as const)('builds the default head %s exactly as the committed GLB', async (level) => {
    const committed = new Uint8Array(readFileSync(`public/models/head-${level}.glb`));
    const head = buildIdentityHead(source, null, level);
    expect(Buffer.from(await writeGlb(head.root, head.sceneExtras)).equals(committed)).toBe(true);

    // The same, read as a user of the file would: the skin's arrays, the eyes' pivots and radius.
    const doc = await new NodeIO().readBinary(committed);
    const prim = doc
      .getRoot()
      .listMeshes()
      .find((m) => m.getName() === 'skin')!
      .listPrimitives()[0];
    const skin = skinOf(head);
    expect(skin.positions).toEqual(prim.getAttribute('POSITION')!.getArray());
    expect(skin.uvs).toEqual(prim.getAttribute('TEXCOORD_0')!.getArray());
    expect(Array.from(skin.indices)).toEqual(Array.from(prim.getIndices()!.getArray()!));
    const extras = doc.getRoot().getDefaultScene()!.getExtras() as { softface: { eyeRadius: number; pivots: Record<string, number[]> } };
    const built = head.sceneExtras.softface as typeof extras.softface;
    expect(built.eyeRadius).toBe(extras.softface.eyeRadius);
    expect(built.pivots['eye-l']).toEqual(extras.softface.pivots['eye-l']);
    expect(built.pivots['eye-r']).toEqual(extras.softface.pivots['eye-r']);
    expect(built.pivots).toEqual(extras.softface.pivots);
  });

  it("gives the low skin's positions cheaply, in head-low.glb's order", () => {
    const low = skinOf(buildIdentityHead(source, null, 'low')).positions;
    const fast = identitySkinPositions(source, null);
    expect(fast.length).toBe(low.length);
    expect(fast.every((x, i) => Math.fround(x) === low[i])).toBe(true);
    const person = STOCK_IDENTITIES['old-african-woman'];
    const moved = skinOf(buildIdentityHead(source, person, 'low')).positions;
    expect(identitySkinPositions(source, person).every((x, i) => Math.fround(x) === moved[i])).toBe(true);
  });

  it("moves the skin for a stock identity, keeping the default head's topology", () => {
    const base = skinOf(buildIdentityHead(source, null, 'medium'));
    const head = buildIdentityHead(source, STOCK_IDENTITIES['old-african-woman'], 'medium');
    const skin = skinOf(head);
    expect(skin.positions.length).toBe(base.positions.length);
    // Same quads (each split along its shorter diagonal, which may differ): the two triangles of each use the same corners.
    expect(skin.indices.length).toBe(base.indices.length);
    const quad = (indices: Uint32Array, q: number): number[] => [...new Set(indices.subarray(6 * q, 6 * q + 6))].sort((a, b) => a - b);
    let flipped = 0;
    for (let q = 0; q < skin.indices.length / 6; q++) {
      expect(quad(skin.indices, q)).toEqual(quad(base.indices, q));
      if (skin.indices[6 * q + 2] !== base.indices[6 * q + 2]) flipped++;
    }
    expect(flipped).toBeLessThan(skin.indices.length / 6);
    expect(skin.uvs).toEqual(base.uvs);
    expect(skin.positions.every(Number.isFinite)).toBe(true);
    expect(skin.normals.every(Number.isFinite)).toBe(true);
    // The targets move the whole body, so the head is moved as well as reshaped: by 36 mm at most here, and by
    // 23 mm once the mean shift is taken out.
    let moved = 0;
    for (let i = 0; i < skin.positions.length; i += 3) {
      const d = [0, 1, 2].map((k) => skin.positions[i + k] - base.positions[i + k]);
      moved = Math.max(moved, Math.hypot(d[0], d[1], d[2]));
    }
    expect(moved).toBeLessThan(0.05);
    expect(shapeChange(base.positions, skin.positions)).toBeGreaterThan(0.005);
    expect(shapeChange(base.positions, skin.positions)).toBeLessThan(0.04);
    const extras = head.sceneExtras.softface as { eyeRadius: number; pivots: Record<string, number[]> };
    expect(Object.values(extras.pivots).flat().every(Number.isFinite)).toBe(true);
    expect(extras.eyeRadius).toBeGreaterThan(0.01);
    expect(extras.eyeRadius).toBeLessThan(0.02);
  });

  it('refuses bytes that are not an identity source, naming the file', () => {
    expect(() => readIdentitySource(BYTES.subarray(0, BYTES.length >> 1))).toThrow(/^identity-source\.bin: .*truncated/);
    expect(() => readIdentitySource(BYTES.subarray(0, 8))).toThrow(/^identity-source\.bin: truncated/);
    const wrongMagic = BYTES.slice();
    wrongMagic.set([0x67, 0x6c, 0x54, 0x46], 0);
    expect(() => readIdentitySource(wrongMagic)).toThrow(/^identity-source\.bin: not an identity source/);
    const wrongVersion = BYTES.slice();
    wrongVersion[4] = 9;
    expect(() => readIdentitySource(wrongVersion)).toThrow(/^identity-source\.bin: format version 9/);
    const damaged = BYTES.slice();
    damaged.fill(0xff, 100, 200);
    expect(() => readIdentitySource(damaged)).toThrow(/^identity-source\.bin: /);
  });
});

describe('identity source (written from a synthetic hm08-like mesh)', () => {
  /** The synthetic mesh with base.obj's 4 decimals. */
  const baseObj = () => {
    const obj = parseObj(syntheticHm08Obj(16, 14));
    obj.positions.forEach((x, i) => {
      obj.positions[i] = Math.round(x * 1e4) / 1e4;
    });
    return obj;
  };
  /** Seeded targets with 3 decimals that move every vertex but the last few a little, as float32 as the parser reads. */
  const targets = (vertices: number): Map<string, MacroTarget> => {
    const random = mulberry32(42);
    return new Map(
      ETHNIC_TARGETS.map((name) => {
        const indices = Uint32Array.from({ length: vertices - 3 }, (_, i) => i);
        const offsets = Float32Array.from({ length: 3 * indices.length }, () => Math.round(random() * 80 - 40) / 1000);
        return [name, { indices, offsets }];
      }),
    );
  };

  it('builds what buildHeadLevels builds from the base mesh moved by the targets (and back by the mean), cut as the base', async () => {
    const obj = baseObj();
    const given = targets(obj.positions.length / 3);
    const bytes = writeIdentitySource(obj, given);
    expect(writeIdentitySource(baseObj(), given)).toEqual(bytes);
    const source = readIdentitySource(bytes);
    const identity = { sex: 0.3, age: 60, ancestry: { african: 0.2, asian: 0.5, european: 0.3 } };

    const cutStart = neckCutStart(sourceMesh(obj));
    const moved = baseObj();
    applyMacroTargets(
      moved.positions,
      macroTargetWeights(identity).map(({ target, weight }) => ({ target: given.get(target)!, weight })),
    );
    // The identity's head is moved back as a whole by its mean offset, to stand where the base head does.
    const headVertices = cutHead(sourceMesh(obj), cutStart).sourceVertex;
    const shift = [0, 1, 2].map(
      (k) => headVertices.reduce((sum, v) => sum + moved.positions[3 * v + k] - obj.positions[3 * v + k], 0) / headVertices.length,
    );
    expect(Math.hypot(...shift)).toBeGreaterThan(0);
    for (let i = 0; i < moved.positions.length; i++) moved.positions[i] -= shift[i % 3];
    const expected = buildHeadLevels(moved, cutStart);
    const base = buildHeadLevels(obj);
    for (const [i, level] of (['low', 'medium', 'high'] as const).entries()) {
      // The shift is summed in another order here: the same numbers to float32 rounding, not the same bytes.
      const head = buildIdentityHead(source, identity, level);
      const got = partsOf(head.root);
      const want = partsOf(expected[i].root);
      expect(got.map((g) => g.positions.length)).toEqual(want.map((g) => g.positions.length));
      got.forEach((g, k) => expect(largestDifference(g.positions, want[k].positions)).toBeLessThan(1e-6));
      const plain = buildIdentityHead(source, null, level);
      const [c, d] = await Promise.all([writeGlb(plain.root, plain.sceneExtras), writeGlb(base[i].root, base[i].sceneExtras)]);
      expect(Buffer.from(c).equals(Buffer.from(d))).toBe(true);
    }
  });

  it('refuses to write numbers it could not give back exactly, and a missing target', () => {
    const obj = baseObj();
    const given = targets(obj.positions.length / 3);
    const last = obj.positions.length / 3 - 1; // the tongue's
    obj.positions[3 * last] += 1e-5;
    expect(() => writeIdentitySource(obj, given)).toThrow(
      new RegExp(`^identity-source\\.bin: vertex ${last}: .* is not a whole number of 1/10000`),
    );
    given.delete('asian-male-old');
    expect(() => writeIdentitySource(baseObj(), given)).toThrow(/^identity-source\.bin: the target "asian-male-old" was not given/);
  });
});

/** Every part's geometry of a node tree, in order. */
function partsOf(node: BuiltHead['root']): TriGeometry[] {
  return [...(node.parts ?? []).map((p) => p.geometry), ...(node.children ?? []).flatMap(partsOf)];
}

function largestDifference(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let worst = 0;
  for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
  return worst;
}
