import { describe, expect, it } from 'vitest';
import { anchorFrame, poseHair, ribbonTriangles, strandsAtRest, ROOT_VERTICES, type HairStrands } from '../src/core/hair/hair';
import { mulberry32 } from '../src/core/random';

/** A bumpy sheet in the xy plane facing +z: positions, normals (from the height's slope) and triangles. */
function sheet(n: number) {
  const positions = new Float32Array(3 * n * n);
  const normals = new Float32Array(3 * n * n);
  const height = (x: number, y: number): number => 0.002 * Math.sin(40 * x) * Math.cos(30 * y);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const x = (i / (n - 1)) * 0.05,
        y = (j / (n - 1)) * 0.05,
        v = 3 * (j * n + i);
      positions.set([x, y, height(x, y)], v);
      const dx = 0.08 * Math.cos(40 * x) * Math.cos(30 * y),
        dy = -0.06 * Math.sin(40 * x) * Math.sin(30 * y);
      const l = Math.hypot(dx, dy, 1);
      normals.set([-dx / l, -dy / l, 1 / l], v);
    }
  }
  const triangles: number[] = [];
  for (let j = 0; j + 1 < n; j++) {
    for (let i = 0; i + 1 < n; i++) {
      const a = j * n + i;
      triangles.push(a, a + 1, a + n, a + 1, a + n + 1, a + n);
    }
  }
  return { positions, normals, triangles: Uint32Array.from(triangles) };
}

const POINTS = 4;

/** Seeded hairs on the sheet: each anchored in a random triangle, its ribbon standing off the skin at random. */
function hairsOn(s: ReturnType<typeof sheet>, count: number, seed: number): { strands: HairStrands; world: Float32Array } {
  const random = mulberry32(seed);
  const hairs = [];
  const frame = new Float64Array(15);
  for (let k = 0; k < count; k++) {
    const t = Math.floor(random() * (s.triangles.length / 3));
    const w0 = random(),
      w1 = random() * (1 - w0);
    const corners = [s.triangles[3 * t], s.triangles[3 * t + 1], s.triangles[3 * t + 2]] as [number, number, number];
    const weights = [w0, w1, 1 - w0 - w1] as [number, number, number];
    // The anchor's frame at rest, to stand the hair on: root on the skin, the rest off it along a random direction.
    anchorFrame(
      { corners: Uint32Array.from(corners), weights: Float32Array.from(weights) } as HairStrands,
      0,
      s.positions,
      s.normals,
      frame,
    );
    const vertices = new Float32Array(3 * 2 * POINTS);
    const dir = [random() - 0.5, random() - 0.5, 0.3 + random()];
    for (let p = 0; p < POINTS; p++) {
      for (let side = 0; side < 2; side++) {
        const o = 3 * (2 * p + side);
        const across = side === 0 ? -0.00005 : 0.00005;
        for (let c = 0; c < 3; c++) vertices[o + c] = frame[c] + 0.002 * p * dir[c] + (c === 0 ? across : 0) + 0.00003 * frame[9 + c];
      }
    }
    hairs.push({ corners, weights, vertices, shade: new Float32Array(2 * POINTS).fill(1) });
  }
  const strands = strandsAtRest(s, hairs, 2 * POINTS, ribbonTriangles(POINTS));
  const world = new Float32Array(hairs.flatMap((h) => [...h.vertices]));
  return { strands, world };
}

describe('hair posed on a skin', () => {
  const s = sheet(12);
  const { strands, world } = hairsOn(s, 200, 7);
  const out = new Float32Array(world.length);
  const normals = new Float32Array(world.length);

  it('is where it was laid when the skin is at rest', () => {
    poseHair(strands, s.positions, s.normals, out, normals);
    let worst = 0;
    for (let i = 0; i < out.length; i++) worst = Math.max(worst, Math.abs(out[i] - world[i]));
    expect(worst).toBeLessThan(1e-7);
  });

  it('turns and moves with a skin that turns and moves as a whole', () => {
    // A turn of 50 degrees about a slanted axis, then a shift.
    const axis = [0.3, -0.5, 0.8].map((v, _i, a) => v / Math.hypot(...a));
    const angle = (50 * Math.PI) / 180,
      c = Math.cos(angle),
      sn = Math.sin(angle);
    const turn = (v: ArrayLike<number>, o: number, shift: number[]): number[] => {
      const [x, y, z] = [v[o], v[o + 1], v[o + 2]];
      const d = axis[0] * x + axis[1] * y + axis[2] * z;
      const cr = [axis[1] * z - axis[2] * y, axis[2] * x - axis[0] * z, axis[0] * y - axis[1] * x];
      return [0, 1, 2].map((k) => [x, y, z][k] * c + cr[k] * sn + axis[k] * d * (1 - c) + shift[k]);
    };
    const moved = new Float32Array(s.positions.length);
    const movedNormals = new Float32Array(s.normals.length);
    for (let v = 0; v < moved.length; v += 3) {
      moved.set(turn(s.positions, v, [0.01, -0.02, 0.03]), v);
      movedNormals.set(turn(s.normals, v, [0, 0, 0]), v);
    }
    poseHair(strands, moved, movedNormals, out, normals);
    let worst = 0;
    for (let v = 0; v < world.length; v += 3) {
      const expected = turn(world, v, [0.01, -0.02, 0.03]);
      for (let k = 0; k < 3; k++) worst = Math.max(worst, Math.abs(out[v + k] - expected[k]));
    }
    expect(worst).toBeLessThan(1e-6);
  });

  it('keeps each root within 0.1 mm of its anchor point on a stretched, rippled skin', () => {
    const random = mulberry32(11);
    const moved = new Float32Array(s.positions.length);
    for (let v = 0; v < moved.length; v += 3) {
      moved[v] = 1.3 * s.positions[v] + 0.0005 * (random() - 0.5);
      moved[v + 1] = 0.8 * s.positions[v + 1] + 0.0005 * (random() - 0.5);
      moved[v + 2] = s.positions[v + 2] + 0.003 * Math.sin(200 * s.positions[v]);
    }
    poseHair(strands, moved, s.normals, out, normals);
    const per = strands.verticesPerHair;
    let worst = 0;
    for (let h = 0; h < strands.count; h++) {
      const anchor = [0, 1, 2].map((k) =>
        [0, 1, 2].reduce((sum, c) => sum + strands.weights[3 * h + c] * moved[3 * strands.corners[3 * h + c] + k], 0),
      );
      const root = [0, 1, 2].map((k) => {
        let sum = 0;
        for (let r = 0; r < ROOT_VERTICES; r++) sum += out[3 * (h * per + r) + k];
        return sum / ROOT_VERTICES;
      });
      worst = Math.max(worst, Math.hypot(root[0] - anchor[0], root[1] - anchor[1], root[2] - anchor[2]));
    }
    expect(worst).toBeLessThan(0.0001);
    expect(worst).toBeGreaterThan(0); // the roots stand a little off the skin, along its normal
  });

  it('writes only the hairs asked for, so that a sparser brow costs less', () => {
    out.fill(NaN);
    poseHair(strands, s.positions, s.normals, out, normals, 50);
    expect(Number.isFinite(out[3 * 50 * strands.verticesPerHair - 1])).toBe(true);
    expect(Number.isNaN(out[3 * 50 * strands.verticesPerHair])).toBe(true);
  });
});
