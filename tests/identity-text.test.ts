import { describe, expect, it } from 'vitest';
import { identityText, readIdentity, sameIdentity, STOCK_IDENTITIES, stockIdentities } from '../src/core/head/identity';
import { mulberry32 } from '../src/core/random';

describe('identity as text (URL hash, attribute, option)', () => {
  it('lists at least 12 stock identities, each read back by its name', () => {
    const stock = stockIdentities();
    expect(stock.length).toBeGreaterThanOrEqual(12);
    for (const { name, identity } of stock) {
      expect(readIdentity(name, 'test')).toEqual({ name, identity });
      expect(identityText(identity)).toBe(name);
    }
  });

  it('writes a person of no stock name as "sex:..,age:..,<ancestry>:.." and reads the same person back', () => {
    const random = mulberry32(33);
    for (let i = 0; i < 50; i++) {
      const a = random();
      const given = { sex: random(), age: 1 + 89 * random(), ancestry: { african: a, asian: 0, european: 1 - a } };
      const text = identityText(given);
      expect(text).toMatch(/^sex:[\d.]+,age:[\d.]+(,(african|asian|european):[\d.]+)+$/);
      const read = readIdentity(text, 'test');
      expect(read?.name).toBe(text);
      expect(sameIdentity(read!.identity, given)).toBe(true);
    }
  });

  it('fills what the text leaves out from MakeHuman’s average and scales the ancestry to sum to 1', () => {
    const read = readIdentity('age:70,asian:0.4,african:0.4', 'test')!;
    expect(read.identity).toEqual({ sex: 0.5, age: 70, ancestry: { african: 0.5, asian: 0.5, european: 0 } });
    expect(readIdentity(null, 'test')).toBeNull();
  });

  it.each([
    ['old-martian-man', /^setIdentity: expected a stock identity .*old-african-woman.*, got "old-martian-man"$/],
    ['sex:2', /^setIdentity: sex: expected a number from 0 to 1, got 2$/],
    ['sex:0.5,age:', /^setIdentity: expected parts like "sex:1".*, got "age:"$/],
    ['sex:0.5,height:3', /^setIdentity: expected one of the fields sex, age, ancestry, got "height"$/],
    ['african:0', /^setIdentity: ancestry: expected weights with a positive sum, got 0$/],
  ])('refuses %s naming what is wrong', (text, message) => {
    expect(() => readIdentity(text, 'setIdentity')).toThrow(message);
  });

  it('refuses what is neither text, an object nor null', () => {
    expect(() => readIdentity(42, 'setIdentity')).toThrow(/^setIdentity: expected an identity \{ sex, age, ancestry \}, got 42$/);
    expect(Object.keys(STOCK_IDENTITIES)).toContain('old-african-woman');
  });
});
