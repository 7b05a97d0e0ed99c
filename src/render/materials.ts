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
  // The teeth, gums and tongue are lit through one opening of the lips.
  const mouth = createMouthOpeningUniforms(true);
  return {
    skin: createSkinMaterial(s, pores),
    sclera: createScleraMaterial(),
    iris: createIrisMaterial(iris),
    cornea: createCorneaMaterial(),
    teeth: createTeethMaterial(mouth),
    gums: createGumsMaterial(mouth),
    tongue: createTongueMaterial(pores, mouth),
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
function createTeethMaterial(mouth: MouthOpeningUniforms): MeshPhysicalMaterial {
  const material = new MeshPhysicalMaterial({
    name: 'teeth',
    color: new Color(0.8, 0.75, 0.63),
    roughness: 0.3,
    ior: 1.55,
    side: DoubleSide,
  });
  return addSubsurface(material, { wrap: [0.45, 0.4, 0.3], normalBlur: [0, 0, 0], cavity: 0 }, mouth);
}

/** Gums: pale coral pink, moist, with a reddish subsurface wrap like the lips'. */
function createGumsMaterial(mouth: MouthOpeningUniforms): MeshPhysicalMaterial {
  const material = new MeshPhysicalMaterial({
    name: 'gums',
    color: new Color(0.62, 0.22, 0.22),
    roughness: 0.38,
    sheen: 0.3,
    sheenColor: new Color(0.9, 0.55, 0.55),
    side: DoubleSide,
  });
  return addSubsurface(material, { wrap: [0.5, 0.22, 0.2], normalBlur: [0, 0, 0], cavity: 0 }, mouth);
}

/** Tongue: pinkish red, moist but rough (papillae, from the pore map at a finer scale), with a soft sheen. */
function createTongueMaterial(pores: Texture, mouth: MouthOpeningUniforms): MeshPhysicalMaterial {
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
  return addSubsurface(material, { wrap: [0.55, 0.25, 0.2], normalBlur: [0.6, 0.3, 0.2], cavity: 0.2 }, mouth);
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

/**
 * Of the light that comes through the lips' opening, the share a point inside the mouth gets again after it scattered
 * off the mouth's walls, for each unit of the opening's view factor: the key light lights what it cannot reach.
 */
const MOUTH_BOUNCE = 0.5;
/** The room's light left deep in a closed mouth (scattered through the lips and cheeks): little. */
const MOUTH_SCATTER = 0.1;
/** Light scattered inside the mouth comes off red walls (linear RGB): the teeth in shade turn warm, not grey. */
const MOUTH_TINT = [1, 0.55, 0.5] as const;

const SUBSURFACE_UNIFORMS = 'uniform vec3 sfWrap;\nuniform vec3 sfNormalBlur;\nuniform float sfCavity;\n';

/**
 * Light inside the mouth comes in through the lips' opening only (the opening as measured by MouthShade, world space;
 * `sfMouth` 1 for the teeth, gums and tongue, 0 for every other part). The same sums as core/head/mouth-opening.ts:
 * the view factor of the opening (room light, and light scattered inside the mouth) and whether a light's ray crosses
 * it (the key light). Without this the mouth's inside was lit as the face is, a pink, white-toothed cave.
 */
const MOUTH_OPENING_GLSL = `uniform float sfMouth;
uniform vec3 sfMouthCentre;
uniform vec3 sfMouthAcross;
uniform vec3 sfMouthUp;
uniform vec3 sfMouthOut;
uniform vec2 sfMouthHalf;
varying vec3 sfWorld;
float sfMouthView;
#define MOUTH_BOUNCE ( ${MOUTH_BOUNCE.toFixed(3)} * MOUTH_TINT )
#define MOUTH_SCATTER ( ${MOUTH_SCATTER.toFixed(3)} * MOUTH_TINT )
#define MOUTH_TINT vec3( ${MOUTH_TINT.map((c) => c.toFixed(3)).join(', ')} )
float sfCorner( vec2 e ) {
	vec2 s = sqrt( 1.0 + e * e );
	return e.x / s.x * atan( e.y / s.x ) + e.y / s.y * atan( e.x / s.y );
}
float sfOpeningView() {
	if ( sfMouth == 0.0 ) return 1.0;
	vec3 r = sfWorld - sfMouthCentre;
	float depth = max( - dot( r, sfMouthOut ), 2e-4 );
	vec2 foot = vec2( dot( r, sfMouthAcross ), dot( r, sfMouthUp ) );
	vec2 h = ${Math.sqrt(Math.PI) / 2} * sfMouthHalf;
	vec2 lo = ( - h - foot ) / depth;
	vec2 hi = ( h - foot ) / depth;
	float f = sfCorner( hi ) - sfCorner( vec2( lo.x, hi.y ) ) - sfCorner( vec2( hi.x, lo.y ) ) + sfCorner( lo );
	return clamp( f / ( 2.0 * PI ), 0.0, 1.0 );
}
float sfLightThrough( vec3 viewDirection ) {
	if ( sfMouth == 0.0 ) return 1.0;
	vec3 l = normalize( ( vec4( viewDirection, 0.0 ) * viewMatrix ).xyz );
	vec3 r = sfWorld - sfMouthCentre;
	float depth = max( - dot( r, sfMouthOut ), 2e-4 );
	float c = dot( l, sfMouthOut );
	if ( c < 0.05 ) return 0.0;
	vec3 hit = r + l * ( depth / c );
	vec2 q = vec2( dot( hit, sfMouthAcross ), dot( hit, sfMouthUp ) ) / max( sfMouthHalf, vec2( 1e-5 ) );
	return 1.0 - smoothstep( 0.8, 1.2, length( q ) );
}
`;

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
	vec3 sfDiffuseIrradiance = saturate( ( sfNL + sfWrap ) / ( 1.0 + sfWrap ) ) * directLight.color;
	// Inside the mouth: the light through the lips' opening, and what of it the mouth scatters (sfMouthView).
	float sfDirect = sfLightThrough( directLight.direction );
	vec3 sfThrough = sfDirect + MOUTH_BOUNCE * sfMouthView * ( 1.0 - sfDirect );
	irradiance *= sfThrough;
	sfDiffuseIrradiance *= sfThrough;`,
    )
    .replace(SHEEN_COMPENSATION, `${SHEEN_COMPENSATION} sfDiffuseIrradiance *= sheenEnergyComp;`)
    .replace(DIRECT_DIFFUSE, 'reflectedLight.directDiffuse += sfDiffuseIrradiance * diffuseBRDF * ( 1.0 - F );');
  return `${SUBSURFACE_UNIFORMS}${MOUTH_OPENING_GLSL}vec3 sfSmoothNormal;\n${chunk}`;
})();

/** The uniforms of the lips' opening that light the inside of the mouth (see MOUTH_OPENING_GLSL), world space. */
export interface MouthOpeningUniforms {
  /** 1 for a part inside the mouth, lit through the opening only; 0 for any other. */
  sfMouth: { value: number };
  sfMouthCentre: { value: Vector3 };
  sfMouthAcross: { value: Vector3 };
  sfMouthUp: { value: Vector3 };
  sfMouthOut: { value: Vector3 };
  /** Half width and half height of the opening, metres. */
  sfMouthHalf: { value: Vector2 };
}

/**
 * Uniforms of a mouth opening: wide open in front of the origin until MouthShade measures the lips (so a part that is
 * never measured, as in a picture without a skin, is lit as before).
 */
function createMouthOpeningUniforms(inside: boolean): MouthOpeningUniforms {
  return {
    sfMouth: { value: inside ? 1 : 0 },
    sfMouthCentre: { value: new Vector3(0, 0, 10) },
    sfMouthAcross: { value: new Vector3(1, 0, 0) },
    sfMouthUp: { value: new Vector3(0, 1, 0) },
    sfMouthOut: { value: new Vector3(0, 0, 1) },
    sfMouthHalf: { value: new Vector2(100, 100) },
  };
}

/**
 * Gives a physical material the subsurface look (wrap lighting, blurred diffuse normal, cavity darkening); `mouth`, for
 * the parts inside the mouth, is the opening they are lit through (shared by those parts, kept in `userData.mouth`).
 */
function addSubsurface<M extends MeshPhysicalMaterial>(material: M, options: SubsurfaceOptions, mouth?: MouthOpeningUniforms): M {
  const opening = mouth ?? createMouthOpeningUniforms(false);
  const uniforms = {
    sfWrap: { value: new Vector3(...options.wrap) },
    sfNormalBlur: { value: new Vector3(...options.normalBlur) },
    sfCavity: { value: options.cavity },
    ...opening,
  };
  material.userData.subsurface = { wrap: [...options.wrap], normalBlur: [...options.normalBlur], cavity: options.cavity };
  if (mouth) material.userData.mouth = mouth;
  material.onBeforeCompile = (shader: WebGLProgramParametersWithUniforms) => {
    if (!SUBSURFACE_LIGHTS) throw new Error('the subsurface look does not fit this three.js: its physical lighting chunk changed');
    Object.assign(shader.uniforms, uniforms);
    shader.vertexShader = `varying vec3 sfWorld;\n${shader.vertexShader}`.replace(
      '#include <project_vertex>',
      '#include <project_vertex>\n\tsfWorld = ( modelMatrix * vec4( transformed, 1.0 ) ).xyz;',
    );
    shader.fragmentShader = shader.fragmentShader
      .replace('#include <lights_physical_pars_fragment>', SUBSURFACE_LIGHTS)
      .replace(
        '#include <normal_fragment_maps>',
        `#include <normal_fragment_maps>
	sfSmoothNormal = nonPerturbedNormal;
	sfMouthView = sfOpeningView();
	#ifdef USE_NORMALMAP_TANGENTSPACE
		diffuseColor.rgb *= mix( 1.0, texture2D( normalMap, vNormalMapUv ).a, sfCavity );
	#endif`,
      )
      .replace(
        '#include <aomap_fragment>',
        `#include <aomap_fragment>
	vec3 sfRoomLight = mix( MOUTH_SCATTER, vec3( 1.0 ), sfMouthView );
	reflectedLight.indirectDiffuse *= sfRoomLight;
	reflectedLight.indirectSpecular *= sfRoomLight;`,
      );
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
