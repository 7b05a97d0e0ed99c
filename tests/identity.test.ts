import { describe, expect, it } from 'vitest';
import {
  ageSlider,
  applyMacroTargets,
  checkIdentity,
  IDENTITY_DEFAULTS,
  macroTargetWeights,
  parseMacroTarget,
  STOCK_IDENTITIES,
  type Identity,
} from '../src/core/head/identity';

const person = (sex: number, age: number, ancestry: Partial<Identity['ancestry']>): Identity =>
  checkIdentity({ sex, age, ancestry }, 'test');
const weightsOf = (identity: Identity): Record<string, number> =>
  Object.fromEntries(macroTargetWeights(identity).map((t) => [t.target, t.weight]));

describe('identity', () => {
  it('maps years to the age slider as MakeHuman 1.x does: 1 y at 0, 10 y at the child knot, 25 y at 0.5, 90 y at 1', () => {
    expect(ageSlider(1)).toBe(0);
    expect(ageSlider(10)).toBeCloseTo(0.1875, 12);
    expect(ageSlider(25)).toBe(0.5);
    expect(ageSlider(57.5)).toBeCloseTo(0.75, 12);
    expect(ageSlider(90)).toBe(1);
  });

  it('weights one file whole at a knot, and two neighbours linearly between knots', () => {
    expect(weightsOf(person(1, 25, { european: 1 }))).toEqual({ 'caucasian-male-young': 1 });
    expect(weightsOf(person(0, 90, { african: 1 }))).toEqual({ 'african-female-old': 1 });
    const between = weightsOf(person(0, 57.5, { asian: 1 }));
    expect(Object.keys(between).sort()).toEqual(['asian-female-old', 'asian-female-young']);
    expect(between['asian-female-old']).toBeCloseTo(0.5, 12);
    // a = 0.25: child 0.8, young 0.2 (the README of the targets).
    const child = weightsOf(person(0.5, 1 + 0.25 * 48, { european: 1 }));
    expect(child['caucasian-female-child']).toBeCloseTo(0.4, 12);
    expect(child['caucasian-male-young']).toBeCloseTo(0.1, 12);
  });

  it('sums the weights to 1 for any identity, with the ancestry scaled to a sum of 1', () => {
    const mixed = person(0.3, 40, { african: 0.2, asian: 0.2 });
    expect(mixed.ancestry).toEqual({ african: 0.5, asian: 0.5, european: 0 });
    for (const identity of [mixed, IDENTITY_DEFAULTS, ...Object.values(STOCK_IDENTITIES)]) {
      const sum = macroTargetWeights(identity).reduce((s, t) => s + t.weight, 0);
      expect(sum).toBeCloseTo(1, 12);
    }
  });

  it('offers at least 12 stock identities: each sex at three ages and three ancestries', () => {
    const names = Object.keys(STOCK_IDENTITIES);
    expect(names.length).toBeGreaterThanOrEqual(12);
    expect(names).toContain('old-african-woman');
    expect(names).toContain('young-asian-man');
    const sexes = new Set(Object.values(STOCK_IDENTITIES).map((i) => i.sex));
    const ages = new Set(Object.values(STOCK_IDENTITIES).map((i) => i.age));
    expect([...sexes].sort()).toEqual([0, 1]);
    expect(ages.size).toBe(3);
  });

  it('refuses a bad identity, naming the field', () => {
    const cases: [unknown, string][] = [
      [{ sex: 2 }, 'setIdentity: sex: expected a number from 0 to 1, got 2'],
      [{ age: -1 }, 'setIdentity: age: expected a number from 1 to 90, got -1'],
      [{ age: Number.NaN }, 'setIdentity: age: expected a number from 1 to 90, got NaN'],
      [{ ancestry: { african: 0, asian: 0 } }, 'setIdentity: ancestry: expected weights with a positive sum, got 0'],
      [{ ancestry: { martian: 1 } }, 'setIdentity: ancestry: expected one of the ancestries african, asian, european, got "martian"'],
      [{ height: 2 }, 'setIdentity: expected one of the fields sex, age, ancestry, got "height"'],
      ['old', 'setIdentity: expected an identity { sex, age, ancestry }, got "old"'],
    ];
    for (const [value, message] of cases) expect(() => checkIdentity(value, 'setIdentity'), JSON.stringify(value)).toThrow(message);
  });

  it('reads a target file and adds its weighted offsets to the listed vertices only', () => {
    const target = parseMacroTarget('0 .5 0 0\n2 0 -1 .25\n', 3, 'a.target');
    const positions = new Float32Array(9).fill(1);
    applyMacroTargets(positions, [{ target, weight: 0.5 }]);
    expect([...positions]).toEqual([1.25, 1, 1, 1, 1, 1, 1, 0.5, 1.125]);
    expect(() => parseMacroTarget('0 1 2\n', 3, 'b.target')).toThrow('b.target: line 1: expected "index dx dy dz" with an index below 3');
    expect(() => parseMacroTarget('5 0 0 0\n', 3, 'c.target')).toThrow('c.target: line 1:');
  });
});
