import { describe, expect, it } from 'vitest';
import { checkIdentity, STOCK_IDENTITIES } from '../src/core/head/identity';
import { identityLook, skinAlbedo } from '../src/core/head/identity-look';

/** CIE L* and b* (which need only Y and Z) and the Individual Typology Angle (Chardon et al. 1991) of a linear sRGB colour, D65. */
function ita([r, g, b]: readonly number[]): { L: number; b: number; ita: number } {
  const Y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const Z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
  const f = (t: number): number => (t > 0.008856 ? Math.cbrt(t) : 7.787 * t + 16 / 116);
  const L = 116 * f(Y) - 16;
  const bStar = 200 * (f(Y) - f(Z / 1.08883));
  return { L, b: bStar, ita: (Math.atan((L - 50) / bStar) * 180) / Math.PI };
}

describe('identity look', () => {
  it('darkens the skin with melanin in every channel, blue the most', () => {
    const light = skinAlbedo(0.02, 0.015);
    const dark = skinAlbedo(0.35, 0.015);
    for (let c = 0; c < 3; c++) expect(dark[c]).toBeLessThan(light[c]);
    expect(dark[2] / light[2]).toBeLessThan(dark[0] / light[0]);
  });

  it('reddens the skin with blood: green falls more than red', () => {
    const pale = skinAlbedo(0.03, 0.005);
    const flushed = skinAlbedo(0.03, 0.03);
    expect(flushed[1] / pale[1]).toBeLessThan(flushed[0] / pale[0]);
  });

  it('puts the stock ancestries in the published skin-colour classes: European light, Asian intermediate, African dark', () => {
    const of = (name: string): number => ita(identityLook(STOCK_IDENTITIES[name]).skin).ita;
    expect(of('young-european-woman')).toBeGreaterThan(41);
    expect(of('young-asian-woman')).toBeGreaterThan(28);
    expect(of('young-asian-woman')).toBeLessThan(41);
    expect(of('young-african-woman')).toBeLessThan(-30);
  });

  it('greys the brows of old people, and more than their lashes', () => {
    const young = identityLook(STOCK_IDENTITIES['young-european-man']);
    const old = identityLook(STOCK_IDENTITIES['old-european-man']);
    const value = (hex: string): number => Number.parseInt(hex.slice(1, 3), 16);
    expect(value(old.browColor)).toBeGreaterThan(value(young.browColor) + 20);
    expect(value(old.browColor) - value(young.browColor)).toBeGreaterThan(value(old.lashColor) - value(young.lashColor));
  });

  it('gives the same person the same eyes, and different people different ones', () => {
    const person = checkIdentity({ sex: 0.3, age: 33, ancestry: { european: 1 } }, 'test');
    expect(identityLook(person)).toEqual(identityLook(person));
    const irises = new Set(Object.values(STOCK_IDENTITIES).map((i) => JSON.stringify(identityLook(i).iris)));
    expect(irises.size).toBeGreaterThan(1);
  });
});
