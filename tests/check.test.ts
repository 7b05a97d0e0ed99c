import { describe, expect, it } from 'vitest';
import { checkBoolean, checkChoice, checkNumber, checkObject, numberIn, refusal, show } from '../src/core/check';

describe('check.ts', () => {
  it('shows found values briefly', () => {
    expect(show(undefined)).toBe('nothing');
    expect(show(-0.01)).toBe('-0.01');
    expect(show('spring')).toBe('"spring"');
    expect(show('x'.repeat(41))).toBe(`"${'x'.repeat(40)}"...`);
    expect(show([1, 2])).toBe('[1,2]');
    expect(show([1, 2, 3, 4, 5])).toBe('an array of 5 items');
    expect(show(['a'])).toBe('an array of 1 item');
    expect(show({})).toBe('an object');
    expect(show(() => 0)).toBe('a function');
  });

  it('words refusals as "<what>: <path>: expected ..., got ...", leaving out an empty path', () => {
    expect(refusal('setLight', 'keyAzimuth', numberIn([0, 360]), 400).message).toBe(
      'setLight: keyAzimuth: expected a number from 0 to 360, got 400',
    );
    expect(refusal('setLight', '', 'an object of options', null).message).toBe('setLight: expected an object of options, got null');
    expect(numberIn([1, 64], true)).toBe('an integer from 1 to 64');
    expect(numberIn(undefined)).toBe('a finite number');
    expect(numberIn(undefined, true)).toBe('an integer');
  });

  it('checks numbers: finite, whole if asked, within the range with its ends', () => {
    expect(checkNumber('f', 'x', 0, [0, 1])).toBe(0);
    expect(checkNumber('f', 'x', 1, [0, 1])).toBe(1);
    expect(checkNumber('f', 'x', -1e9)).toBe(-1e9);
    expect(() => checkNumber('f', 'x', 1.01, [0, 1])).toThrow('f: x: expected a number from 0 to 1, got 1.01');
    expect(() => checkNumber('f', 'x', Number.NaN)).toThrow('f: x: expected a finite number, got NaN');
    expect(() => checkNumber('f', 'x', '1', [0, 1])).toThrow('f: x: expected a number from 0 to 1, got "1"');
    expect(() => checkNumber('f', 'n', 2.5, [0, 64], true)).toThrow('f: n: expected an integer from 0 to 64, got 2.5');
  });

  it('checks booleans, choices and objects', () => {
    expect(checkBoolean('f', 'on', false)).toBe(false);
    expect(() => checkBoolean('f', 'on', 1)).toThrow('f: on: expected true or false, got 1');
    expect(checkChoice('f', 'mode', 'add', ['add', 'remove'])).toBe('add');
    expect(() => checkChoice('f', 'mode', 'off', ['add', 'remove'])).toThrow('f: mode: expected one of "add", "remove", got "off"');
    expect(checkObject('f', { a: 1 })).toEqual({ a: 1 });
    expect(() => checkObject('f', [])).toThrow('f: expected an object of options, got []');
    expect(() => checkObject('f', null, 'a brush')).toThrow('f: expected a brush, got null');
  });
});
