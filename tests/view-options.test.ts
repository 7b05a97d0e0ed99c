import { describe, expect, it } from 'vitest';
import {
  LIGHT_DEFAULTS,
  LIGHT_RANGES,
  RENDER_DEFAULTS,
  checkOptions,
  type LightOptions,
  type RenderOptions,
} from '../src/render/view-options';

const light = (partial: unknown): Partial<LightOptions> => checkOptions<LightOptions>('setLight', partial, LIGHT_DEFAULTS, LIGHT_RANGES);
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

  it('name the method and the bad key or value', () => {
    expect(() => light({ keyAzimuth: -1 })).toThrow('setLight: keyAzimuth must be within 0..360, got -1');
    expect(() => light({ keyIntensity: Number.POSITIVE_INFINITY })).toThrow('setLight: keyIntensity needs a finite number, got Infinity');
    expect(() => light({ colour: '#ffffff' })).toThrow('setLight: unknown option "colour"');
    expect(() => light({ keyColor: '#fff' })).toThrow('setLight: keyColor needs a colour "#rrggbb", got "#fff"');
    expect(() => light({ keyColor: 0xffffff })).toThrow('setLight: keyColor needs a string, got 16777215');
    expect(() => light([1])).toThrow('setLight: needs an object of options');
    expect(() => render({ showEyes: 'yes' })).toThrow('setRenderOptions: showEyes needs a boolean, got "yes"');
    expect(() => render(undefined)).toThrow('setRenderOptions: needs an object of options, got undefined');
  });

  it('defaults sit inside their ranges', () => {
    for (const [key, [min, max]] of Object.entries(LIGHT_RANGES)) {
      const value = LIGHT_DEFAULTS[key as keyof typeof LIGHT_RANGES];
      expect(value).toBeGreaterThanOrEqual(min);
      expect(value).toBeLessThanOrEqual(max);
    }
  });
});
