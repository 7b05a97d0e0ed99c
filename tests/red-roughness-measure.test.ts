import { beforeAll, describe, expect, it } from 'vitest';
import { landmarkLookup } from './fixtures/face-landmarks';
import { redRoughness } from './fixtures/facs-cues';
import { loadHeadSimulation } from './fixtures/head-simulation';

// The lips' red smoothness measure (tests/fixtures/facs-cues.ts) on made-up displacements of the medium head: a
// smooth pull reads as smooth, however steep, and a ripple along the red reads as folded. (Its earlier form, a Gaussian
// mean of the nearby vertices less a straight trend, read 0.15 mm on the smooth bowl: more than most expressions.)
describe("the lips' red smoothness measure", () => {
  let rest: Float32Array;
  let normals: Float32Array;
  let triangles: Uint32Array;
  let mouth: [number, number];
  /** The rest shape moved along its normals by `d(x, y)` metres. */
  const moved = (d: (x: number, y: number) => number): Float32Array => {
    const x = Float32Array.from(rest);
    for (let v = 0; v < rest.length / 3; v++) {
      const s = d(rest[3 * v], rest[3 * v + 1]);
      for (let k = 0; k < 3; k++) x[3 * v + k] += s * normals[3 * v + k];
    }
    return x;
  };
  /** A bowl along the mouth, 5 mm deep in the middle and nothing at the corners, steeper across it by `across`. */
  const bowl = (across: number) => (x: number, y: number) =>
    -0.005 * Math.max(0, 1 - (x / mouth[0]) ** 2) * (1 + (across * (y - mouth[1])) / 0.01);
  beforeAll(async () => {
    const sim = await loadHeadSimulation('medium');
    ({ rest, restNormals: normals } = sim.host.topology);
    triangles = sim.triangles;
    const [x, y] = landmarkLookup(rest, triangles, 'test')('mouth-l');
    mouth = [x, y];
  });

  it.each([0, 1, 2])('reads a smooth bowl as smooth (steeper across the lips by %d per cm)', (across) => {
    expect(redRoughness(rest, normals, triangles, moved(bowl(across))).rms).toBeLessThan(0.02);
  });

  it.each([4, 5, 6])('reads a 0.2 mm ripple %d mm long on the bowl as folded', (wavelength) => {
    const ripple = (x: number, y: number) => bowl(0)(x, y) + 0.0002 * Math.sin((2 * Math.PI * x) / (wavelength / 1000));
    // The ripple's root mean square is 0.14 mm; what the trend takes of it leaves 0.09 to 0.11.
    expect(redRoughness(rest, normals, triangles, moved(ripple)).rms).toBeGreaterThan(0.06);
  });
});
