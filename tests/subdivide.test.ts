import { describe, expect, it } from 'vitest';
import { boundaryLoops } from '../src/core/head/build/cut';
import { buildEdges, faceCount, vertexCount } from '../src/core/head/polymesh';
import { catmullClark } from '../src/core/head/subdivide';
import { cube, grid } from './fixtures/meshes';

describe('Catmull-Clark subdivision', () => {
  it('turns V vertices, E edges and F quads into V + E + F vertices and 4F quads', () => {
    const m = cube();
    const once = catmullClark(m);
    expect(vertexCount(once)).toBe(8 + 12 + 6);
    expect(faceCount(once)).toBe(24);
    const twice = catmullClark(once);
    expect(vertexCount(twice)).toBe(26 + buildEdges(once).vertices.length / 2 + 24);
    expect(faceCount(twice)).toBe(96);
  });

  it('moves a cube corner to the known limit-scheme position (Catmull-Clark: 5/9 of the way in)', () => {
    // For a cube of half-size 1, the first-level vertex point of a valence-3 corner is (Q + 2R + 0*S)/3 with
    // Q = mean face point = 2/3, R = mean edge midpoint = 2/3 in each coordinate: (2/3 + 4/3) / 3 = 5/9.
    const once = catmullClark(cube(2));
    for (let k = 0; k < 3; k++) expect(Math.abs(once.positions[3 * 7 + k])).toBeCloseTo(5 / 9, 12);
  });

  it('keeps a flat grid flat and its boundary on the border (the smooth boundary rule only rounds the corners)', () => {
    const g = catmullClark(catmullClark(grid(4, 3)));
    for (let v = 0; v < vertexCount(g); v++) expect(g.positions[3 * v + 2]).toBe(0);
    const [loop] = boundaryLoops(g);
    expect(boundaryLoops(g)).toHaveLength(1);
    for (const v of loop) {
      const x = g.positions[3 * v];
      const y = g.positions[3 * v + 1];
      const onBorder = Math.abs(x) < 1e-12 || Math.abs(x - 4) < 1e-12 || Math.abs(y) < 1e-12 || Math.abs(y - 3) < 1e-12;
      const nearCorner = [
        [0, 0],
        [4, 0],
        [0, 3],
        [4, 3],
      ].some(([cx, cy]) => Math.hypot(x - cx, y - cy) < 1);
      expect(x).toBeGreaterThanOrEqual(0);
      expect(y).toBeGreaterThanOrEqual(0);
      if (!nearCorner) expect(onBorder).toBe(true);
    }
  });

  it('keeps the winding: every new quad faces the same way as the face it came from', () => {
    const g = catmullClark(grid(2, 2));
    for (let f = 0; f < faceCount(g); f++) {
      const c = g.corners.subarray(g.faceStart[f], g.faceStart[f + 1]);
      const p = (i: number) => [g.positions[3 * c[i]], g.positions[3 * c[i] + 1]];
      const [a, b, d] = [p(0), p(1), p(3)];
      const crossZ = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
      expect(crossZ).toBeGreaterThan(0);
    }
  });

  it('interpolates face-varying uvs linearly and keeps corner uvs', () => {
    const source = grid(1, 1);
    const g = catmullClark(source);
    // The grid's uv is its original xy; the corners keep theirs even though the crease rule moves their positions.
    for (let c = 0; c < g.corners.length; c++) {
      const v = g.corners[c];
      if (v < 4) expect([g.cornerUVs[2 * c], g.cornerUVs[2 * c + 1]]).toEqual([source.positions[3 * v], source.positions[3 * v + 1]]);
    }
    const centre = vertexCount(g) - 1;
    const c = Array.from(g.corners).indexOf(centre);
    expect([g.cornerUVs[2 * c], g.cornerUVs[2 * c + 1]]).toEqual([0.5, 0.5]);
  });

  it('is deterministic', () => {
    const a = catmullClark(catmullClark(cube()));
    const b = catmullClark(catmullClark(cube()));
    expect(Buffer.from(a.positions.buffer).equals(Buffer.from(b.positions.buffer))).toBe(true);
    expect(Array.from(a.corners)).toEqual(Array.from(b.corners));
  });
});
