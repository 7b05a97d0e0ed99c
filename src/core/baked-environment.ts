/**
 * The byte format of a baked lighting environment: a prefiltered cube map (the mip levels three.js's PMREMGenerator
 * makes) stored losslessly as half floats. Each face image's RGB is predicted from its left, upper and upper-left
 * neighbours (as PNG's gradient filter does; half-float bit patterns of positive values are ordered, so the residuals
 * stay small on smooth light), and the residuals' high and low bytes are stored as two planes, which gzip packs to
 * about a third of the raw size. Pure: no DOM, no three.
 */

/** 'PREM' as a little-endian u32: the first word of the file. */
const ENVIRONMENT_MAGIC = 0x4d455250;
const ENVIRONMENT_VERSION = 1;
/** Header words: magic, version, face size of level 0, mip levels. */
const HEADER_WORDS = 4;
/** Half-float 1, the alpha of every texel (the file stores RGB only). */
const HALF_ONE = 0x3c00;

/** A prefiltered cube map: `faces[level][face]` holds RGBA half floats, rows from t = 0, level sizes halving. */
export interface EnvironmentLevels {
  size: number;
  levels: number;
  faces: Uint16Array[][];
}

/** Texels in all faces of all levels. */
function texelCount(size: number, levels: number): number {
  let n = 0;
  for (let l = 0; l < levels; l++) n += 6 * (size >> l) * (size >> l);
  return n;
}

/**
 * The gradient predictor of value `i` of an RGBA face image whose rows are `row` values long, at texel (x, y): from
 * the same channel's left, upper and upper-left values.
 */
function predict(values: Uint16Array, i: number, x: number, y: number, row: number): number {
  if (x > 0 && y > 0) return values[i - 4] + values[i - row] - values[i - row - 4];
  return x > 0 ? values[i - 4] : y > 0 ? values[i - row] : 0;
}

/**
 * Decodes one RGBA face image of `s` x `s` texels in place, its residuals' high bytes from `bytes[high..]` and low
 * bytes from `bytes[low..]` (three a texel). A function per face, with the texel's three channels written out: one
 * walk of every level's faces in nested loops around a callback ran into a few thousand bailouts of V8's on-stack
 * replacement in the browser, a third of a second of a page's start.
 */
function decodeFace(face: Uint16Array, s: number, bytes: Uint8Array, high: number, low: number): void {
  const row = 4 * s;
  for (let y = 0, t = 0; y < s; y++) {
    for (let x = 0; x < s; x++, t++) {
      const i = 4 * t;
      const r = 3 * t;
      face[i] = (predict(face, i, x, y, row) + ((bytes[high + r] << 8) | bytes[low + r])) & 0xffff;
      face[i + 1] = (predict(face, i + 1, x, y, row) + ((bytes[high + r + 1] << 8) | bytes[low + r + 1])) & 0xffff;
      face[i + 2] = (predict(face, i + 2, x, y, row) + ((bytes[high + r + 2] << 8) | bytes[low + r + 2])) & 0xffff;
      face[i + 3] = HALF_ONE;
    }
  }
}

/** The file's bytes (before gzip) for `environment`; alpha is dropped (it is 1 everywhere in a PMREM). */
export function encodeEnvironment(environment: EnvironmentLevels): Uint8Array {
  const { size, levels, faces } = environment;
  const n = 3 * texelCount(size, levels);
  const out = new Uint8Array(4 * HEADER_WORDS + 2 * n);
  new Uint32Array(out.buffer, 0, HEADER_WORDS).set([ENVIRONMENT_MAGIC, ENVIRONMENT_VERSION, size, levels]);
  const planes = 4 * HEADER_WORDS;
  let o = 0;
  for (let l = 0; l < levels; l++) {
    const s = size >> l;
    const row = 4 * s;
    for (let f = 0; f < 6; f++) {
      const face = faces[l][f];
      if (face.length !== 4 * s * s) throw new Error(`environment level ${l} face ${f}: ${face.length} values, expected ${4 * s * s}`);
      for (let y = 0; y < s; y++) {
        for (let x = 0; x < s; x++) {
          for (let c = 0; c < 3; c++, o++) {
            const i = 4 * (y * s + x) + c;
            const residual = (face[i] - predict(face, i, x, y, row)) & 0xffff;
            out[planes + o] = residual >> 8;
            out[planes + n + o] = residual & 0xff;
          }
        }
      }
    }
  }
  return out;
}

/** Reads what encodeEnvironment wrote; throws naming the problem if the bytes are not such a file. */
export function decodeEnvironment(bytes: Uint8Array): EnvironmentLevels {
  if (bytes.length < 4 * HEADER_WORDS)
    throw new Error(`a baked environment has a ${4 * HEADER_WORDS}-byte header; this file has ${bytes.length} bytes`);
  const header = new DataView(bytes.buffer, bytes.byteOffset, 4 * HEADER_WORDS);
  const word = (k: number): number => header.getUint32(4 * k, true);
  if (word(0) !== ENVIRONMENT_MAGIC) throw new Error('not a baked environment (its first bytes are not "PREM")');
  if (word(1) !== ENVIRONMENT_VERSION)
    throw new Error(`baked environment version ${word(1)}; this build reads version ${ENVIRONMENT_VERSION}`);
  const size = word(2);
  const levels = word(3);
  if (!(size >= 1 && size <= 4096 && (size & (size - 1)) === 0 && levels >= 1 && size >> (levels - 1) >= 1)) {
    throw new Error(`baked environment with face size ${size} and ${levels} levels: not a power of two with that many halvings`);
  }
  const n = 3 * texelCount(size, levels);
  if (bytes.length !== 4 * HEADER_WORDS + 2 * n)
    throw new Error(`baked environment of ${bytes.length} bytes; its header asks for ${4 * HEADER_WORDS + 2 * n}`);
  const planes = 4 * HEADER_WORDS;
  const faces: Uint16Array[][] = [];
  let o = planes;
  for (let l = 0; l < levels; l++) {
    const s = size >> l;
    const level: Uint16Array[] = [];
    for (let f = 0; f < 6; f++) {
      const face = new Uint16Array(4 * s * s);
      decodeFace(face, s, bytes, o, o + n);
      o += 3 * s * s;
      level.push(face);
    }
    faces.push(level);
  }
  return { size, levels, faces };
}
