import { describe, expect, it } from 'vitest';
import { decodeExpression, encodeExpression } from '../src/app/expression-hash';

describe('the expression carried in the URL hash', () => {
  it('round-trips non-zero Action Units and preset weights, leaving zeros out', () => {
    const hash = encodeExpression({ actionUnits: { AU12L: 0.5, AU12R: 0.5, AU17: 0, AU4R: 0.123456 }, presets: { happiness: 0.3, 'thesis-anger': 0, 'a b&c': 1 } });
    expect(hash).toBe('#AU12L=0.5&AU12R=0.5&AU4R=0.1235&preset%3Ahappiness=0.3&preset%3Aa+b%26c=1');
    expect(decodeExpression(hash)).toEqual({ actionUnits: { AU12L: 0.5, AU12R: 0.5, AU4R: 0.1235 }, presets: { happiness: 0.3, 'a b&c': 1 } });
  });

  it('is empty for the neutral face', () => {
    expect(encodeExpression({ actionUnits: { AU1L: 0 }, presets: {} })).toBe('');
    expect(decodeExpression('')).toEqual({ actionUnits: {}, presets: {} });
  });

  it('skips entries that are not finite numbers (the face checks the ids)', () => {
    expect(decodeExpression('#AU1L=abc&AU2L=&AU4=Infinity&AU5L=0.2&preset:x=NaN&AU99=1')).toEqual({ actionUnits: { AU5L: 0.2, AU99: 1 }, presets: {} });
  });
});
