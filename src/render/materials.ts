import { Color, DoubleSide, MeshPhysicalMaterial, MeshStandardMaterial } from 'three';

/** Skin: a physically based dielectric with a soft sheen for the fine vellus hair and oily film. */
export function createSkinMaterial(): MeshPhysicalMaterial {
  return new MeshPhysicalMaterial({
    name: 'skin',
    color: new Color(0.72, 0.42, 0.31),
    roughness: 0.5,
    metalness: 0,
    sheen: 0.35,
    sheenRoughness: 0.55,
    sheenColor: new Color(0.9, 0.55, 0.45),
    specularIntensity: 0.6,
  });
}

/** Cornea: clear and glossy, so the eye catches the light above the iris. */
export function createCorneaMaterial(): MeshPhysicalMaterial {
  return new MeshPhysicalMaterial({
    name: 'cornea',
    color: 0xffffff,
    roughness: 0.02,
    metalness: 0,
    transparent: true,
    opacity: 0.12,
    depthWrite: false,
    clearcoat: 1,
    clearcoatRoughness: 0.02,
  });
}

/** Teeth: off-white enamel, slightly translucent looking (rough, warm). */
export function createTeethMaterial(): MeshStandardMaterial {
  return new MeshStandardMaterial({ name: 'teeth', color: new Color(0.84, 0.79, 0.67), roughness: 0.32, side: DoubleSide });
}
