/**
 * Procedural skin micro-detail as a tiling tangent-space normal map: pores, the fine criss-cross furrows of the
 * skin's surface and a faint grain, from a seeded generator, so every load (and every test) gives the same bytes.
 * Pure data (no DOM), so it runs in tests; materials.ts turns it into a texture.
 */
import { clamp01 } from '../core/math3';
import { mulberry32 } from '../core/random';

/** Options of the pore map. Sizes are in texels; the map tiles, so all patterns wrap around its edges. */
export interface PoreMapOptions {
  /** Texels per side; a power of two (so that it mipmaps and tiles cleanly). */
  size: number;
  seed: number;
  /** Mean distance between pore centres. */
  poreSpacing: number;
  /** Pore radius range. */
  poreRadius: readonly [number, number];
  /** Pore depth, in height units (the furrows' depth is 1). */
  poreDepth: number;
  /** Depth of the criss-cross furrows relative to the pores' unit; 0 leaves them out. */
  furrowDepth: number;
  /** Whole furrows across the map, per direction. */
  furrowCount: number;
  /** Amplitude of the fine grain. */
  grain: number;
  /** Height-to-slope factor: larger makes steeper normals. */
  strength: number;
}

const PORE_MAP_DEFAULTS: Readonly<Required<PoreMapOptions>> = Object.freeze({
  size: 512,
  seed: 1,
  poreSpacing: 5.5,
  poreRadius: [0.9, 1.9] as const,
  poreDepth: 1,
  furrowDepth: 0.15,
  furrowCount: 48,
  grain: 0.25,
  strength: 0.5,
});

/** An RGBA8 image, rows from v = 0 upward. */
export interface PoreMap {
  width: number;
  height: number;
  /** Normal (x, y, z) * 0.5 + 0.5 in RGB; A is the cavity (255 flat, darker in pores and furrows). */
  data: Uint8Array;
}

/** Builds the pore normal map; the same options always give the same bytes. */
export function generatePoreMap(options: Partial<PoreMapOptions> = {}): PoreMap {
  const o: Required<PoreMapOptions> = { ...PORE_MAP_DEFAULTS, ...options };
  const n = o.size;
  if (!Number.isInteger(n) || n < 8 || (n & (n - 1)) !== 0)
    throw new Error(`generatePoreMap: size must be a power of two of at least 8, got ${n}`);
  const random = mulberry32(o.seed);
  const mask = n - 1;
  const height = new Float32Array(n * n);

  // Grain and a slow warp of the furrows, from tiling value noise.
  const warp = valueNoise(n, 8, random);
  const grain = valueNoise(n, n / 4, random);
  const grainFine = valueNoise(n, n / 2, random);
  // Furrows: two families of lines at about +-35 degrees; integer frequencies in both axes keep them tiling.
  const fa = o.furrowCount;
  const fb = Math.round(0.7 * o.furrowCount);
  for (let y = 0; y < n; y++) {
    for (let x = 0; x < n; x++) {
      const i = y * n + x;
      const w = 4 * warp[i];
      const p1 = (2 * Math.PI * (fa * x + fb * y)) / n + w;
      const p2 = (2 * Math.PI * (fa * x - fb * y)) / n - w;
      // Narrow valleys between broad plateaus, as the skin's surface looks under a lens.
      const furrow = Math.abs(Math.sin(0.5 * p1)) ** 0.35 + Math.abs(Math.sin(0.5 * p2)) ** 0.35;
      height[i] = o.furrowDepth * (furrow - 2) + o.grain * (0.65 * grain[i] + 0.35 * grainFine[i]);
    }
  }

  // Pores: jittered on a grid (even cover, no clumps), each a smooth dimple.
  const cells = Math.max(1, Math.round(n / o.poreSpacing));
  const cell = n / cells;
  for (let cy = 0; cy < cells; cy++) {
    for (let cx = 0; cx < cells; cx++) {
      const px = (cx + random()) * cell;
      const py = (cy + random()) * cell;
      const r = o.poreRadius[0] + random() * (o.poreRadius[1] - o.poreRadius[0]);
      const depth = o.poreDepth * (0.45 + 0.55 * random());
      const reach = Math.ceil(r + 1);
      for (let dy = -reach; dy <= reach; dy++) {
        for (let dx = -reach; dx <= reach; dx++) {
          const x = Math.floor(px) + dx;
          const y = Math.floor(py) + dy;
          const d2 = ((x + 0.5 - px) ** 2 + (y + 0.5 - py) ** 2) / (r * r);
          if (d2 >= 1) continue;
          const s = 1 - d2;
          height[(y & mask) * n + (x & mask)] -= depth * s * s;
        }
      }
    }
  }

  // Normals by central differences (wrapping), and a cavity term from how far below the mean height a texel lies.
  let mean = 0;
  let spread = 0;
  for (let i = 0; i < height.length; i++) mean += height[i];
  mean /= height.length;
  for (let i = 0; i < height.length; i++) spread += (height[i] - mean) ** 2;
  spread = Math.sqrt(spread / height.length) || 1;
  const data = new Uint8Array(4 * n * n);
  for (let y = 0; y < n; y++) {
    for (let x = 0; x < n; x++) {
      const i = y * n + x;
      const gx = 0.5 * (height[y * n + ((x + 1) & mask)] - height[y * n + ((x - 1) & mask)]);
      const gy = 0.5 * (height[((y + 1) & mask) * n + x] - height[((y - 1) & mask) * n + x]);
      const nx = -o.strength * gx;
      const ny = -o.strength * gy;
      const len = Math.hypot(nx, ny, 1);
      data[4 * i] = encode(nx / len);
      data[4 * i + 1] = encode(ny / len);
      data[4 * i + 2] = encode(1 / len);
      data[4 * i + 3] = Math.round(255 * clamp01(1 + (0.35 * (height[i] - mean)) / spread));
    }
  }
  return { width: n, height: n, data };
}

/** A unit component -1..1 to a byte. */
const encode = (v: number): number => Math.round(127.5 + 127.5 * v);

/**
 * Tiling value noise on an n x n grid: random values on a lattice of `period` cells per side, smoothly interpolated;
 * -1..1. `period` must divide n.
 */
function valueNoise(n: number, period: number, random: () => number): Float32Array {
  const lattice = Float32Array.from({ length: period * period }, () => 2 * random() - 1);
  const out = new Float32Array(n * n);
  const scale = period / n;
  for (let y = 0; y < n; y++) {
    const fy = y * scale;
    const y0 = Math.floor(fy);
    noiseRow(out, y * n, n, scale, lattice, period, (y0 % period) * period, ((y0 + 1) % period) * period, smooth(fy - y0));
  }
  return out;
}

/**
 * One row of valueNoise: `n` values from `out[at]`, between lattice rows `r0` and `r1` at `ty`. A function of its own:
 * the row loop nested in the image's ran into some hundred bailouts of V8's on-stack replacement in the browser.
 */
function noiseRow(
  out: Float32Array,
  at: number,
  n: number,
  scale: number,
  lattice: Float32Array,
  period: number,
  r0: number,
  r1: number,
  ty: number,
): void {
  for (let x = 0; x < n; x++) {
    const fx = x * scale;
    const x0 = Math.floor(fx);
    const tx = smooth(fx - x0);
    const c0 = x0 % period;
    const c1 = (x0 + 1) % period;
    const top = lattice[r0 + c0] + tx * (lattice[r0 + c1] - lattice[r0 + c0]);
    const bottom = lattice[r1 + c0] + tx * (lattice[r1 + c1] - lattice[r1 + c0]);
    out[at + x] = top + ty * (bottom - top);
  }
}

const smooth = (t: number): number => t * t * (3 - 2 * t);
