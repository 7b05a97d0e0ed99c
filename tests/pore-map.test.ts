import { describe, expect, it } from 'vitest';
import { generatePoreMap } from '../src/render/pore-map';

/** Mean decoded normal of a map, and the fraction of texels leaning more than 10 degrees. */
function stats(data: Uint8Array): { mean: number[]; leaning: number } {
  const mean = [0, 0, 0];
  let leaning = 0;
  const count = data.length / 4;
  for (let i = 0; i < data.length; i += 4) {
    const n = [0, 1, 2].map((k) => data[i + k] / 127.5 - 1);
    for (let k = 0; k < 3; k++) mean[k] += n[k] / count;
    if (n[2] / Math.hypot(n[0], n[1], n[2]) < Math.cos((10 * Math.PI) / 180)) leaning++;
  }
  return { mean, leaning: leaning / count };
}

describe('pore map', () => {
  it('gives the same bytes for the same seed and different bytes for another', () => {
    const a = generatePoreMap({ size: 128, seed: 3 });
    const b = generatePoreMap({ size: 128, seed: 3 });
    const c = generatePoreMap({ size: 128, seed: 4 });
    expect(a.width).toBe(128);
    expect(a.data.length).toBe(4 * 128 * 128);
    expect(Buffer.from(a.data).equals(Buffer.from(b.data))).toBe(true);
    const differing = a.data.reduce((n, v, i) => n + (v !== c.data[i] ? 1 : 0), 0);
    expect(differing / a.data.length).toBeGreaterThan(0.3);
  });

  it('averages to the flat normal (0, 0, 1) and still has detail', () => {
    const { data } = generatePoreMap();
    const { mean, leaning } = stats(data);
    expect(Math.abs(mean[0])).toBeLessThan(0.01);
    expect(Math.abs(mean[1])).toBeLessThan(0.01);
    expect(mean[2]).toBeGreaterThan(0.95);
    // Pores and furrows: a real share of texels lean, but most of the skin is near flat.
    expect(leaning).toBeGreaterThan(0.05);
    expect(leaning).toBeLessThan(0.6);
  });

  it('tiles: the detail wraps across its edges', () => {
    // With wrapping differences, the first and last columns are as alike as any two neighbouring columns.
    const { data, width } = generatePoreMap({ size: 64, seed: 9 });
    const column = (x: number): number[] => Array.from({ length: width }, (_, y) => data[4 * (y * width + x)]);
    const step = (a: number[], b: number[]): number => a.reduce((s, v, i) => s + Math.abs(v - b[i]), 0) / a.length;
    const inner = Array.from({ length: width - 1 }, (_, x) => step(column(x), column(x + 1)));
    const seam = step(column(width - 1), column(0));
    expect(seam).toBeLessThan(2 * Math.max(...inner));
  });

  it('rejects a size that is not a power of two', () => {
    expect(() => generatePoreMap({ size: 100 })).toThrow(/power of two/);
  });
});
