import type { BufferAttribute, Material, Mesh, Object3D } from 'three';
import { smoothstep } from '../core/math3';
import type { Vec3 } from '../core/rig/rig-types';
import { findLipSlit, type LipSlit } from '../core/head/lip-slit';

/** Light left on the teeth and gums behind lips that touch: a slit lets little of the room's light in. */
export const CLOSED_MOUTH_LIGHT = 0.3;
/** The lips' gap at the midline (metres) up to which they count as closed, and from which the teeth get all the light. */
const CLOSED_GAP = 0.0012;
const OPEN_GAP = 0.003;

/** A uniform holding how much light a part gets (the subsurface materials' `userData.shade`). */
export interface ShadeUniform {
  value: number;
}

/**
 * Shades the teeth and gums by how far the lips are apart at the midline, whenever the skin shows a new frame: behind
 * lips that touch they were lit as in a smile, and showed as a white line through the slit at rest. Their baked
 * occlusion darkens the mouth's back and the inner mouth's tint darkens with depth, but neither knows the lips.
 */
export class MouthShade {
  private readonly slit: LipSlit | null;
  private readonly positions: BufferAttribute;

  /** Finds the slit on `skin` as it is now (at rest) from its mouth corners (in the skin's own frame). */
  constructor(
    skin: Mesh,
    mouthL: Vec3,
    mouthR: Vec3,
    private readonly shades: readonly ShadeUniform[],
  ) {
    const geometry = skin.geometry;
    this.positions = geometry.getAttribute('position') as BufferAttribute;
    const normals = geometry.getAttribute('normal') as BufferAttribute;
    this.slit = findLipSlit(this.positions.array, normals.array, mouthL, mouthR);
    this.skinChanged();
  }

  /** Sets the shade from the skin mesh's current positions (call after the skin took a new frame). */
  skinChanged(): void {
    const light = this.slit ? mouthLightAt(this.gap(this.slit)) : 1;
    for (let i = 0; i < this.shades.length; i++) this.shades[i].value = light;
  }

  /** Restores the full light (the head leaves the view, or the shade is no longer wanted). */
  dispose(): void {
    for (let i = 0; i < this.shades.length; i++) this.shades[i].value = 1;
  }

  private gap(slit: LipSlit): number {
    const p = this.positions.array;
    const u = 3 * slit.upper;
    const l = 3 * slit.lower;
    return Math.hypot(p[u] - p[l], p[u + 1] - p[l + 1], p[u + 2] - p[l + 2]);
  }
}

/** The light the teeth get with the lips `gap` metres apart at the midline: CLOSED_MOUTH_LIGHT closed, 1 open. */
export function mouthLightAt(gap: number): number {
  return CLOSED_MOUTH_LIGHT + (1 - CLOSED_MOUTH_LIGHT) * smoothstep(CLOSED_GAP, OPEN_GAP, gap);
}

/** The light uniforms of the teeth rows' materials (the teeth's and the gums'), each once. */
export function teethShades(rows: readonly Object3D[]): ShadeUniform[] {
  const shades = new Set<ShadeUniform>();
  for (const row of rows) {
    row.traverse((o) => {
      const material = (o as Partial<Mesh>).material;
      for (const m of Array.isArray(material) ? material : material ? [material] : []) {
        const shade = (m as Material).userData.shade as ShadeUniform | undefined;
        if (shade) shades.add(shade);
      }
    });
  }
  return [...shades];
}
