import { describe, expect, it } from 'vitest';
import { colliderDistance, slabSide } from '../src/core/solver/colliders';
import { CollisionCandidates } from '../src/core/solver/collision-candidates';
import { loadHeadSimulation } from './fixtures/head-simulation';

// The candidates are found by measuring only the skin in each collider's widened box; this checks that they are the
// ones measuring every vertex against every collider gives: each vertex within 6 mm of its nearest collider at rest,
// outside it, with its clearance (capped at 1 mm) and its side of a slab.
describe('collision candidates', () => {
  it('are the vertices every vertex measured against every collider picks, on the default head', async () => {
    const sim = await loadHeadSimulation('medium');
    const topology = sim.host.topology;
    const colliders = sim.colliders;
    const found = new CollisionCandidates(topology, colliders, 'local');
    const X = topology.rest;
    const dir = [0, 0, 0];
    const expected: { collider: number; vertex: number; clearance: number; side: number }[] = [];
    const nearest: number[] = [];
    const distance: number[] = [];
    for (let v = 0; v < topology.vertexCount; v++) {
      let best = -1;
      let bestD = Infinity;
      colliders.forEach((c, ci) => {
        // Kept in single precision, as the candidates' distances are: where two slabs of the teeth meet, a vertex
        // lies as near to both, and the nearer of the two is decided as they decide it.
        const d = colliderDistance(c, X[3 * v], X[3 * v + 1], X[3 * v + 2], dir);
        if (d < bestD) {
          bestD = Math.fround(d);
          best = ci;
        }
      });
      nearest.push(best);
      distance.push(bestD);
    }
    for (let ci = 0; ci < colliders.length; ci++)
      for (let v = 0; v < topology.vertexCount; v++)
        if (nearest[v] === ci && distance[v] >= 0 && distance[v] < 0.006)
          expected.push({
            collider: ci,
            vertex: v,
            clearance: Math.fround(Math.min(distance[v], 0.001)),
            side: slabSide(colliders[ci], X[3 * v], X[3 * v + 1], X[3 * v + 2]),
          });
    const listed = [];
    for (let ci = 0; ci < colliders.length; ci++)
      for (let j = found.colliderStart[ci]; j < found.colliderStart[ci + 1]; j++)
        listed.push({
          collider: ci,
          vertex: found.colliderVertices[j],
          clearance: found.colliderClearance[j],
          side: found.colliderSide[j],
        });
    // The eyes and the teeth hold hundreds of candidates each; a box too small would lose some of them.
    expect(expected.length).toBeGreaterThan(1000);
    expect(listed).toEqual(expected);
  });
});
