/**
 * How a person's skin, hair and eyes look, from their sex, age and ancestry. The skin's colour comes from a small
 * physical model of two pigments rather than one tint per ancestry: melanin in the epidermis filters the light twice
 * (in and out), and what reaches the dermis is scattered back with the blood's haemoglobin absorbing on the way. Pure
 * numbers, no three.js.
 *
 * Sources of the numbers:
 * - eumelanin absorption 6.6e11 λ^-3.33 cm^-1 (λ in nm), the bloodless dermis baseline 0.244 + 85.3 e^-(λ-154)/66.2
 *   cm^-1, and the reduced scattering 46 (λ/500)^-1.421 cm^-1: S. L. Jacques, "Optical properties of biological tissues:
 *   a review", Phys. Med. Biol. 58 (2013) R37, and his skin-optics note (omlc.org, 1998);
 * - haemoglobin's molar extinction at 450, 550 and 650 nm: S. Prahl's tabulation (omlc.org/spectra/hemoglobin), whole
 *   blood at 150 g/L, 75 % oxygen saturation;
 * - the dermis's diffuse reflectance: T. J. Farrell, M. S. Patterson, B. Wilson, "A diffusion theory model of spatially
 *   resolved, steady-state diffuse reflectance", Med. Phys. 19 (1992) 879 (total reflectance, A = 2.9 for n = 1.4);
 * - melanosome volume fractions: Jacques (1998): lightly pigmented adults 1.3-6.3 %, moderately 11-16 %, darkly 18-43 %.
 *   The fractions below put light European skin near ITA 45° (Chardon et al. 1991's "light"), East Asian near 35°
 *   ("intermediate") and African near -40° ("dark").
 */
import { mulberry32 } from '../random';
import type { Identity } from './identity';

/** Wavelengths standing for the red, green and blue channels, nm. */
const CHANNEL_NM = [650, 550, 450] as const;
/** Oxy- and deoxy-haemoglobin molar extinction, cm^-1/M (Prahl), at the channel wavelengths. */
const HAEMOGLOBIN: Readonly<Record<(typeof CHANNEL_NM)[number], readonly [number, number]>> = {
  650: [368, 3750.12],
  550: [43016, 53412],
  450: [62816, 103292],
};
const BLOOD_G_PER_L = 150;
const HAEMOGLOBIN_G_PER_MOL = 64500;
const OXYGEN_SATURATION = 0.75;
/** Effective path through the epidermis's melanin layer, cm (its 60-100 µm thickness, crossed at an angle). */
const EPIDERMIS_PATH_CM = 0.007;
/** Light the stratum corneum sends back before it meets any melanin. */
const SURFACE_REFLECTANCE = 0.04;

/** Melanosome volume fraction of the epidermis by ancestry (see the sources above). */
const MELANIN_BY_ANCESTRY = Object.freeze({ african: 0.35, asian: 0.045, european: 0.025 });
/** Blood volume fraction of the dermis: men's skin carries a little more (a higher erythema index). */
const BLOOD_FEMALE = 0.013;
const BLOOD_MALE = 0.017;

/** Diffuse reflectance of a semi-infinite scattering medium (Farrell et al. 1992, total reflectance, A = 2.9). */
function diffuseReflectance(absorption: number, scattering: number): number {
  const albedo = scattering / (absorption + scattering);
  const s = Math.sqrt(3 * (1 - albedo));
  return (albedo / 2) * (1 + Math.exp((-4 / 3) * 2.9 * s)) * Math.exp(-s);
}

/**
 * Skin albedo (linear RGB) for a melanosome volume fraction of the epidermis and a blood volume fraction of the
 * dermis: the surface's own reflectance, plus the dermis's diffuse reflectance seen through the melanin twice.
 */
export function skinAlbedo(melanin: number, blood: number): [number, number, number] {
  const out: [number, number, number] = [0, 0, 0];
  CHANNEL_NM.forEach((nm, c) => {
    const melaninAbsorption = 6.6e11 * nm ** -3.33;
    const [oxy, deoxy] = HAEMOGLOBIN[nm];
    const bloodAbsorption =
      Math.LN10 * (BLOOD_G_PER_L / HAEMOGLOBIN_G_PER_MOL) * (OXYGEN_SATURATION * oxy + (1 - OXYGEN_SATURATION) * deoxy);
    const baseline = 0.244 + 85.3 * Math.exp(-(nm - 154) / 66.2);
    const scattering = 46 * (nm / 500) ** -1.421;
    const dermis = diffuseReflectance(blood * bloodAbsorption + baseline, scattering);
    const filter = Math.exp(-2 * melanin * melaninAbsorption * EPIDERMIS_PATH_CM);
    out[c] = SURFACE_REFLECTANCE + (1 - SURFACE_REFLECTANCE) * filter * dermis;
  });
  return out;
}

/** A person's look: skin albedo, hair colours and density, iris colours. */
export interface IdentityLook {
  /** Skin albedo, linear RGB. */
  skin: [number, number, number];
  /** Brow and lash colours, sRGB `#rrggbb`. */
  browColor: string;
  lashColor: string;
  /** Share of the brow hairs drawn, 0..1. */
  browDensity: number;
  /** Iris colours near the pupil and at the limbus (linear RGB), and the seed of its fibres. */
  iris: { inner: [number, number, number]; outer: [number, number, number]; seed: number };
}

/** Hair colours by ancestry (sRGB): the mix is taken in linear light. */
const HAIR = Object.freeze({ african: [0x1a, 0x14, 0x11], asian: [0x1d, 0x17, 0x13], european: [0x4a, 0x34, 0x27] });
const GREY = [0xa8, 0xa4, 0x9f] as const;
/** Irises a light-eyed person may have (linear RGB, inner and outer): blue, grey-green, hazel. */
const LIGHT_IRISES: readonly (readonly [readonly [number, number, number], readonly [number, number, number]])[] = [
  [
    [0.18, 0.26, 0.34],
    [0.06, 0.1, 0.16],
  ],
  [
    [0.2, 0.22, 0.12],
    [0.07, 0.12, 0.1],
  ],
  [
    [0.3, 0.17, 0.06],
    [0.1, 0.16, 0.13],
  ],
];
const BROWN_IRIS = [
  [0.12, 0.055, 0.02],
  [0.045, 0.028, 0.014],
] as const;

const toLinear = (v: number): number => (v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4);
const toSrgb = (v: number): number => (v <= 0.0031308 ? 12.92 * v : 1.055 * v ** (1 / 2.4) - 0.055);
const hex = (linear: readonly number[]): string =>
  `#${linear
    .map((v) =>
      Math.round(255 * toSrgb(Math.min(1, Math.max(0, v))))
        .toString(16)
        .padStart(2, '0'),
    )
    .join('')}`;

/** A seed from the person's numbers (FNV-1a over them): the same person always gets the same eyes. */
function personSeed(identity: Identity): number {
  const a = identity.ancestry;
  let hash = 0x811c9dc5;
  for (const ch of [identity.sex, identity.age, a.african, a.asian, a.european].map((x) => x.toFixed(4)).join(',')) {
    hash = Math.imul(hash ^ ch.charCodeAt(0), 0x01000193);
  }
  return hash >>> 0;
}

/**
 * The look of a person: skin from melanin by ancestry and blood by sex; brows and lashes dark by ancestry, greying
 * from 45 years (lashes later than brows), fuller for men and sparser for children; irises brown, or for a share of
 * European ancestry one of the light colours, picked by the person's own seed.
 */
export function identityLook(identity: Identity): IdentityLook {
  const a = identity.ancestry;
  const melanin = a.african * MELANIN_BY_ANCESTRY.african + a.asian * MELANIN_BY_ANCESTRY.asian + a.european * MELANIN_BY_ANCESTRY.european;
  const blood = BLOOD_FEMALE + (BLOOD_MALE - BLOOD_FEMALE) * identity.sex;
  const hair = [0, 1, 2].map(
    (c) =>
      a.african * toLinear(HAIR.african[c] / 255) + a.asian * toLinear(HAIR.asian[c] / 255) + a.european * toLinear(HAIR.european[c] / 255),
  );
  const greying = Math.min(1, Math.max(0, (identity.age - 45) / 40));
  const grey = GREY.map((g) => toLinear(g / 255));
  const mix = (t: number): number[] => hair.map((h, c) => h + (grey[c] - h) * t);
  const seed = personSeed(identity);
  const random = mulberry32(seed);
  const light = random() < 0.7 * a.european;
  const [inner, outer] = light ? LIGHT_IRISES[Math.floor(random() * LIGHT_IRISES.length)] : BROWN_IRIS;
  return {
    skin: skinAlbedo(melanin, blood),
    browColor: hex(mix(0.7 * greying)),
    lashColor: hex(mix(0.3 * greying).map((v) => 0.6 * v)),
    browDensity: (identity.age < 12 ? 0.6 : 0.8) + 0.2 * identity.sex,
    iris: { inner: [...inner], outer: [...outer], seed: seed % 1000 },
  };
}
