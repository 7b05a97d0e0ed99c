import { describe, expect, it } from 'vitest';
import { ATTRIBUTE_DEFAULTS, readAttributes, readPresets, type FaceAttribute } from '../src/embed/element-attributes';

const read = (attributes: Partial<Record<FaceAttribute, string>>) => readAttributes((a) => attributes[a] ?? null, ATTRIBUTE_DEFAULTS);

describe('<soft-face> attributes', () => {
  it('read as the options they ask for, absent ones as the defaults', () => {
    expect(ATTRIBUTE_DEFAULTS).toMatchObject({
      resolution: 'medium',
      solver: 'auto',
      panels: false,
      eyeSimulation: false,
      background: '#1d2024',
    });
    expect(
      read({
        resolution: 'low',
        panels: '',
        'eye-simulation': 'eye-simulation',
        background: 'transparent',
        expression: '#AU12=0.8&preset:happiness=0.3',
        preset: 'surprise:0.5, fear',
        facs: '1+2+5B+L12C',
        identity: ' old-african-woman ',
      }),
    ).toEqual({
      resolution: 'low',
      solver: 'auto',
      panels: true,
      eyeSimulation: true,
      background: 'transparent',
      expression: { actionUnits: { AU12: 0.8 }, presets: { happiness: 0.3 } },
      preset: { actionUnits: {}, presets: { surprise: 0.5, fear: 1 } },
      facs: { AU1: 1, AU2: 1, AU5: 0.2, AU12L: 0.4 },
      identity: 'old-african-woman',
    });
    expect(read({ identity: 'sex:1,age:30,asian:1' }).identity).toBe('sex:1,age:30,asian:1');
    expect(read({ panels: 'false', 'eye-simulation': 'TRUE' })).toMatchObject({ panels: false, eyeSimulation: true });
  });

  it('read only the attribute asked for, keeping the others', () => {
    const current = { ...ATTRIBUTE_DEFAULTS, resolution: 'low' as const };
    expect(readAttributes((a) => (a === 'panels' ? '' : 'bad'), current, 'panels')).toEqual({ ...current, panels: true });
  });

  it('reject a bad value, naming the attribute', () => {
    expect(() => read({ resolution: 'ultra' })).toThrow('<soft-face>: resolution: expected one of low, medium, high, got "ultra"');
    expect(() => read({ panels: 'yes' })).toThrow('<soft-face>: panels: expected present (on), "true" or "false", got "yes"');
    expect(() => read({ identity: 'sex:1,age:-1' })).toThrow('<soft-face> identity: age: expected a number from 1 to 90, got -1');
    expect(() => read({ expression: 'AU12=' })).toThrow('<soft-face> expression: AU12: expected a finite number, got ""');
    expect(() => read({ facs: '4+L17' })).toThrow('<soft-face> facs: at 3 of "4+L17": expected 17 without a side');
    expect(() => readPresets('happiness:lots')).toThrow(
      '<soft-face>: preset: expected a preset name and a weight, like "happiness:0.5", got "happiness:lots"',
    );
    expect(() => readPresets(':1')).toThrow('<soft-face>: preset: expected a preset name and a weight, like "happiness:0.5", got ":1"');
  });
});
