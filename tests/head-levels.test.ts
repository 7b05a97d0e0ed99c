import { describe, expect, it } from 'vitest';
import { decimateHead, levelPlan, subdivideHead } from '../src/core/head/head-levels';
import { DEFAULT_LANDMARKS, findLandmarks, LANDMARK_NAMES } from '../src/core/head/landmarks';
import { buildTopology } from '../src/core/solver/topology';
import { loadHeadSkin } from './fixtures/head';

describe('resolution levels of a loaded head', () => {
  it('plans the subdivisions or decimation nearest each level, never above 200,000 triangles', () => {
    // A 5,114-triangle head: as it is for low, once subdivided (30,684) for medium, twice (122,736) for high.
    expect(levelPlan(5_114, 'low')).toEqual({ subdivisions: 0 });
    expect(levelPlan(5_114, 'medium')).toEqual({ subdivisions: 1 });
    expect(levelPlan(5_114, 'high')).toEqual({ subdivisions: 2 });
    // 8,524 triangles: twice would be 204,576, over the limit, so high is once subdivided.
    expect(levelPlan(8_524, 'high')).toEqual({ subdivisions: 1 });
    // A dense scan is decimated to the level's count.
    expect(levelPlan(180_000, 'low')).toEqual({ decimateTo: 8_524 });
    expect(levelPlan(180_000, 'high')).toEqual({ subdivisions: 0 });
  });

  it('subdivides a head into one closed surface (seams welded) where the same landmarks are found', async () => {
    const { positions, indices } = await loadHeadSkin('low');
    const fine = subdivideHead({ positions, indices, uvs: new Float32Array((2 * positions.length) / 3) }, 1);
    expect(fine.indices.length / 3).toBe(6 * (indices.length / 3));
    const topology = buildTopology(fine.positions, fine.indices);
    expect(topology.report.nonManifoldTriangles).toBe(0);
    // Catmull-Clark on triangles: each face adds a face point and each edge an edge point.
    const coarse = buildTopology(positions, indices);
    expect(topology.vertexCount).toBe(coarse.vertexCount + coarse.restLength.length + indices.length / 3);
    const { found, missing } = findLandmarks(fine.positions, fine.indices);
    expect(missing).toEqual([]);
    for (const name of LANDMARK_NAMES) {
      const d = Math.hypot(...[0, 1, 2].map((k) => found[name]![k] - DEFAULT_LANDMARKS[name][k]));
      expect(d, name).toBeLessThan(0.004);
    }
  });

  it('decimates a dense head to about the level count, keeping its face', async () => {
    const { positions, indices } = await loadHeadSkin('medium');
    const coarse = await decimateHead({ positions, indices }, 8_524);
    expect(coarse.indices.length / 3).toBeGreaterThan(0.8 * 8_524);
    expect(coarse.indices.length / 3).toBeLessThan(1.05 * 8_524);
    const { missing } = findLandmarks(coarse.positions, coarse.indices);
    expect(missing).toEqual([]);
  });
});
