import { describe, expect, it } from 'vitest';
import { CarriedFrames } from '../src/core/solver/carried-frames';
import { triangleFrames } from '../src/core/solver/orientation-kernel';
import { buildTopology } from '../src/core/solver/topology';
import { triangleGrid } from './fixtures/grids';

// The orientation frames of skin a rotation muscle carries (src/core/solver/carried-frames.ts): a bent sheet turned
// bodily gets its rest normals turned the same way, skin no rotation muscle holds keeps them, and a released turn
// gives them back.
describe('orientation frames carried with a turn', () => {
  // A cylinder section, so that the rest normals differ from triangle to triangle.
  const grid = triangleGrid(0.02, 0.01, 0.001, 0.03);
  const t = buildTopology(grid.positions, grid.indices);
  const n = t.vertexCount;
  const triangleCount = t.triangles.length / 3;
  const rest = triangleFrames(t.rest, t.triangles);
  /** The rest positions turned by `angle` about the x axis through the origin. */
  const turned = (angle: number): Float32Array => {
    const out = new Float32Array(t.rest);
    const [c, s] = [Math.cos(angle), Math.sin(angle)];
    for (let i = 0; i < out.length; i += 3) {
      const [y, z] = [t.rest[i + 1], t.rest[i + 2]];
      out[i + 1] = c * y - s * z;
      out[i + 2] = s * y + c * z;
    }
    return out;
  };
  const ones = new Float32Array(n).fill(1);

  it('turns every frame of skin turned bodily by the same rotation, the bounds unchanged', () => {
    const carried = new CarriedFrames(t.rest, t.restNormals, t.triangles, rest);
    const frames = Float32Array.from(rest);
    // The orientation passes' list holds every triangle, in reverse order.
    const listed = new Float32Array(frames.length);
    const places = Int32Array.from({ length: triangleCount }, (_, k) => triangleCount - 1 - k);
    const angle = (100 * Math.PI) / 180;
    carried.update(turned(angle), ones, ones, ones, frames, listed, places);
    const [c, s] = [Math.cos(angle), Math.sin(angle)];
    let worst = 0;
    for (let k = 0; k < triangleCount; k++) {
      const o = 4 * k;
      const want = [rest[o], c * rest[o + 1] - s * rest[o + 2], s * rest[o + 1] + c * rest[o + 2]];
      worst = Math.max(worst, Math.hypot(frames[o] - want[0], frames[o + 1] - want[1], frames[o + 2] - want[2]));
      expect(frames[o + 3]).toBe(rest[o + 3]);
      expect(Array.from(listed.subarray(4 * places[k], 4 * places[k] + 4))).toEqual(Array.from(frames.subarray(o, o + 4)));
    }
    // Past edge-on against the rest normals, as a closing lid's margin goes, and still each triangle's own normal:
    // within about a degree (0.0175), as a frame takes the shortest turn between its corners' mean normals, which for a
    // triangle tilted against that mean differs from the sheet's turn by a hair (0.43 degrees here).
    expect(worst).toBeLessThan(0.0175);
  });

  it('leaves the frames of skin no rotation muscle holds at rest, and gives the turned ones back when the turn ends', () => {
    const carried = new CarriedFrames(t.rest, t.restNormals, t.triangles, rest);
    const frames = Float32Array.from(rest);
    // The list holds the triangles in their own order.
    const listed = Float32Array.from(rest);
    const places = Int32Array.from({ length: triangleCount }, (_, k) => k);
    // Held by a muscle that does not turn the skin (a linear one's weights, no turn weight): no frame changes.
    const none = new Float32Array(n);
    carried.update(turned(0.5), ones, ones, none, frames, listed, places);
    expect(frames).toEqual(rest);
    expect(listed).toEqual(rest);
    // Turned, then released: every turned frame is back at rest, exactly, in the list too.
    carried.update(turned(0.5), ones, ones, ones, frames, listed, places);
    expect(frames).not.toEqual(rest);
    expect(listed).toEqual(frames);
    carried.update(t.rest, none, none, none, frames, listed, places);
    expect(frames).toEqual(rest);
    expect(listed).toEqual(rest);
  });
});
