import { readFileSync } from 'node:fs';
import { gunzipSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import { decodeEnvironment, encodeEnvironment, type EnvironmentLevels } from '../src/core/baked-environment';
import { mulberry32 } from '../src/core/random';

/** A seeded cube of random positive, finite half floats (alpha 1), the hardest case for the predictor. */
function randomEnvironment(size: number, levels: number, seed: number): EnvironmentLevels {
  const random = mulberry32(seed);
  const faces: Uint16Array[][] = [];
  for (let l = 0; l < levels; l++) {
    const level: Uint16Array[] = [];
    for (let f = 0; f < 6; f++) {
      const face = new Uint16Array(4 * (size >> l) ** 2);
      for (let i = 0; i < face.length; i++) face[i] = i % 4 === 3 ? 0x3c00 : Math.floor(random() * 0x7bff);
      level.push(face);
    }
    faces.push(level);
  }
  return { size, levels, faces };
}

describe('baked environment', () => {
  it('decodes exactly what it encoded, every texel of every face and level', () => {
    const environment = randomEnvironment(16, 3, 7);
    const back = decodeEnvironment(encodeEnvironment(environment));
    expect(back.size).toBe(16);
    expect(back.levels).toBe(3);
    for (let l = 0; l < 3; l++) for (let f = 0; f < 6; f++) expect(back.faces[l][f]).toEqual(environment.faces[l][f]);
  });

  it('refuses bytes that are not a baked environment, saying why', () => {
    const bytes = encodeEnvironment(randomEnvironment(8, 2, 3));
    expect(() => decodeEnvironment(bytes.subarray(0, 10))).toThrow(/16-byte header; this file has 10 bytes/);
    expect(() => decodeEnvironment(new TextEncoder().encode('<!doctype html><html></html>'))).toThrow(/not a baked environment/);
    expect(() => decodeEnvironment(bytes.subarray(0, bytes.length - 2))).toThrow(/header asks for/);
    const wrongVersion = bytes.slice();
    wrongVersion[4] = 9;
    expect(() => decodeEnvironment(wrongVersion)).toThrow(/version 9/);
  });

  it('the committed room environment is a 256-pixel cube with its six prefiltered levels of finite light', () => {
    const room = decodeEnvironment(new Uint8Array(gunzipSync(readFileSync(new URL('../public/environment/room.pmrem', import.meta.url)))));
    expect(room.size).toBe(256);
    expect(room.levels).toBe(6);
    // The roughest level is the room's diffuse light: every face lit, none black, none infinite or NaN.
    for (const face of room.faces[5]) {
      let brightest = 0;
      for (let i = 0; i < face.length; i++) {
        if (i % 4 === 3) continue;
        expect((face[i] & 0x7c00) !== 0x7c00 && face[i] < 0x8000).toBe(true); // finite and not negative
        brightest = Math.max(brightest, face[i]);
      }
      expect(brightest).toBeGreaterThan(0x3000); // above 0.125
    }
  });

  it('writes the committed room environment again byte for byte from what it reads (the format has not moved)', () => {
    const bytes = new Uint8Array(gunzipSync(readFileSync(new URL('../public/environment/room.pmrem', import.meta.url))));
    expect(Buffer.from(encodeEnvironment(decodeEnvironment(bytes))).equals(Buffer.from(bytes))).toBe(true);
  });
});
