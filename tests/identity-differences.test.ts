import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { identitySkinPositions } from '../src/core/head/build/identity-head';
import { readIdentitySource } from '../src/core/head/build/identity-source';
import { STOCK_IDENTITIES } from '../src/core/head/identity';
import { identityLook } from '../src/core/head/identity-look';
import { fitIdentityWarp } from '../src/core/head/identity-warp';
import { DEFAULT_LANDMARKS, type LandmarkName } from '../src/core/head/landmarks';
import { warpPoint } from '../src/core/head/thin-plate';

const source = readIdentitySource(new Uint8Array(readFileSync(new URL('../public/models/identity-source.bin', import.meta.url))));
const base = identitySkinPositions(source, null);

/** Each stock identity's landmarks, carried over from the default head as the face carries them (identity-head.ts). */
const landmarks = Object.fromEntries(
  Object.entries(STOCK_IDENTITIES).map(([name, identity]) => {
    const warp = fitIdentityWarp(base, identitySkinPositions(source, identity));
    const at = (n: LandmarkName): number[] => warpPoint(warp, DEFAULT_LANDMARKS[n]);
    return [name, at];
  }),
);
const distance = (a: number[], b: number[]): number => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const mid = (a: number[], b: number[]): number[] => a.map((x, k) => (x + b[k]) / 2);

/** Measures of a face (mm) that differ between people. */
const MEASURES: Record<string, (at: (n: LandmarkName) => number[]) => number> = {
  // Across the head at the ears: the jaw's and skull's width.
  'head width (ear to ear)': (at) => 1000 * distance(at('ear-l'), at('ear-r')),
  'nose length (brows to tip)': (at) => 1000 * distance(mid(at('brow-l'), at('brow-r')), at('nose-tip')),
  'brow to eye': (at) => 1000 * distance(at('brow-l'), mid(at('eye-inner-l'), at('eye-outer-l'))),
  'mouth width': (at) => 1000 * distance(at('mouth-l'), at('mouth-r')),
  'face height (brows to chin)': (at) => 1000 * distance(mid(at('brow-l'), at('brow-r')), at('chin')),
};

describe('stock identities differ where faces differ', () => {
  for (const [measure, of] of Object.entries(MEASURES)) {
    it(`${measure}: the largest is at least 8 % over the smallest`, () => {
      const values = Object.values(landmarks).map(of);
      expect(Math.max(...values) / Math.min(...values)).toBeGreaterThan(1.08);
      for (const v of values) expect(Number.isFinite(v) && v > 5 && v < 250).toBe(true);
    });
  }

  it('no two people look alike: the skins of any two differ by 2 mm or more somewhere', () => {
    const skins = Object.values(STOCK_IDENTITIES).map((identity) => identitySkinPositions(source, identity));
    for (let i = 0; i < skins.length; i++)
      for (let j = i + 1; j < skins.length; j++) {
        let most = 0;
        for (let k = 0; k < base.length; k += 3)
          most = Math.max(
            most,
            Math.hypot(skins[i][k] - skins[j][k], skins[i][k + 1] - skins[j][k + 1], skins[i][k + 2] - skins[j][k + 2]),
          );
        expect(most).toBeGreaterThan(0.002);
      }
  });

  it('men have wider heads and longer faces than women of the same age and ancestry', () => {
    for (const age of ['young', 'middle-aged', 'old'])
      for (const ancestry of ['african', 'asian', 'european']) {
        const man = landmarks[`${age}-${ancestry}-man`];
        const woman = landmarks[`${age}-${ancestry}-woman`];
        expect(MEASURES['head width (ear to ear)'](man)).toBeGreaterThan(MEASURES['head width (ear to ear)'](woman));
        expect(MEASURES['face height (brows to chin)'](man)).toBeGreaterThan(MEASURES['face height (brows to chin)'](woman));
      }
  });

  it('their skin tones differ: darker with African ancestry, and each ancestry its own', () => {
    const luminance = (name: string): number => {
      const [r, g, b] = identityLook(STOCK_IDENTITIES[name]).skin;
      return 0.2126 * r + 0.7152 * g + 0.0722 * b;
    };
    expect(luminance('young-african-woman')).toBeLessThan(0.5 * luminance('young-european-woman'));
    expect(luminance('young-asian-woman')).toBeLessThan(luminance('young-european-woman'));
    expect(luminance('young-asian-woman')).toBeGreaterThan(luminance('young-african-woman'));
  });
});
