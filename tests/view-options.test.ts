import { describe, expect, it } from 'vitest';
import { checkOptions } from '../src/core/check';
import { LIGHT_DEFAULTS, LIGHT_RANGES, RENDER_DEFAULTS, type LightOptions, type RenderOptions } from '../src/render/view-options';

const light = (partial: unknown): Partial<LightOptions> =>
  checkOptions<LightOptions>('setLight', partial, LIGHT_DEFAULTS, { ranges: LIGHT_RANGES });
const render = (partial: unknown): Partial<RenderOptions> => checkOptions<RenderOptions>('setRenderOptions', partial, RENDER_DEFAULTS);

describe('light and render option checks', () => {
  it('accept known options of the right type within range', () => {
    expect(light({ keyAzimuth: 360, keyElevation: -90, keyColor: '#A0b0c0', ambientIntensity: 0 })).toEqual({
      keyAzimuth: 360,
      keyElevation: -90,
      keyColor: '#A0b0c0',
      ambientIntensity: 0,
    });
    expect(render({ wireframe: true })).toEqual({ wireframe: true });
    expect(light({})).toEqual({});
  });

  it('name the method and the bad key or value as "<what>: <path>: expected ..., got ..."', () => {
    expect(() => light({ keyAzimuth: -1 })).toThrow('setLight: keyAzimuth: expected a number from 0 to 360, got -1');
    expect(() => light({ keyIntensity: Number.POSITIVE_INFINITY })).toThrow(
      'setLight: keyIntensity: expected a number from 0 to 10, got Infinity',
    );
    expect(() => light({ colour: '#ffffff' })).toThrow(
      'setLight: expected one of the options ambientIntensity, keyAzimuth, keyElevation, keyIntensity, keyColor, got "colour"',
    );
    expect(() => light({ keyColor: '#fff' })).toThrow('setLight: keyColor: expected a colour "#rrggbb", got "#fff"');
    expect(() => light({ keyColor: 0xffffff })).toThrow('setLight: keyColor: expected a colour "#rrggbb", got 16777215');
    expect(() => light([1])).toThrow('setLight: expected an object of options, got an array of 1 item');
    expect(() => render({ showEyes: 'yes' })).toThrow('setRenderOptions: showEyes: expected true or false, got "yes"');
    expect(() => render(undefined)).toThrow('setRenderOptions: expected an object of options, got nothing');
  });

  it('defaults sit inside their ranges', () => {
    for (const [key, [min, max]] of Object.entries(LIGHT_RANGES)) {
      const value = LIGHT_DEFAULTS[key as keyof typeof LIGHT_RANGES];
      expect(value).toBeGreaterThanOrEqual(min);
      expect(value).toBeLessThanOrEqual(max);
    }
  });
});
