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
      antialias: 'still',
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
      antialias: 'still',
      eyeSimulation: false,
    });
  });

  it('reject a bad option with a message naming it and the value', () => {
    const cases: [object, string][] = [
      [{ resolution: 'ultra' }, 'createFace: resolution: expected one of low, medium, high, got "ultra"'],
      [{ solver: 'gpu' }, 'createFace: solver: expected one of auto, shared, transfer, main, got "gpu"'],
      [{ panels: 'yes' }, 'createFace: panels: expected true or false, got "yes"'],
      [{ eyeSimulation: 1 }, 'createFace: eyeSimulation: expected true or false, got 1'],
      [{ background: 'red' }, 'createFace: background: expected a colour "#rrggbb" or "transparent", got "red"'],
      [{ rig: 42 }, 'createFace: rig: expected a URL or a rig object, got 42'],
      [{ model: {} }, 'createFace: model: expected a URL, got an object'],
      [{ assetBase: '' }, 'createFace: assetBase: expected a URL, got ""'],
      [{ onResolution: 'reload' }, 'createFace: onResolution: expected a function, got "reload"'],
      [{ workers: 3 }, 'createFace: workers: expected 1, 2 or "auto", got 3'],
      [{ light: { keyAzimuth: 400 } }, 'createFace: light: keyAzimuth: expected a number from 0 to 360, got 400'],
      [{ expression: 'AU12=much' }, 'createFace: expression: AU12: expected a finite number, got "much"'],
      [{ expression: { AU12: '0.5' } }, 'createFace: expression: AU12: expected a finite number, got "0.5"'],
      [
        { facs: '6+12+99' },
        'createFace: facs: at 6 of "6+12+99": expected an Action Unit the face has ' +
          '(1, 2, 4, 5, 6, 7, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 20, 22, 23, 24, 25, 26, 27, 38, 39, 41, 42, 43, 44, 45, 46, ' +
          '51, 52, 53, 54, 55, 56, 57, 58, 61, 62, 63, 64, 65, 66), got "99"',
      ],
      [
        { resolutoin: 'low' },
        'createFace: expected one of the options resolution, rig, model, identity, solver, workers, panels, expression, facs, ' +
          'eyeSimulation, light, appearance, background, motionResolution, slowDrawMs, antialias, assetBase, onResolution, ' +
          'autosave, ' +
          'got "resolutoin"',
      ],
      [{ autosave: 1 }, 'createFace: autosave: expected true, false or a key, got 1'],
      [{ appearance: { browDensity: 2 } }, 'createFace: appearance: browDensity: expected a number from 0 to 1, got 2'],
      [{ appearance: { browColor: 'brown' } }, 'createFace: appearance: browColor: expected a colour "#rrggbb", got "brown"'],
      [
        { appearance: { beard: true } },
        'createFace: appearance: expected one of the options skinColor, brows, browColor, browDensity, lashes, lashColor, got "beard"',
      ],
      [{ motionResolution: 0.1 }, 'createFace: motionResolution: expected a number from 0.25 to 1, got 0.1'],
      [{ motionResolution: Number.NaN }, 'createFace: motionResolution: expected a number from 0.25 to 1, got NaN'],
      [{ motionResolution: '0.5' }, 'createFace: motionResolution: expected a number from 0.25 to 1, got "0.5"'],
      [{ slowDrawMs: -1 }, 'createFace: slowDrawMs: expected a finite number of ms, at least 0, got -1'],
      [{ slowDrawMs: Number.POSITIVE_INFINITY }, 'createFace: slowDrawMs: expected a finite number of ms, at least 0, got Infinity'],
      [{ antialias: true }, 'createFace: antialias: expected one of auto, always, still, got true'],
      [{ autosave: ' ' }, 'createFace: autosave: expected true, false or a key, got " "'],
    ];
    for (const [options, message] of cases) expect(() => checkFaceOptions(options), JSON.stringify(options)).toThrow(message);
    expect(() => checkFaceOptions('low')).toThrow('createFace: expected an object of options, got "low"');
  });
});
