import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { eulerMatrix } from '../src/core/math3';
import { applyHeadTransform, checkHeadMesh, findHeadTransform, mergeVertices, weldSeams, type Axis } from '../src/core/head/head-mesh';
import { DEFAULT_LANDMARKS, findLandmarks, LANDMARK_NAMES } from '../src/core/head/landmarks';
import { mulberry32 } from '../src/core/random';
import { eulerDegrees, warpRig } from '../src/core/rig/rig-warp';
import { parseRigText } from '../src/core/rig/rig-schema';
import type { Vec3 } from '../src/core/rig/rig-types';
import { fitThinPlate, warpJacobian, warpPoint } from '../src/core/head/thin-plate';
import { loadHeadSkin } from './fixtures/head';

const rig = parseRigText(readFileSync(new URL('../public/rigs/default.json', import.meta.url), 'utf8'), 'default.json');
const sources = LANDMARK_NAMES.map((n) => [...DEFAULT_LANDMARKS[n]] as Vec3);

describe('thin-plate warp', () => {
  const random = mulberry32(12);
  const targets = sources.map((p) => p.map((x) => 1.1 * x + 0.01 * (random() - 0.5)) as Vec3);
  const warp = fitThinPlate(sources, targets);

  it('takes every landmark exactly onto its target', () => {
    sources.forEach((p, i) => {
      const q = warpPoint(warp, p);
      for (let k = 0; k < 3; k++) expect(q[k]).toBeCloseTo(targets[i][k], 9);
    });
  });

  it('is an affine map where the landmarks differ by one, far from them too', () => {
    const affine = (p: readonly number[]): Vec3 => [1.2 * p[0] + 0.1 * p[1] + 0.02, 0.9 * p[1] - 0.05, 1.05 * p[2] + 0.1 * p[0]];
    const w = fitThinPlate(sources, sources.map(affine));
    for (const p of [
      [0.3, -0.2, 0.5],
      [0, 0.7, 0.1],
      [-1, 2, 3],
    ]) {
      const q = warpPoint(w, p);
      const e = affine(p);
      for (let k = 0; k < 3; k++) expect(q[k]).toBeCloseTo(e[k], 9);
    }
    expect(w.scale).toBeCloseTo(Math.cbrt(1.2 * 0.9 * 1.05), 9);
  });

  it('is smooth: its derivative matches finite differences away from the landmarks', () => {
    for (let t = 0; t < 20; t++) {
      const p = [0.1 * (random() - 0.5), 0.6 + 0.3 * random(), 0.2 * (random() - 0.5)];
      const J = warpJacobian(warp, p);
      const h = 1e-6;
      for (let col = 0; col < 3; col++) {
        const a = [...p];
        const b = [...p];
        a[col] -= h;
        b[col] += h;
        const qa = warpPoint(warp, a);
        const qb = warpPoint(warp, b);
        for (let row = 0; row < 3; row++) expect(J[row * 3 + col]).toBeCloseTo((qb[row] - qa[row]) / (2 * h), 5);
      }
    }
  });

  it('refuses too few or coplanar points, naming the problem', () => {
    expect(() => fitThinPlate(sources.slice(0, 3), targets.slice(0, 3))).toThrow('needs at least 4 point pairs, got 3');
    const flat: Vec3[] = [
      [0, 0, 0],
      [1, 0, 0],
      [0, 1, 0],
      [1, 1, 0],
      [2, 1, 0],
    ];
    expect(() => fitThinPlate(flat, flat)).toThrow('degenerate');
    expect(() =>
      fitThinPlate(
        sources,
        targets.map((p, i) => (i === 3 ? [Number.NaN, 0, 0] : p)),
      ),
    ).toThrow('target point 3 is not finite');
  });
});

describe('carrying the rig over', () => {
  it('leaves the rig as it is under the identity warp', () => {
    const warped = warpRig(rig, fitThinPlate(sources, sources));
    const flat = (x: unknown): number[] =>
      typeof x === 'number' ? [x] : Array.isArray(x) || (typeof x === 'object' && x) ? Object.values(x as object).flatMap(flat) : [];
    const a = flat(rig.muscles);
    const b = flat(
      warped.muscles.map((m) =>
        m.type === 'jaw' && !rig.muscles.find((r) => r.name === m.name && r.type === 'jaw' && r.joint) ? { ...m, joint: undefined } : m,
      ),
    );
    expect(b.length).toBe(a.length);
    a.forEach((x, i) => expect(Math.abs(x - b[i])).toBeLessThan(2e-4));
  });

  it('scales points, radii and fades with a uniform scaling and keeps frames, and the result passes the schema', () => {
    const about: Vec3 = [0, 0.7, 0.1];
    const scaled = (p: readonly number[]): Vec3 => p.map((x, k) => about[k] + 1.25 * (x - about[k])) as Vec3;
    const warped = warpRig(rig, fitThinPlate(sources, sources.map(scaled)));
    expect(() => parseRigText(JSON.stringify(warped), 'warped')).not.toThrow();
    rig.muscles.forEach((m, i) => {
      const w = warped.muscles[i];
      if (m.type === 'linear' && w.type === 'linear') {
        scaled(m.insertion).forEach((x, k) => expect(w.insertion[k]).toBeCloseTo(x, 5));
        expect(w.angle).toBe(m.angle);
      } else if (m.type === 'sphincter' && w.type === 'sphincter') {
        m.radii.forEach((r, k) => expect(w.radii[k]).toBeCloseTo(1.25 * r, 5));
        m.rotation.forEach((a, k) => expect(w.rotation[k]).toBeCloseTo(a, 2));
      } else if (m.type === 'jaw' && w.type === 'jaw') {
        expect(w.fade).toBeCloseTo(1.25 * m.fade, 5);
        m.size.forEach((r, k) => expect(w.size[k]).toBeCloseTo(1.25 * r, 5));
      }
    });
  });

  it('reads Euler angles back from their matrix', () => {
    const random = mulberry32(3);
    for (let t = 0; t < 50; t++) {
      const angles: Vec3 = [360 * random() - 180, 170 * random() - 85, 360 * random() - 180];
      const M = new Array<number>(9);
      eulerMatrix(angles, M);
      eulerDegrees(M).forEach((a, k) => expect(a).toBeCloseTo(angles[k], 3));
    }
  });
});

describe('landmarks', () => {
  it.each(['low', 'medium'] as const)('are found on the default %s head within 4 mm of the default landmarks', async (resolution) => {
    const { positions, indices } = await loadHeadSkin(resolution);
    const { found, missing } = findLandmarks(positions, indices);
    expect(missing).toEqual([]);
    for (const name of LANDMARK_NAMES) {
      const d = Math.hypot(...([0, 1, 2].map((k) => found[name]![k] - DEFAULT_LANDMARKS[name][k]) as Vec3));
      expect(d, name).toBeLessThan(0.004);
    }
  });

  it('put the mouth corners and the nose tip where the head has them', async () => {
    const { positions, indices } = await loadHeadSkin('low');
    const { found } = findLandmarks(positions, indices);
    // The lip corners the Action Unit tests measure (the zygomaticus major's insertions), within 5 mm.
    expect(Math.hypot(found['mouth-l']![0] - 0.0255, found['mouth-l']![1] - 0.6608, found['mouth-l']![2] - 0.1419)).toBeLessThan(0.005);
    let front = -Infinity;
    for (let i = 2; i < positions.length; i += 3) front = Math.max(front, positions[i]);
    expect(found['nose-tip']![2]).toBeCloseTo(front, 3);
  });

  it('are not found on a sphere: no eyes, no mouth', () => {
    const { positions, indices } = sphere(0.1, 48);
    const { missing } = findLandmarks(positions, indices);
    expect(missing.map((m) => m.name)).toEqual(expect.arrayContaining(['eye-inner-l', 'mouth-l', 'chin']));
    expect(missing.find((m) => m.name === 'eye-inner-l')!.reason).toBe('no pair of eye openings was found above the nose');
  });
});

describe('head mesh checks and frame', () => {
  it('refuses non-finite coordinates, bad indices, empty and oversized meshes, naming what is wrong', () => {
    const { positions, indices } = sphere(0.1, 8);
    const bad = positions.slice();
    bad[3 * 5 + 1] = Number.NaN;
    expect(() => checkHeadMesh({ positions: bad, indices }, 'nan.obj')).toThrow('nan.obj: vertex 5 has a non-finite y coordinate (NaN)');
    const far = indices.slice();
    far[7] = 99999;
    expect(() => checkHeadMesh({ positions, indices: far }, 'x.glb')).toThrow('x.glb: triangle 2 uses vertex 99999, but the mesh has');
    expect(() => checkHeadMesh({ positions, indices: new Uint32Array(0) }, 'e.obj')).toThrow('e.obj: the mesh has no triangles');
    expect(() => checkHeadMesh({ positions, indices: new Uint32Array(3 * 200_001) }, 'big.glb')).toThrow(
      'big.glb: the mesh has 200,001 triangles, more than the 200,000',
    );
    expect(() => checkHeadMesh({ positions, indices }, 'ok')).not.toThrow();
  });

  it('welds seam copies a float apart onto one position and leaves distinct vertices alone', () => {
    const p = Float32Array.from([0, 0, 0, 1, 0, 0, 1 + 1e-7, 0, 0, 0, 1, 0, 0.5, 0.5, 0]);
    expect(weldSeams(p, 1e-5)).toBe(1);
    expect(Array.from(p.slice(6, 9))).toEqual([1, 0, 0]);
    expect(p[12]).toBe(0.5);
  });

  it('merges the corners an OBJ reader splits into indexed vertices, keeping UV seam copies apart', () => {
    // Two triangles sharing an edge, every corner its own vertex; the shared edge has the same uvs on one end only.
    const positions = Float32Array.from([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]);
    const uvs = Float32Array.from([0, 0, 1, 0, 0, 1, 1, 0, 1, 1, 0.5, 1]);
    const merged = mergeVertices({ positions, indices: Uint32Array.from([0, 1, 2, 3, 4, 5]), uvs });
    expect(merged.positions.length / 3).toBe(5);
    expect(Array.from(merged.indices)).toEqual([0, 1, 2, 1, 3, 4]);
  });

  it.each([
    ['m', '+y', '+z'],
    ['cm', '+z', '-x'],
    ['mm', '-y', '+x'],
    ['dm', '+x', '-z'],
  ] as const)('finds units %s, up %s and forward %s of the default head turned that way', async (units, up, forward) => {
    const { positions, indices } = await loadHeadSkin('low');
    const scale = { m: 1, dm: 10, cm: 100, mm: 1000 }[units];
    const axis = (a: Axis): number[] => [0, 1, 2].map((k) => (k === 'xyz'.indexOf(a[1]) ? (a[0] === '-' ? -1 : 1) : 0));
    const u = axis(up);
    const f = axis(forward);
    const l = [u[1] * f[2] - u[2] * f[1], u[2] * f[0] - u[0] * f[2], u[0] * f[1] - u[1] * f[0]];
    const file = new Float32Array(positions.length);
    for (let i = 0; i < positions.length; i += 3) {
      for (let k = 0; k < 3; k++) file[i + k] = scale * (l[k] * positions[i] + u[k] * positions[i + 1] + f[k] * positions[i + 2]);
    }
    const frame = findHeadTransform(file, indices);
    expect(frame).toMatchObject({ units, up, forward });
    applyHeadTransform(file, frame);
    for (let i = 0; i < file.length; i++) expect(Math.abs(file[i] - positions[i])).toBeLessThan(1e-5);
  });

  it('refuses a mesh no unit makes head-sized', () => {
    const { positions, indices } = sphere(40, 8);
    expect(() => findHeadTransform(positions, indices, {}, 'moon.obj')).toThrow(
      'moon.obj: the mesh is 80.0 units across, not the size of a head in m, dm, cm or mm; give its units',
    );
  });
});

/** A UV sphere of `radius` about (0, 0.7, 0): `n` segments, n / 2 rings. */
function sphere(radius: number, n: number): { positions: Float32Array; indices: Uint32Array } {
  const positions: number[] = [];
  const indices: number[] = [];
  const rings = n / 2;
  for (let j = 0; j <= rings; j++) {
    for (let i = 0; i <= n; i++) {
      const t = (Math.PI * j) / rings;
      const p = (2 * Math.PI * i) / n;
      positions.push(radius * Math.sin(t) * Math.sin(p), 0.7 + radius * Math.cos(t), radius * Math.sin(t) * Math.cos(p));
    }
  }
  for (let j = 0; j < rings; j++) {
    for (let i = 0; i < n; i++) {
      const a = j * (n + 1) + i;
      const b = a + n + 1;
      indices.push(a, b, a + 1, a + 1, b, b + 1);
    }
  }
  return { positions: Float32Array.from(positions), indices: Uint32Array.from(indices) };
}
