/**
 * Where the skin's colour departs from its base: red lips, a darker red inner mouth and faintly flushed cheeks, as a
 * per-vertex multiplier of the albedo. Worked out once from the head at rest (metres, +y up, face toward +z); the
 * colours then ride on their vertices through every expression.
 */
import { smoothstep } from '../core/math3';

/** Where the tinted regions are, on the MakeHuman hm08 head (scripts/build-head-model.ts). */
export interface SkinTintOptions {
  /** Middle of the mouth slit at rest (x = 0). */
  mouth: readonly [number, number, number];
  /** Half the mouth's width, and the heights of the upper and lower lips' vermilion at the midline. */
  lipHalfWidth: number;
  upperLip: number;
  lowerLip: number;
  /** The inner mouth's uv island: u from, u to, v below. */
  innerMouthUv: readonly [number, number, number];
  /** Albedo multipliers, linear RGB. */
  lipTint: readonly [number, number, number];
  innerMouthTint: readonly [number, number, number];
  cheekTint: readonly [number, number, number];
}

export const SKIN_TINT_DEFAULTS: Readonly<Required<SkinTintOptions>> = Object.freeze({
  mouth: [0, 0.6615, 0.152] as const,
  lipHalfWidth: 0.026,
  upperLip: 0.0115,
  lowerLip: 0.011,
  innerMouthUv: [0.74, 0.94, 0.14] as const,
  lipTint: [0.86, 0.6, 0.62] as const,
  innerMouthTint: [0.72, 0.36, 0.4] as const,
  cheekTint: [1, 0.9, 0.9] as const,
});

/** Albedo multiplier (RGB) per vertex, from rest positions and uvs. */
export function skinTint(positions: ArrayLike<number>, uvs: ArrayLike<number>, options: Partial<SkinTintOptions> = {}): Float32Array {
  const o: Required<SkinTintOptions> = { ...SKIN_TINT_DEFAULTS, ...options };
  // Mottling: a few fixed plane waves of 1 to 4 cm, so no two patches of skin have quite the same tone.
  const waves = [
    [157, 61, -93, 0.3],
    [-83, 171, 44, 1.7],
    [212, -140, 118, 2.9],
    [-260, -97, 201, 4.1],
    [48, 233, -310, 5.3],
  ];
  const count = positions.length / 3;
  const out = new Float32Array(3 * count);
  const [mx, my, mz] = o.mouth;
  for (let i = 0; i < count; i++) {
    const x = positions[3 * i] - mx;
    const y = positions[3 * i + 1] - my;
    const z = positions[3 * i + 2];
    const u = uvs[2 * i];
    const v = uvs[2 * i + 1];
    let mottle = 0;
    for (const [a, b, c, phase] of waves) mottle += Math.sin(a * positions[3 * i] + b * positions[3 * i + 1] + c * z + phase);
    mottle /= waves.length;
    // Darker patches lean brown (melanin), lighter ones a touch pink (blood near the surface).
    const tint = [1 + 0.05 * mottle, 1 + 0.07 * mottle, 1 + 0.08 * mottle];
    // Cheeks: soft blobs below and outside the eyes.
    const cheek = Math.exp(-((Math.abs(x) - 0.045) ** 2 + (y - 0.035) ** 2) / 0.018 ** 2) * smoothstep(0.09, 0.12, z);
    for (let k = 0; k < 3; k++) tint[k] *= 1 + cheek * (o.cheekTint[k] - 1);
    // Lips: the vermilion narrows toward the corners; its border is fairly sharp, as a real lip's is.
    const across = Math.abs(x) / o.lipHalfWidth;
    if (across < 1 && z > mz - 0.02) {
      const h = (y > 0 ? o.upperLip : o.lowerLip) * (1 - across * across) ** 0.45;
      const lip = (1 - smoothstep(0.75, 1.05, Math.abs(y) / Math.max(h, 1e-6))) * (1 - smoothstep(0.8, 1, across));
      for (let k = 0; k < 3; k++) tint[k] *= 1 + lip * (o.lipTint[k] - 1);
    }
    if (u > o.innerMouthUv[0] && u < o.innerMouthUv[1] && v < o.innerMouthUv[2]) {
      const light = mouthLight(z, mz);
      for (let k = 0; k < 3; k++) tint[k] = o.innerMouthTint[k] * light;
    }
    out.set(tint, 3 * i);
  }
  return out;
}

/** Light left 5 cm or more inside the mouth: what comes in through the lips is mostly absorbed by then. */
export const DEEP_MOUTH_LIGHT = 0.2;

/**
 * How much of the room's light reaches the mouth's inside at depth `z` (metres, +z toward the face's front), with the
 * mouth slit's front at `front`: all of it just behind the lips, falling smoothly to DEEP_MOUTH_LIGHT 5 cm in. A
 * multiplier of the inner mouth's and the tongue's albedo, as the teeth have their occlusion baked.
 */
export function mouthLight(z: number, front: number): number {
  return DEEP_MOUTH_LIGHT + (1 - DEEP_MOUTH_LIGHT) * smoothstep(front - 0.05, front - 0.005, z);
}
