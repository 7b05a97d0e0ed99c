import { describe, expect, it } from 'vitest';
import { LevelCarry } from '../src/core/head/level-carry';
import { buildTopology, type SkinTopology } from '../src/core/solver/topology';
import { mulberry32 } from '../src/core/random';
import { loadHeadSkin } from './fixtures/head';

async function skin(resolution: 'low' | 'medium' | 'high'): Promise<SkinTopology> {
  const { positions, indices } = await loadHeadSkin(resolution);
  return buildTopology(positions, indices);
}

function largestDistance(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let worst = 0;
  for (let i = 0; i < a.length; i += 3) worst = Math.max(worst, Math.hypot(a[i] - b[i], a[i + 1] - b[i + 1], a[i + 2] - b[i + 2]));
  return worst;
}

describe('LevelCarry: a shape carried up a level through the Catmull-Clark stencils', () => {
  it('makes the finer default head at rest from the coarser one at rest, low to medium and medium to high', async () => {
    const [low, medium, high] = await Promise.all([skin('low'), skin('medium'), skin('high')]);
    for (const [coarse, fine] of [
      [low, medium],
      [medium, high],
    ]) {
      const carry = LevelCarry.between(coarse.rest, coarse.triangles, fine.rest);
      expect(carry).not.toBeNull();
      const out = new Float32Array(3 * fine.vertexCount);
      carry!.carry(coarse.rest, out);
      expect(largestDistance(out, fine.rest)).toBeLessThan(1e-6);
    }
  }, 60_000);

  it('moves the fine skin as the coarse one moves: a turned and shifted coarse shape gives the fine rest turned and shifted', async () => {
    const [low, medium] = await Promise.all([skin('low'), skin('medium')]);
    const carry = LevelCarry.between(low.rest, low.triangles, medium.rest)!;
    const angle = 0.4;
    const [c, s] = [Math.cos(angle), Math.sin(angle)];
    const move = (x: Float32Array): Float32Array => {
      const out = new Float32Array(x.length);
      for (let i = 0; i < x.length; i += 3) {
        out[i] = c * x[i] + s * x[i + 2] + 0.01;
        out[i + 1] = x[i + 1] - 0.02;
        out[i + 2] = -s * x[i] + c * x[i + 2];
      }
      return out;
    };
    const out = new Float32Array(3 * medium.vertexCount);
    carry.carry(move(low.rest), out);
    expect(largestDistance(out, move(medium.rest))).toBeLessThan(1e-6);
  }, 60_000);

  it('refuses a fine skin that is not the coarse one subdivided: two levels apart, or one vertex moved 0.1 mm', async () => {
    const [low, medium, high] = await Promise.all([skin('low'), skin('medium'), skin('high')]);
    expect(LevelCarry.between(low.rest, low.triangles, high.rest)).toBeNull();
    const moved = Float32Array.from(medium.rest);
    const v = Math.floor(mulberry32(7)() * medium.vertexCount);
    moved[3 * v + 1] += 0.0001;
    expect(LevelCarry.between(low.rest, low.triangles, moved)).toBeNull();
    expect(LevelCarry.between(low.rest, low.triangles, medium.rest)).not.toBeNull();
  }, 60_000);
});
