import { beforeAll, describe, expect, it } from 'vitest';
import { displacement, faceLandmarks, type FaceLandmarks } from './fixtures/face-landmarks';
import { loadHeadSimulation, MAX_SETTLE_FRAMES, settleExpression, triangleArea } from './fixtures/head-simulation';

/**
 * The share of the neck's side (behind and below the jaw's angle, both sides: the default head's rest skin 3 to 9 cm
 * out, 58.5 to 64.5 cm up, 3 to 10 cm forward) whose triangles shrank below 80 % of their rest area: skin squeezed
 * that much buckles into folds.
 */
function neckSqueezed(rest: Float32Array, x: Float32Array, triangles: Uint32Array): number {
  let squeezed = 0;
  let total = 0;
  for (let t = 0; t < triangles.length; t += 3) {
    const a = triangles[t],
      b = triangles[t + 1],
      c = triangles[t + 2];
    const cx = Math.abs(rest[3 * a] + rest[3 * b] + rest[3 * c]) / 3;
    const cy = (rest[3 * a + 1] + rest[3 * b + 1] + rest[3 * c + 1]) / 3;
    const cz = (rest[3 * a + 2] + rest[3 * b + 2] + rest[3 * c + 2]) / 3;
    if (cx < 0.03 || cx > 0.09 || cy < 0.585 || cy > 0.645 || cz < 0.03 || cz > 0.1) continue;
    const at = triangleArea(rest, a, b, c);
    total += at;
    if (triangleArea(x, a, b, c) < 0.8 * at) squeezed += at;
  }
  return squeezed / total;
}

// A jaw does not open about a fixed hinge at the ear: its condyle glides forward as it turns, so the chin drops more
// than it swings back, and the neck behind the jaw's angle is not pushed into folds.
describe('the opening jaw, medium head', () => {
  let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
  let rest: Float32Array;
  let lm: FaceLandmarks;
  const settle = (unit: string): Float32Array => {
    expect(settleExpression(sim, unit, MAX_SETTLE_FRAMES).sleeping, `${unit} comes to rest`).toBe(true);
    return Float32Array.from(sim.host.solver.buffers.positions);
  };
  beforeAll(async () => {
    sim = await loadHeadSimulation('medium');
    rest = sim.host.topology.rest;
    lm = faceLandmarks(rest, sim.triangles);
  });

  it('AU26 drops the chin at least twice as far as it draws it back', () => {
    const chin = displacement(rest, settle('AU26'), lm.chin);
    expect(-chin.up).toBeGreaterThan(15);
    expect(-chin.forward).toBeLessThanOrEqual(-chin.up / 2);
  });

  it('AU27, the jaw open wide, squeezes at most 5 % of the neck behind the jaw below four fifths of its area', () => {
    expect(neckSqueezed(rest, settle('AU27'), sim.triangles)).toBeLessThanOrEqual(0.05);
  });
});
