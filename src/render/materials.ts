import {
  Color,
  CustomBlending,
  DataTexture,
  DoubleSide,
  LinearFilter,
  LinearMipmapLinearFilter,
  MeshPhysicalMaterial,
  NoColorSpace,
  OneFactor,
  OneMinusSrcAlphaFactor,
  RepeatWrapping,
  ClampToEdgeWrapping,
  RGBAFormat,
  SRGBColorSpace,
  ShaderChunk,
  UnsignedByteType,
  Vector2,
  Vector3,
  type Material,
  type Texture,
  type WebGLProgramParametersWithUniforms,
} from 'three';
import { generateIrisImage, generateScleraImage, type EyeImage, type IrisOptions } from './eye-textures';
import { generatePoreMap, type PoreMap } from './pore-map';

/** A light-scattering look for a dielectric: wrapped, per-channel diffuse lighting. */
export interface SubsurfaceOptions {
  /**
   * How far past the terminator diffuse light wraps, per channel (linear RGB, 0..1). Red wraps furthest, as red light
   * travels furthest under skin, so the terminator turns warm instead of going grey.
   */
  wrap: readonly [number, number, number];
  /**
   * How much the diffuse light ignores the normal map, per channel (0: uses it, 1: uses the smooth surface normal):
   * light scattered under the skin blurs fine detail, more for red. Wrinkles are in the mesh, so they stay sharp.
   */
  normalBlur: readonly [number, number, number];
  /** How much pores and furrows darken the diffuse colour (from the normal map's alpha), 0..1. */
  cavity: number;
}

/** Options of the skin material; colours are linear RGB. */
export interface SkinLookOptions extends SubsurfaceOptions {
  color: readonly [number, number, number];
  roughness: number;
  /** Index of refraction of the surface layer (sets the specular reflectance at normal incidence). */
  ior: number;
  /** Sheen (the vellus hair and the oily film catch grazing light). */
  sheen: number;
  sheenRoughness: number;
  sheenColor: readonly [number, number, number];
  /** Seed of the pore map. */
  poreSeed: number;
  /** Pore tiles across the head's uv square (the head's uvs span about 1 m, so 8 gives tiles of about 12 cm). */
  poreRepeat: number;
  /** Strength of the pore normal map (three.js normalScale). */
  poreStrength: number;
}

const SKIN_LOOK_DEFAULTS: Readonly<Required<SkinLookOptions>> = Object.freeze({
  color: [0.6, 0.35, 0.26] as const,
  roughness: 0.45,
  ior: 1.4,
  sheen: 0.4,
  sheenRoughness: 0.6,
  sheenColor: [0.8, 0.58, 0.5] as const,
  wrap: [0.5, 0.22, 0.16] as const,
  normalBlur: [0.8, 0.5, 0.35] as const,
  cavity: 0.12,
  poreSeed: 1,
  poreRepeat: 8,
  poreStrength: 0.5,
});

/** The materials of a head, made together so that they share one pore texture. */
export interface HeadMaterials {
  skin: MeshPhysicalMaterial;
  sclera: MeshPhysicalMaterial;
  iris: MeshPhysicalMaterial;
  cornea: MeshPhysicalMaterial;
  teeth: MeshPhysicalMaterial;
  gums: MeshPhysicalMaterial;
  tongue: MeshPhysicalMaterial;
}

/** Makes the head's materials; the procedural textures are generated here, once. */
export function createHeadMaterials(skin: Partial<SkinLookOptions> = {}, iris: Partial<IrisOptions> = {}): HeadMaterials {
  const s: Required<SkinLookOptions> = { ...SKIN_LOOK_DEFAULTS, ...skin };
  const pores = poreTexture(poreMapOf(s.poreSeed), s.poreRepeat);
  pores.userData.seed = s.poreSeed;
  return {
    skin: createSkinMaterial(s, pores),
    sclera: createScleraMaterial(),
    iris: createIrisMaterial(iris),
    cornea: createCorneaMaterial(),
    teeth: createTeethMaterial(),
    gums: createGumsMaterial(),
    tongue: createTongueMaterial(pores),
  };
}

/** Skin: a physically based dielectric with sheen, pores in its normal map and a subsurface (wrap) diffuse term. */
function createSkinMaterial(options: Partial<SkinLookOptions> = {}, pores?: Texture): MeshPhysicalMaterial {
  const s: Required<SkinLookOptions> = { ...SKIN_LOOK_DEFAULTS, ...options };
  const normalMap = pores ?? poreTexture(poreMapOf(s.poreSeed), s.poreRepeat);
  const material = new MeshPhysicalMaterial({
    name: 'skin',
    color: new Color(...s.color),
    roughness: s.roughness,
    metalness: 0,
    ior: s.ior,
    sheen: s.sheen,
    sheenRoughness: s.sheenRoughness,
    sheenColor: new Color(...s.sheenColor),
    normalMap,
    normalScale: new Vector2(s.poreStrength, s.poreStrength),
  });
  return addSubsurface(material, s);
}

/** Sclera: slightly off-white and wet (glossy), with faint veins. */
function createScleraMaterial(): MeshPhysicalMaterial {
  const material = new MeshPhysicalMaterial({ name: 'sclera', map: colourTexture(generateScleraImage()), roughness: 0.22, ior: 1.38 });
  return addSubsurface(material, { wrap: [0.3, 0.2, 0.18], normalBlur: [0, 0, 0], cavity: 0 });
}

/** Iris: radial fibres, collarette, dark limbal ring and pupil, seen through the cornea. */
function createIrisMaterial(options: Partial<IrisOptions> = {}): MeshPhysicalMaterial {
  return new MeshPhysicalMaterial({ name: 'iris', map: colourTexture(generateIrisImage(options)), roughness: 0.6 });
}

/**
 * Cornea: clear and glossy. It adds only its reflection (blend one, one minus alpha, with no diffuse colour), so it
 * shows strong highlights and a reflection of the room over the iris without dimming it, and needs no transmission pass.
 */
function createCorneaMaterial(): MeshPhysicalMaterial {
  return new MeshPhysicalMaterial({
    name: 'cornea',
    color: 0x000000,
    roughness: 0.04,
    metalness: 0,
    ior: 1.376,
    specularIntensity: 1,
    clearcoat: 1,
    clearcoatRoughness: 0.02,
    envMapIntensity: 3,
    transparent: true,
    opacity: 0.04,
    depthWrite: false,
    blending: CustomBlending,
    blendSrc: OneFactor,
    blendDst: OneMinusSrcAlphaFactor,
  });
}

/** Teeth: off-white enamel, glossy, with light wrapping round their edges as through translucent enamel. */
function createTeethMaterial(): MeshPhysicalMaterial {
  const material = new MeshPhysicalMaterial({
    name: 'teeth',
    color: new Color(0.8, 0.75, 0.63),
    roughness: 0.3,
    ior: 1.55,
    side: DoubleSide,
  });
  return addSubsurface(material, { wrap: [0.45, 0.4, 0.3], normalBlur: [0, 0, 0], cavity: 0 });
}

/** Gums: pale coral pink, moist, with a reddish subsurface wrap like the lips'. */
function createGumsMaterial(): MeshPhysicalMaterial {
  const material = new MeshPhysicalMaterial({
    name: 'gums',
    color: new Color(0.62, 0.22, 0.22),
    roughness: 0.38,
    sheen: 0.3,
    sheenColor: new Color(0.9, 0.55, 0.55),
    side: DoubleSide,
  });
  return addSubsurface(material, { wrap: [0.5, 0.22, 0.2], normalBlur: [0, 0, 0], cavity: 0 });
}

/** Tongue: pinkish red, moist but rough (papillae, from the pore map at a finer scale), with a soft sheen. */
function createTongueMaterial(pores: Texture): MeshPhysicalMaterial {
  const papillae = pores.clone(); // shares the image and its GPU upload; only the repeat differs
  papillae.repeat.set(24, 24);
  const material = new MeshPhysicalMaterial({
    name: 'tongue',
    color: new Color(0.5, 0.12, 0.12),
    roughness: 0.55,
    sheen: 0.5,
    sheenRoughness: 0.4,
    sheenColor: new Color(0.8, 0.45, 0.45),
    normalMap: papillae,
    normalScale: new Vector2(0.8, 0.8),
  });
  return addSubsurface(material, { wrap: [0.55, 0.25, 0.2], normalBlur: [0.6, 0.3, 0.2], cavity: 0.2 });
}

/** The pore map made last, kept for the next head (another person, a second face on the page): read only. */
let lastPoreMap: { seed: number; map: PoreMap } | null = null;

/** The pore map of `seed`: the one made last if it has that seed (a map takes about 100 ms to make). */
function poreMapOf(seed: number): PoreMap {
  if (lastPoreMap?.seed !== seed) lastPoreMap = { seed, map: generatePoreMap({ seed }) };
  return lastPoreMap.map;
}

/** The normal map of pores, tiling. */
function poreTexture(map: PoreMap, repeat: number): DataTexture {
  const t = new DataTexture(map.data, map.width, map.height, RGBAFormat, UnsignedByteType);
  t.name = 'pores';
  t.wrapS = t.wrapT = RepeatWrapping;
  t.repeat.set(repeat, repeat);
  t.magFilter = LinearFilter;
  t.minFilter = LinearMipmapLinearFilter;
  // Mipmaps average the pores away with distance: at the default framing they only soften the highlights.
  t.generateMipmaps = true;
  t.colorSpace = NoColorSpace;
  t.needsUpdate = true;
  return t;
}

/** An eye texture: u goes round the eye (wraps), v does not. */
function colourTexture(image: EyeImage): DataTexture {
  const t = new DataTexture(image.data, image.width, image.height, RGBAFormat, UnsignedByteType);
  t.wrapS = RepeatWrapping;
  t.wrapT = ClampToEdgeWrapping;
  t.magFilter = LinearFilter;
  t.minFilter = LinearMipmapLinearFilter;
  t.generateMipmaps = true;
  t.colorSpace = SRGBColorSpace;
  t.needsUpdate = true;
  return t;
}

// The subsurface look replaces the direct diffuse term of three.js's physical lighting: these are the exact lines it
// edits (three r187); a three.js whose shader differs makes the first compile throw, instead of silently losing it.
const DIRECT_IRRADIANCE = 'vec3 irradiance = dotNL * directLight.color;';
const SHEEN_COMPENSATION = 'irradiance *= sheenEnergyComp;';
const DIRECT_DIFFUSE = 'reflectedLight.directDiffuse += irradiance * diffuseBRDF * ( 1.0 - F );';

/** The physical lighting chunk with the wrapped, per-channel diffuse term. */
const SUBSURFACE_LIGHTS = (() => {
  let chunk = ShaderChunk.lights_physical_pars_fragment;
  for (const line of [DIRECT_IRRADIANCE, SHEEN_COMPENSATION, DIRECT_DIFFUSE]) if (!chunk.includes(line)) return undefined;
  chunk = chunk
    .replace(
      DIRECT_IRRADIANCE,
      `${DIRECT_IRRADIANCE}
	// Subsurface look: diffuse light wraps past the terminator, red furthest, and uses a normal blurred toward the smooth one.
	vec3 sfNL = mix( vec3( dot( geometryNormal, directLight.direction ) ),
		vec3( dot( sfSmoothNormal, directLight.direction ) ), sfNormalBlur );
	vec3 sfDiffuseIrradiance = saturate( ( sfNL + sfWrap ) / ( 1.0 + sfWrap ) ) * directLight.color;`,
    )
    .replace(SHEEN_COMPENSATION, `${SHEEN_COMPENSATION} sfDiffuseIrradiance *= sheenEnergyComp;`)
    .replace(DIRECT_DIFFUSE, 'reflectedLight.directDiffuse += sfDiffuseIrradiance * diffuseBRDF * ( 1.0 - F );');
  const uniforms = 'uniform vec3 sfWrap;\nuniform vec3 sfNormalBlur;\nuniform float sfCavity;\nuniform float sfShade;\n';
  return `${uniforms}vec3 sfSmoothNormal;\n${chunk}`;
})();

/** Gives a physical material the subsurface look (wrap lighting, blurred diffuse normal, cavity darkening). */
function addSubsurface<M extends MeshPhysicalMaterial>(material: M, options: SubsurfaceOptions): M {
  const uniforms = {
    sfWrap: { value: new Vector3(...options.wrap) },
    sfNormalBlur: { value: new Vector3(...options.normalBlur) },
    sfCavity: { value: options.cavity },
    // The light that reaches the part at all, 0..1: 1 but for the teeth and gums behind lips all but closed (MouthShade).
    sfShade: { value: 1 },
  };
  material.userData.subsurface = { wrap: [...options.wrap], normalBlur: [...options.normalBlur], cavity: options.cavity };
  material.userData.shade = uniforms.sfShade;
  material.onBeforeCompile = (shader: WebGLProgramParametersWithUniforms) => {
    if (!SUBSURFACE_LIGHTS) throw new Error('the subsurface look does not fit this three.js: its physical lighting chunk changed');
    Object.assign(shader.uniforms, uniforms);
    shader.fragmentShader = shader.fragmentShader
      .replace('#include <lights_physical_pars_fragment>', SUBSURFACE_LIGHTS)
      .replace(
        '#include <normal_fragment_maps>',
        `#include <normal_fragment_maps>
	sfSmoothNormal = nonPerturbedNormal;
	#ifdef USE_NORMALMAP_TANGENTSPACE
		diffuseColor.rgb *= mix( 1.0, texture2D( normalMap, vNormalMapUv ).a, sfCavity );
	#endif`,
      )
      .replace('#include <opaque_fragment>', 'outgoingLight *= sfShade;\n#include <opaque_fragment>');
  };
  // One program for every material with the look (their uniforms differ, their code does not).
  material.customProgramCacheKey = () => 'softface-subsurface';
  return material;
}

/** What a material is, as plain data (for tests and debugging). */
export interface MaterialDescription {
  /** The material's name, e.g. `skin`, `sclera`, `iris`, `cornea`, `teeth`, `gums` or `tongue`. */
  name: string;
  /** The three.js material class, e.g. `MeshPhysicalMaterial`. */
  type: string;
  /** Whether it draws only its triangles' edges (the `wireframe` render option). */
  wireframe: boolean;
  /** Base colour, sRGB `#rrggbb`. */
  color: string;
  /** Surface roughness, 0 (mirror-like) to 1 (matte); 1 for a material that has none. */
  roughness: number;
  /** Whether it is blended over what lies behind it (as the cornea is), rather than drawn opaque. */
  transparent: boolean;
  /** Strength of the sheen layer that catches grazing light (fine hair, an oily film), 0..1; 0 without one. */
  sheen: number;
  /** Strength of the clear coat, a glossy film over the surface (the cornea's), 0..1; 0 without one. */
  clearcoat: number;
  /** The colour texture's size, if any. */
  map: {
    /** Width of the colour texture, in texels. */
    width: number;
    /** Height of the colour texture, in texels. */
    height: number;
  } | null;
  /** The normal map: size, tiling, strength and what its texels hold (normal components -1..1). */
  normalMap: {
    /** Width of the normal map, in texels. */
    width: number;
    /** Height of the normal map, in texels. */
    height: number;
    /** How many times the map tiles across the mesh's uv square, along u and v. */
    repeat: [number, number];
    /** Strength of the map's bumps along u and v (three.js `normalScale`): 0 flat, 1 as the texels say. */
    normalScale: [number, number];
    /** Seed of the procedural pore map it was generated from, or null for a map that is not one. */
    seed: number | null;
    /** Mean normal of the texels. */
    mean: [number, number, number];
    /** Fraction of texels whose normal leans more than 10 degrees from flat. */
    detail: number;
  } | null;
  /**
   * The light-scattering look (diffuse light wrapped past the terminator per channel) of skin, sclera, teeth, gums and
   * tongue; null for a material without one.
   */
  subsurface: SubsurfaceOptions | null;
}

/** Describes a material as plain data. */
export function describeMaterial(m: Material): MaterialDescription {
  const p = m as Partial<MeshPhysicalMaterial>;
  const image = (t: Texture | null | undefined): { width: number; height: number; data?: ArrayLike<number> } | null =>
    t ? (t.image as { width: number; height: number; data?: ArrayLike<number> }) : null;
  const mapImage = image(p.map);
  const normalImage = image(p.normalMap);
  let normalMap: MaterialDescription['normalMap'] = null;
  if (p.normalMap && normalImage) {
    const data = normalImage.data ?? [];
    const mean: [number, number, number] = [0, 0, 0];
    let leaning = 0;
    const count = data.length / 4;
    const cos10 = Math.cos((10 * Math.PI) / 180);
    for (let i = 0; i < data.length; i += 4) {
      const n = [0, 1, 2].map((k) => data[i + k] / 127.5 - 1);
      for (let k = 0; k < 3; k++) mean[k] += n[k] / count;
      if (n[2] / Math.hypot(n[0], n[1], n[2]) < cos10) leaning++;
    }
    normalMap = {
      width: normalImage.width,
      height: normalImage.height,
      repeat: [p.normalMap.repeat.x, p.normalMap.repeat.y],
      normalScale: [p.normalScale?.x ?? 1, p.normalScale?.y ?? 1],
      seed: typeof p.normalMap.userData.seed === 'number' ? p.normalMap.userData.seed : null,
      mean,
      detail: count ? leaning / count : 0,
    };
  }
  return {
    name: m.name,
    type: m.type,
    wireframe: 'wireframe' in m && m.wireframe === true,
    color: p.color ? `#${p.color.getHexString()}` : '',
    roughness: p.roughness ?? 1,
    transparent: m.transparent,
    sheen: p.sheen ?? 0,
    clearcoat: p.clearcoat ?? 0,
    map: mapImage ? { width: mapImage.width, height: mapImage.height } : null,
    normalMap,
    subsurface: (m.userData.subsurface as SubsurfaceOptions | undefined) ?? null,
  };
}
