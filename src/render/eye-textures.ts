/**
 * Procedural eye textures in the eyeball's own uv layout (scripts/model/eye.ts): u goes once around the optical axis,
 * v runs outward on the iris (0 at the centre, 1 at the limbus) and backward on the sclera (0 at the limbus, 1 at the
 * back pole). Seeded, so every load looks the same. Pure data (RGBA8, sRGB-encoded colour), no DOM.
 */
import { clamp01, smoothstep } from '../core/math3';
import { mulberry32 } from '../core/random';

/** An RGBA8 image, rows from v = 0 upward, colour sRGB-encoded. */
export interface EyeImage {
  width: number;
  height: number;
  data: Uint8Array;
}

/** Options of the iris texture; colours are linear RGB. */
export interface IrisOptions {
  seed: number;
  /** Pupil radius as a fraction of the iris radius (the model's pupil ring: scripts/model/eye.ts). */
  pupilRatio: number;
  /** Iris colour near the pupil and near the limbus. */
  inner: readonly [number, number, number];
  outer: readonly [number, number, number];
}

const IRIS_DEFAULTS: Readonly<Required<IrisOptions>> = Object.freeze({
  seed: 11,
  pupilRatio: 0.34,
  inner: [0.3, 0.17, 0.06] as const,
  outer: [0.1, 0.16, 0.13] as const,
});

/** Iris: radial fibres, a brighter collarette ring with crypts, a dark limbal ring and the black pupil. */
export function generateIrisImage(options: Partial<IrisOptions> = {}): EyeImage {
  const o: Required<IrisOptions> = { ...IRIS_DEFAULTS, ...options };
  const width = 256;
  const height = 64;
  const random = mulberry32(o.seed);
  // Fibre brightness per angle, at three scales; each sum stays periodic in u.
  const waves = Array.from({ length: 24 }, (_, k) => ({
    f: 3 + Math.floor(random() * (k < 8 ? 20 : 90)),
    phase: 2 * Math.PI * random(),
    a: random(),
  }));
  const crypts = Array.from({ length: 14 }, () => ({ u: random(), r: 0.28 + 0.3 * random(), size: 0.015 + 0.025 * random() }));
  const data = new Uint8Array(4 * width * height);
  for (let y = 0; y < height; y++) {
    const t = (y + 0.5) / height;
    for (let x = 0; x < width; x++) {
      const u = (x + 0.5) / width;
      const i = 4 * (y * width + x);
      let rgb: [number, number, number];
      if (t < o.pupilRatio) {
        rgb = [0.004, 0.004, 0.005];
      } else {
        const s = (t - o.pupilRatio) / (1 - o.pupilRatio);
        let fibre = 0;
        let sum = 0;
        for (const w of waves) {
          // Fibres wave a little as they run outward, as the stroma's do.
          fibre += w.a * Math.sin(w.f * 2 * Math.PI * u + w.phase + 1.5 * s * Math.sin(w.phase + 6 * s));
          sum += w.a;
        }
        fibre /= sum;
        // The collarette: a lighter, wavy ring about a third of the way out.
        const collar = 0.3 + 0.03 * Math.sin(2 * Math.PI * 9 * u + 1.3);
        const ring = Math.exp(-(((s - collar) / 0.06) ** 2));
        let crypt = 0;
        for (const c of crypts) {
          const du = Math.min(Math.abs(u - c.u), 1 - Math.abs(u - c.u)) * 2.2;
          crypt = Math.max(crypt, Math.exp(-((du * du + (s - c.r) ** 2) / (c.size * c.size))));
        }
        const limbal = 1 - 0.85 * smoothstep(0.72, 1, s);
        const ruff = 1 - 0.6 * (1 - smoothstep(0, 0.06, s));
        const light = (0.78 + 0.55 * fibre + 0.35 * ring) * (1 - 0.45 * crypt) * limbal * ruff;
        const m = smoothstep(0.1, 0.75, s);
        rgb = [0, 1, 2].map((k) => Math.max(0, light * (o.inner[k] * (1 - m) + o.outer[k] * m))) as [number, number, number];
      }
      for (let k = 0; k < 3; k++) data[i + k] = toSrgbByte(rgb[k]);
      data[i + 3] = 255;
    }
  }
  return { width, height, data };
}

/** Sclera: off-white, a little pinker and yellower away from the limbus, with a few faint branching veins. */
export function generateScleraImage(seed = 5): EyeImage {
  const width = 256;
  const height = 128;
  const random = mulberry32(seed);
  const vein = new Float32Array(width * height);
  // Veins: random walks from behind the visible part toward the limbus, thinning and fading as they go.
  for (let k = 0; k < 26; k++) {
    let x = random() * width;
    let y = height * (0.45 + 0.4 * random());
    let heading = -Math.PI / 2 + (random() - 0.5) * 0.8;
    const strength = 0.3 + 0.7 * random();
    const steps = 40 + Math.floor(random() * 60);
    for (let s = 0; s < steps && y > 2; s++) {
      heading += (random() - 0.5) * 0.5;
      x += Math.cos(heading);
      y += Math.sin(heading);
      const xi = ((Math.round(x) % width) + width) % width;
      const yi = Math.round(y);
      if (yi < 0 || yi >= height) break;
      const v = strength * (1 - s / steps);
      vein[yi * width + xi] = Math.max(vein[yi * width + xi], v);
      vein[yi * width + ((xi + 1) % width)] = Math.max(vein[yi * width + ((xi + 1) % width)], 0.4 * v);
    }
  }
  const data = new Uint8Array(4 * width * height);
  for (let y = 0; y < height; y++) {
    const t = (y + 0.5) / height;
    const back = smoothstep(0.05, 0.7, t);
    // Just outside the limbus the sclera is a little greyer (the limbus is not a hard edge).
    const limbus = 1 - 0.12 * (1 - smoothstep(0, 0.06, t));
    for (let x = 0; x < width; x++) {
      const i = y * width + x;
      const v = 0.55 * vein[i];
      const base = [0.62 - 0.02 * back, 0.57 - 0.06 * back, 0.5 - 0.09 * back];
      const tint = [0.55, 0.1, 0.08];
      for (let k = 0; k < 3; k++) data[4 * i + k] = toSrgbByte(limbus * (base[k] * (1 - v) + tint[k] * v));
      data[4 * i + 3] = 255;
    }
  }
  return { width, height, data };
}

/** Linear 0..1 to an sRGB-encoded byte. */
function toSrgbByte(linear: number): number {
  const c = clamp01(linear);
  const s = c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055;
  return Math.round(255 * s);
}
