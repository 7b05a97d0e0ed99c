import { describe, expect, it } from 'vitest';
import { boundaryLoops } from '../src/core/head/build/cut';
import { writeGlb } from '../scripts/model/glb';
import { buildHeadLevels, cutHead, neckCutStart, sourceMesh } from '../src/core/head/build/head-build';
import { parseObj } from '../src/core/head/build/obj';
import { vertexCount } from '../src/core/head/polymesh';
import { syntheticHm08Obj } from './fixtures/synthetic-hm08';

describe('head model builder (on a synthetic hm08-like mesh)', () => {
  const obj = parseObj(syntheticHm08Obj(16, 14));

  it('cuts along the neck ring through the front-midline vertex nearest the cut point', () => {
    const cut = cutHead(sourceMesh(obj));
    // Rings are 3/13 dm apart from y = 5; the one nearest y = 5.78 is ring 3 (y = 5.692...).
    const ringY = 5 + 9 / 13;
    expect(cut.neckLoop).toHaveLength(16);
    for (const v of cut.neckLoop) expect(cut.mesh.positions[3 * v + 1]).toBeCloseTo(ringY, 5);
    for (let v = 0; v < vertexCount(cut.mesh); v++) expect(cut.mesh.positions[3 * v + 1]).toBeGreaterThan(ringY - 1e-6);
    expect(boundaryLoops(cut.mesh)).toHaveLength(1);
  });

  it('cuts a mesh moved as identity targets move it where the base mesh is cut, so the head keeps its vertices', () => {
    const start = neckCutStart(sourceMesh(obj));
    // A person a ring shorter in the neck: every vertex 3/13 dm lower, and the head a little wider.
    const moved = parseObj(syntheticHm08Obj(16, 14));
    for (let i = 0; i < moved.positions.length; i += 3) {
      moved.positions[i] *= 1.1;
      moved.positions[i + 1] -= 3 / 13;
    }
    const base = cutHead(sourceMesh(obj));
    const cut = cutHead(sourceMesh(moved), start);
    expect(vertexCount(cut.mesh)).toBe(vertexCount(base.mesh));
    expect(cut.neckLoop).toEqual(base.neckLoop);
    for (let v = 0; v < vertexCount(cut.mesh); v++)
      expect(cut.mesh.positions[3 * v + 1]).toBeCloseTo(base.mesh.positions[3 * v + 1] - 3 / 13, 9);
    // Without the base's start the cut would run through the ring nearest the cut point in the moved mesh: another ring.
    expect(vertexCount(cutHead(sourceMesh(moved)).mesh)).not.toBe(vertexCount(base.mesh));
  });

  it('writes three resolutions whose counts follow Catmull-Clark: V + E + F, then 4 quads per quad', () => {
    const levels = buildHeadLevels(obj);
    expect(levels.map((l) => l.stats.name)).toEqual(['low', 'medium', 'high']);
    const [low, medium, high] = levels.map((l) => l.stats);
    // Above the cut: rings 3..13 (11 rings of 16) and the top pole; 10 bands of 16 quads and 16 fan triangles.
    expect(low.skinVertices).toBe(11 * 16 + 1);
    const edges = 11 * 16 + 10 * 16 + 16; // ring edges, column edges, fan spokes
    const faces = 10 * 16 + 16;
    expect(medium.skinVertices).toBe(low.skinVertices + edges + faces);
    expect(medium.quads).toBe(10 * 16 * 4 + 16 * 3);
    expect(high.quads).toBe(4 * medium.quads);
    expect(high.triangles).toBe(2 * high.quads);
  });

  it('gives identical GLB bytes when run twice', async () => {
    const a = buildHeadLevels(obj)[1];
    const b = buildHeadLevels(parseObj(syntheticHm08Obj(16, 14)))[1];
    const [ga, gb] = await Promise.all([writeGlb(a.root, a.sceneExtras), writeGlb(b.root, b.sceneExtras)]);
    expect(ga.length).toBeGreaterThan(1000);
    expect(Buffer.from(ga).equals(Buffer.from(gb))).toBe(true);
  });

  it('records the pivots in metres from the joint cube centres', () => {
    const extras = buildHeadLevels(obj)[0].sceneExtras.softface as { pivots: Record<string, number[]> };
    expect(extras.pivots['eye-l'][0]).toBeCloseTo(0.03, 9);
    expect(extras.pivots['eye-l'][1]).toBeCloseTo(0.73, 9);
    expect(extras.pivots['jaw-hinge'][1]).toBeCloseTo(0.69, 9);
    expect(Object.keys(extras.pivots).sort()).toEqual([
      'chin',
      'eye-l',
      'eye-r',
      'head',
      'jaw-hinge',
      'lowerlid-l',
      'lowerlid-r',
      'neck',
      'upperlid-l',
      'upperlid-r',
    ]);
  });

  it('names the missing group when the OBJ is not an hm08 base mesh', () => {
    const broken = parseObj(syntheticHm08Obj().replace('g helper-tongue', 'g something-else'));
    expect(() => buildHeadLevels(broken)).toThrow('the base mesh has no group "helper-tongue"');
  });
});
