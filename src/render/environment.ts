import {
  CompressedCubeTexture,
  HalfFloatType,
  LinearFilter,
  LinearMipmapLinearFilter,
  LinearSRGBColorSpace,
  RGBAFormat,
  type CompressedPixelFormat,
  type CompressedTextureMipmap,
} from 'three';
import { decodeEnvironment, type EnvironmentLevels } from '../core/baked-environment';

/**
 * Loads the baked lighting environment (written by `npm run build:environment`): the same prefiltered cube map the
 * view would otherwise make with PMREMGenerator at start-up, which without a GPU costs seconds of every page load.
 * Resolves to null, with a warning, when it cannot be had (a host that does not serve it, a browser without
 * DecompressionStream): the view then makes the environment itself.
 */
export async function loadEnvironment(url: string): Promise<CompressedCubeTexture | null> {
  try {
    if (typeof DecompressionStream === 'undefined') return null;
    const response = await fetch(url);
    if (!response.ok || !response.body) throw new Error(`HTTP ${response.status}`);
    const bytes = new Uint8Array(await new Response(response.body.pipeThrough(new DecompressionStream('gzip'))).arrayBuffer());
    return environmentTexture(decodeEnvironment(bytes));
  } catch (error) {
    console.warn(
      `the lighting environment ${url} could not be loaded (${(error as Error).message}); ` +
        `making it instead, which takes seconds without a GPU`,
    );
    return null;
  }
}

/**
 * A cube texture three.js takes as a finished PMREM. The file holds the faces as PMREMGenerator's render target has
 * them; three.js looks a cube texture that is not a render target up mirrored in x (the convention of cube maps made
 * from images), so the faces are mirrored here to match: +x and -x swap, and every face flips left to right.
 */
function environmentTexture(environment: EnvironmentLevels): CompressedCubeTexture {
  const { size, levels, faces } = environment;
  const images: { width: number; height: number; mipmaps: CompressedTextureMipmap[] }[] = [];
  // Each face turned in place (the decoded arrays are this function's alone): no second copy of a few megabytes.
  for (let l = 0; l < levels; l++) for (let f = 0; f < 6; f++) mirrorRows(faces[l][f], size >> l);
  for (let f = 0; f < 6; f++) {
    const source = f === 0 ? 1 : f === 1 ? 0 : f;
    const mipmaps: CompressedTextureMipmap[] = [];
    for (let l = 0; l < levels; l++) mipmaps.push({ data: faces[l][source], width: size >> l, height: size >> l });
    images.push({ width: size, height: size, mipmaps });
  }
  // Uncompressed RGBA levels go up through the compressed cube path's plain-data branch, each level as given.
  const texture = new CompressedCubeTexture(images, RGBAFormat as unknown as CompressedPixelFormat, HalfFloatType);
  texture.minFilter = LinearMipmapLinearFilter;
  texture.magFilter = LinearFilter;
  texture.generateMipmaps = false;
  texture.colorSpace = LinearSRGBColorSpace;
  texture.isPMREMTexture = true;
  texture.name = 'PMREM';
  texture.needsUpdate = true;
  return texture;
}

/** Flips each row of an RGBA image `s` texels wide left to right, in place. */
function mirrorRows(data: Uint16Array, s: number): void {
  for (let y = 0; y < s; y++) {
    for (let a = 4 * y * s, b = 4 * (y * s + s - 1); a < b; a += 4, b -= 4) {
      for (let c = 0; c < 4; c++) {
        const t = data[a + c];
        data[a + c] = data[b + c];
        data[b + c] = t;
      }
    }
  }
}
