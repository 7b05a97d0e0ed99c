import { describe, expect, it } from 'vitest';
import { boundaryLoops, cutAlongLoop, findEdgeLoop } from '../src/core/head/build/cut';
import { faceCount, vertexCount } from '../src/core/head/polymesh';
import { cappedTube, grid } from './fixtures/meshes';

describe('edge loops and the cut', () => {
  const segments = 12;
  const rings = 6;
  const tube = cappedTube(segments, rings);
  const ringVertex = (j: number, i: number): number => j * segments + i;

  it('follows a ring of regular quads all the way round', () => {
    const loop = findEdgeLoop(tube, ringVertex(2, 0), ringVertex(2, 1));
    expect(loop).toEqual(Array.from({ length: segments }, (_, i) => ringVertex(2, i)));
  });

  it('refuses a loop that runs into an irregular vertex', () => {
    // Going up a column reaches the top pole, whose valence is the segment count.
    expect(() => findEdgeLoop(tube, ringVertex(0, 0), ringVertex(1, 0))).toThrow(/valence/);
  });

  it('keeps exactly the whole faces on the seed side, with one clean boundary along the loop', () => {
    const loop = findEdgeLoop(tube, ringVertex(2, 0), ringVertex(2, 1));
    const topFace = faceCount(tube) - 1; // a fan triangle at the top pole
    const cut = cutAlongLoop(tube, loop, topFace);
    // Above ring 2: rings 2..5 (4 rings), the top pole; quads between rings 2..5 (3 bands) and the top fan.
    expect(vertexCount(cut.mesh)).toBe(4 * segments + 1);
    expect(faceCount(cut.mesh)).toBe(3 * segments + segments);
    const loops = boundaryLoops(cut.mesh);
    expect(loops).toHaveLength(1);
    expect(loops[0].map((v) => cut.sourceVertex[v]).sort((a, b) => a - b)).toEqual([...loop].sort((a, b) => a - b));
    for (let v = 0; v < vertexCount(cut.mesh); v++)
      expect(cut.mesh.positions[3 * v + 1]).toBeGreaterThanOrEqual(tube.positions[3 * loop[0] + 1]);
  });

  it('says so when the loop does not separate the mesh', () => {
    const g = grid(3, 3);
    // A single interior edge blocks nothing: the faces stay connected around it.
    expect(() => cutAlongLoop(g, [5, 6], 0)).toThrow(/does not separate/);
  });
});
