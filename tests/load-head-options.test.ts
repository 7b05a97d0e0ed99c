import { describe, expect, it } from 'vitest';
import { checkLoadHeadOptions, LOAD_HEAD_DEFAULTS, MAX_HEAD_FILE_BYTES, readHeadFiles } from '../src/face/head-loader';

describe('loadHead options', () => {
  it('fills in the defaults and keeps what is given', () => {
    expect(checkLoadHeadOptions(undefined)).toEqual(LOAD_HEAD_DEFAULTS);
    expect(checkLoadHeadOptions({ units: 'cm', up: '+z', landmarks: { chin: [0, 0.6, 0.15] } })).toEqual({
      ...LOAD_HEAD_DEFAULTS,
      units: 'cm',
      up: '+z',
      landmarks: { chin: [0, 0.6, 0.15] },
    });
  });

  it('refuses a bad option, naming it and what it takes', () => {
    expect(() => checkLoadHeadOptions({ units: 'inch' })).toThrow('loadHead: units: expected one of auto, m, dm, cm, mm, got "inch"');
    expect(() => checkLoadHeadOptions({ up: 'y' })).toThrow('loadHead: up: expected one of auto, +x, -x, +y, -y, +z, -z, got "y"');
    expect(() => checkLoadHeadOptions({ resolution: 'ultra' })).toThrow(
      'loadHead: resolution: expected one of low, medium, high, file, got "ultra"',
    );
    expect(() => checkLoadHeadOptions({ landmarks: { nose: [0, 0, 0] } })).toThrow(
      /^loadHead: landmarks: expected one of the landmarks nose-tip, .*, got "nose"$/,
    );
    expect(() => checkLoadHeadOptions({ landmarks: { chin: [0, Number.NaN, 0] } })).toThrow(
      'loadHead: landmarks.chin: expected [x, y, z] in metres, got [0,NaN,0]',
    );
    expect(() => checkLoadHeadOptions({ scale: 2 })).toThrow(
      'loadHead: expected one of the options skin, units, up, forward, landmarks, resolution, got "scale"',
    );
  });

  it('refuses a file over the size limit before reading it', async () => {
    const big = new File([new Uint8Array(MAX_HEAD_FILE_BYTES + 1)], 'huge.glb');
    await expect(readHeadFiles([big])).rejects.toThrow('huge.glb: the file is 67.1 MB, more than the 64 MB a head may be');
  });
});
