import { describe, expect, it } from 'vitest';
import { FACE_DEFAULTS, checkFaceOptions } from '../src/face/face-options';

describe('createFace options', () => {
  it('fill in the defaults, and keep what is given', () => {
    expect(checkFaceOptions(undefined)).toEqual(FACE_DEFAULTS);
    const o = checkFaceOptions({
      resolution: 'low',
      solver: 'transfer',
      panels: true,
      background: 'transparent',
      expression: 'AU12=0.8',
      light: { keyAzimuth: 90 },
      motionResolution: 1,
      slowDrawMs: 0,
      resolutionUnused: undefined,
    });
    expect(o).toMatchObject({
      resolution: 'low',
      solver: 'transfer',
      panels: true,
      background: 'transparent',
      expression: 'AU12=0.8',
      light: { keyAzimuth: 90 },
      motionResolution: 1,
      slowDrawMs: 0,
      eyeSimulation: false,
    });
  });

  it('reject a bad option with a message naming it and the value', () => {
    const cases: [object, string][] = [
      [{ resolution: 'ultra' }, 'createFace: resolution must be one of low, medium, high, got "ultra"'],
      [{ solver: 'gpu' }, 'createFace: solver must be one of auto, shared, transfer, main, got "gpu"'],
      [{ panels: 'yes' }, 'createFace: panels must be true or false, got "yes"'],
      [{ eyeSimulation: 1 }, 'createFace: eyeSimulation must be true or false, got 1'],
      [{ background: 'red' }, 'createFace: background must be a colour "#rrggbb" or "transparent", got "red"'],
      [{ rig: 42 }, 'createFace: rig must be a URL or a rig object, got 42'],
      [{ model: {} }, 'createFace: model must be a URL, got an object'],
      [{ assetBase: '' }, 'createFace: assetBase must be a URL, got ""'],
      [{ onResolution: 'reload' }, 'createFace: onResolution must be a function, got "reload"'],
      [{ workers: 3 }, 'createFace: workers must be 1, 2 or "auto", got 3'],
      [{ light: { keyAzimuth: 400 } }, 'createFace: light: keyAzimuth must be within 0..360, got 400'],
      [{ expression: 'AU12=much' }, 'createFace: expression: AU12 needs a finite number, got "much"'],
      [{ expression: { AU12: '0.5' } }, 'createFace: expression: AU12 needs a finite number, got "0.5"'],
      [
        { resolutoin: 'low' },
        'createFace: unknown option "resolutoin" (options: resolution, rig, model, solver, workers, panels, ' +
          'expression, eyeSimulation, light, appearance, background, motionResolution, slowDrawMs, assetBase, onResolution, autosave)',
      ],
      [{ autosave: 1 }, 'createFace: autosave must be true, false or a key, got 1'],
      [{ appearance: { browDensity: 2 } }, 'createFace: appearance: browDensity must be within 0..1, got 2'],
      [{ appearance: { browColor: 'brown' } }, 'createFace: appearance: browColor needs a colour "#rrggbb", got "brown"'],
      [{ appearance: { beard: true } }, 'createFace: appearance: unknown option "beard"'],
      [{ motionResolution: 0.1 }, 'createFace: motionResolution must be a number within 0.25..1, got 0.1'],
      [{ motionResolution: Number.NaN }, 'createFace: motionResolution must be a number within 0.25..1, got NaN'],
      [{ motionResolution: '0.5' }, 'createFace: motionResolution must be a number within 0.25..1, got "0.5"'],
      [{ slowDrawMs: -1 }, 'createFace: slowDrawMs must be a finite number of ms, at least 0, got -1'],
      [{ slowDrawMs: Number.POSITIVE_INFINITY }, 'createFace: slowDrawMs must be a finite number of ms, at least 0, got Infinity'],
      [{ autosave: ' ' }, 'createFace: autosave must be true, false or a key, got " "'],
    ];
    for (const [options, message] of cases) expect(() => checkFaceOptions(options), JSON.stringify(options)).toThrow(message);
    expect(() => checkFaceOptions('low')).toThrow('createFace: needs an object of options, got "low"');
  });
});
