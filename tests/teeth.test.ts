import { readFileSync } from 'node:fs';
import { NodeIO, type Document, type Node as GltfNode, type Primitive } from '@gltf-transform/core';
import { beforeAll, describe, expect, it } from 'vitest';
import { archSlabs } from '../src/core/solver/colliders';
import { loadHeadSimulation, MAX_SETTLE_FRAMES, settleExpression } from './fixtures/head-simulation';

/** A primitive's positions in head space (the nodes here carry translations only). */
function worldPositions(node: GltfNode, prim: Primitive): Float32Array {
  const m = node.getWorldMatrix();
  const p = prim.getAttribute('POSITION')!.getArray()!;
  const out = new Float32Array(p.length);
  for (let i = 0; i < p.length; i += 3) for (let k = 0; k < 3; k++) out[i + k] = p[i + k] + m[12 + k];
  return out;
}

/** Connected pieces of a triangle list (vertices sharing a triangle are joined). */
function pieces(indices: ArrayLike<number>, vertexCount: number): number {
  const parent = Int32Array.from({ length: vertexCount }, (_, i) => i);
  const find = (v: number): number => {
    if (parent[v] !== v) parent[v] = find(parent[v]);
    return parent[v];
  };
  for (let t = 0; t < indices.length; t += 3) {
    const a = find(indices[t]);
    parent[find(indices[t + 1])] = a;
    parent[find(indices[t + 2])] = a;
  }
  const roots = new Set<number>();
  for (let v = 0; v < vertexCount; v++) roots.add(find(v));
  return roots.size;
}

/** How many triangles of a mesh a ray from `o` along `d` crosses (Moller-Trumbore). */
function crossings(P: ArrayLike<number>, I: ArrayLike<number>, o: number[], d: number[]): number {
  let count = 0;
  for (let t = 0; t < I.length; t += 3) {
    const a = 3 * I[t];
    const b = 3 * I[t + 1];
    const c = 3 * I[t + 2];
    const e1 = [P[b] - P[a], P[b + 1] - P[a + 1], P[b + 2] - P[a + 2]];
    const e2 = [P[c] - P[a], P[c + 1] - P[a + 1], P[c + 2] - P[a + 2]];
    const p = [d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]];
    const det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (Math.abs(det) < 1e-14) continue;
    const s = [o[0] - P[a], o[1] - P[a + 1], o[2] - P[a + 2]];
    const u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    if (u < 0 || u > 1) continue;
    const q = [s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]];
    const v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    if (v < 0 || u + v > 1) continue;
    if ((e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det > 0) count++;
  }
  return count;
}

// The low head: the teeth are the same at every resolution, and its skin makes the ray casts cheap.
describe('the dental arches of the default head', () => {
  let doc: Document;
  const node = (name: string): GltfNode =>
    doc
      .getRoot()
      .listNodes()
      .find((n) => n.getName() === name)!;
  const part = (name: string, material: string) => {
    const prim = node(name)
      .getMesh()!
      .listPrimitives()
      .find((p) => p.getMaterial()!.getName() === material)!;
    return { prim, positions: worldPositions(node(name), prim), indices: prim.getIndices()!.getArray()! };
  };
  beforeAll(async () => {
    doc = await new NodeIO().readBinary(new Uint8Array(readFileSync('public/models/head-low.glb')));
  });

  it.each(['teeth-upper', 'teeth-lower'])('%s holds 16 separate crowns and a gum band, a few thousand triangles in all', (name) => {
    expect(
      node(name)
        .getMesh()!
        .listPrimitives()
        .map((p) => p.getMaterial()!.getName()),
    ).toEqual(['teeth', 'gums']);
    const teeth = part(name, 'teeth');
    const gums = part(name, 'gums');
    expect(pieces(teeth.indices, teeth.positions.length / 3)).toBe(16);
    expect(pieces(gums.indices, gums.positions.length / 3)).toBe(1);
    const triangles = (teeth.indices.length + gums.indices.length) / 3;
    expect(triangles).toBeGreaterThan(2000);
    expect(triangles).toBeLessThan(8000);
    // Symmetric about the midline, about 5 cm across, as an adult arch.
    let minX = Infinity;
    let maxX = -Infinity;
    for (let i = 0; i < teeth.positions.length; i += 3) {
      minX = Math.min(minX, teeth.positions[i]);
      maxX = Math.max(maxX, teeth.positions[i]);
    }
    expect(maxX + minX).toBeCloseTo(0, 4);
    expect(maxX - minX).toBeGreaterThan(0.045);
    expect(maxX - minX).toBeLessThan(0.065);
  });

  it.each(['teeth-upper', 'teeth-lower'])('%s is shaded darker at the back of the mouth than at the front (baked occlusion)', (name) => {
    const { prim, positions } = part(name, 'teeth');
    const shade = prim.getAttribute('COLOR_0')!.getArray()!;
    let minZ = Infinity;
    for (let i = 2; i < positions.length; i += 3) minZ = Math.min(minZ, positions[i]);
    const mean = (pick: (i: number) => boolean): number => {
      let sum = 0;
      let n = 0;
      for (let i = 0; i < positions.length; i += 3) {
        if (!pick(i)) continue;
        sum += shade[i];
        n++;
      }
      return sum / n;
    };
    const front = mean((i) => Math.abs(positions[i]) < 0.005);
    const back = mean((i) => positions[i + 2] < minZ + 0.01);
    expect(front).toBeGreaterThan(0.8);
    expect(front).toBeLessThanOrEqual(1);
    expect(back).toBeLessThan(0.75 * front);
  });

  it('bites with the upper incisors over and in front of the lower ones (a few millimetres of overbite and overjet)', () => {
    const front = (p: Float32Array, pick: (y: number, z: number) => number, start: number) => {
      let best = start;
      for (let i = 0; i < p.length; i += 3) if (Math.abs(p[i]) < 0.004) best = pick(best, i);
      return best;
    };
    const upper = part('teeth-upper', 'teeth').positions;
    const lower = part('teeth-lower', 'teeth').positions;
    const upperEdge = front(upper, (b, i) => Math.min(b, upper[i + 1]), Infinity);
    const lowerEdge = front(lower, (b, i) => Math.max(b, lower[i + 1]), -Infinity);
    const upperFace = front(upper, (b, i) => Math.max(b, upper[i + 2]), -Infinity);
    const lowerFace = front(lower, (b, i) => Math.max(b, lower[i + 2]), -Infinity);
    const overbite = lowerEdge - upperEdge;
    const overjet = upperFace - lowerFace;
    expect(overbite).toBeGreaterThan(0.001);
    expect(overbite).toBeLessThan(0.005);
    expect(overjet).toBeGreaterThan(0.002);
    expect(overjet).toBeLessThan(0.008);
  });

  /**
   * Teeth and gum vertices no skin covers: a ray outward from the back of the mouth, tilted up for the upper row and
   * down for the lower one, must pass through the upper lip or the lower (a ray level with the lips' parting line
   * may leave between them, as a sight line does). Every `stride`-th vertex is checked.
   */
  const exposed = (skin: ArrayLike<number>, skinIndices: ArrayLike<number>, stride: number): string[] => {
    const out: string[] = [];
    for (const [name, tilt] of [
      ['teeth-upper', 0.3],
      ['teeth-lower', -0.3],
    ] as const) {
      for (const material of ['teeth', 'gums']) {
        const p = part(name, material).positions;
        for (let i = 0; i < p.length; i += 3 * stride) {
          const dx = p[i];
          const dz = p[i + 2] - 0.1;
          const length = Math.hypot(dx, dz);
          if (crossings(skin, skinIndices, [p[i], p[i + 1], p[i + 2]], [dx / length, tilt, dz / length]) === 0)
            out.push(`${name} ${material} vertex ${i / 3}`);
        }
      }
    }
    return out;
  };

  it('keeps every crown and gum behind the lips and cheeks at rest: a ray outward through its own lip meets the skin', () => {
    const skinPrim = doc
      .getRoot()
      .listMeshes()
      .find((m) => m.getName() === 'skin')!
      .listPrimitives()[0];
    expect(exposed(skinPrim.getAttribute('POSITION')!.getArray()!, skinPrim.getIndices()!.getArray()!, 2)).toEqual([]);
  });

  it.each(['happiness', 'AU12'])('keeps them covered in a closed-lips smile (%s): the lips slide over the teeth', async (item) => {
    const sim = await loadHeadSimulation('low');
    expect(settleExpression(sim, item, MAX_SETTLE_FRAMES)).toMatchObject({ sleeping: true, inverted: 0 });
    expect(exposed(sim.host.solver.buffers.positions, sim.triangles, 3)).toEqual([]);
  });

  it('gives the skin colliders that wrap the rows closely (thin walls along each arch)', () => {
    for (const name of ['teeth-upper', 'teeth-lower']) {
      const all = [...part(name, 'teeth').positions, ...part(name, 'gums').positions];
      const slabs = archSlabs(name, all);
      expect(slabs.length).toBe(8);
      for (const s of slabs) {
        // As thick as the molars and gums at most, and as tall as a crown with its gum.
        expect(s.radius).toBeGreaterThan(0.002);
        expect(s.radius).toBeLessThan(0.009);
        expect(s.up![1]).toBeGreaterThan(0.012);
        expect(s.up![1]).toBeLessThan(0.026);
      }
    }
  });
});
