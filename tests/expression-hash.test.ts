import { describe, expect, it } from 'vitest';
import {
  appearanceChanges,
  decodeAppearance,
  decodeExpression,
  encodeExpression,
  expressionEntries,
  readExpression,
} from '../src/face/expression-hash';

describe('the expression carried in the URL hash', () => {
  it('round-trips non-zero Action Units and preset weights, leaving zeros out', () => {
    const hash = encodeExpression({
      actionUnits: { AU12L: 0.5, AU12R: 0.5, AU17: 0, AU4R: 0.123456 },
      presets: { happiness: 0.3, 'thesis-anger': 0, 'a b&c': 1 },
    });
    expect(hash).toBe('#AU12L=0.5&AU12R=0.5&AU4R=0.1235&preset%3Ahappiness=0.3&preset%3Aa+b%26c=1');
    expect(decodeExpression(hash)).toEqual({
      actionUnits: { AU12L: 0.5, AU12R: 0.5, AU4R: 0.1235 },
      presets: { happiness: 0.3, 'a b&c': 1 },
    });
  });

  it('is empty for the neutral face', () => {
    expect(encodeExpression({ actionUnits: { AU1L: 0 }, presets: {} })).toBe('');
    expect(decodeExpression('')).toEqual({ actionUnits: {}, presets: {} });
  });

  it('skips entries that are not finite numbers (the face checks the ids)', () => {
    expect(decodeExpression('#AU1L=abc&AU2L=&AU4=Infinity&AU5L=0.2&preset:x=NaN&AU99=1')).toEqual({
      actionUnits: { AU5L: 0.2, AU99: 1 },
      presets: {},
    });
  });
});

describe('an expression given to createFace, setExpression or <soft-face>', () => {
  it('reads the text form or the same entries as an object', () => {
    const expected = { actionUnits: { AU12: 0.8, AU6L: 0.5 }, presets: { happiness: 0.3 } };
    expect(readExpression('AU12=0.8&AU6L=0.5&preset:happiness=0.3')).toEqual(expected);
    expect(readExpression('#AU12=0.8&AU6L=0.5&preset%3Ahappiness=0.3')).toEqual(expected);
    expect(readExpression({ AU12: 0.8, AU6L: 0.5, 'preset:happiness': 0.3 })).toEqual(expected);
    expect(readExpression('')).toEqual({ actionUnits: {}, presets: {} });
    expect(expressionEntries(expected)).toEqual({ AU12: 0.8, AU6L: 0.5, 'preset:happiness': 0.3 });
  });

  it('refuses, naming it, an entry that is not a finite number (where the hash skips it)', () => {
    expect(() => readExpression('AU12=abc', 'setExpression')).toThrow('setExpression: AU12: expected a finite number, got "abc"');
    expect(() => readExpression('AU12=', 'setExpression')).toThrow('setExpression: AU12: expected a finite number, got ""');
    expect(() => readExpression({ AU12: Infinity })).toThrow('expression: AU12: expected a finite number, got Infinity');
    expect(() => readExpression(42 as unknown as string)).toThrow(
      'expression: expected text like "AU12=0.8&preset:happiness=0.3" or an object like { AU12: 0.8 }, got 42',
    );
  });
});

describe('appearance in the hash', () => {
  const defaults = { brows: true, browColor: '#4a3427', browDensity: 1, lashes: true, lashColor: '#1c1612' };

  it('carries only what differs from the defaults, beside the expression, and reads it back typed', () => {
    const changes = appearanceChanges({ ...defaults, browDensity: 0.4, lashes: false, browColor: '#4A3427' }, defaults);
    expect(changes).toEqual({ browDensity: 0.4, lashes: false });
    const hash = encodeExpression({ actionUnits: { AU12: 0.5 }, presets: {} }, undefined, { ...changes, lashColor: '#aa0000' });
    expect(hash).toBe('#AU12=0.5&appearance.browDensity=0.4&appearance.lashes=0&appearance.lashColor=%23aa0000');
    expect(decodeAppearance(hash, defaults)).toEqual({ browDensity: 0.4, lashes: false, lashColor: '#aa0000' });
    // Not Action Units.
    expect(decodeExpression(hash)).toEqual({ actionUnits: { AU12: 0.5 }, presets: {} });
  });

  it('keeps entries of the wrong form as given, for the face to refuse by name', () => {
    expect(decodeAppearance('#appearance.browDensity=lots&appearance.brows=yes&appearance.beard=1', defaults)).toEqual({
      browDensity: 'lots',
      brows: 'yes',
      beard: '1',
    });
  });
});
