import { Vector3, type BufferAttribute, type Material, type Mesh, type Object3D, type WebGLRenderer } from 'three';
import type { Vec3 } from '../core/rig/rig-types';
import { findLipSlit, type LipSlit } from '../core/head/lip-slit';
import {
  MOUTH_OPENING_SIZE,
  OPENING_ACROSS,
  OPENING_CENTRE,
  OPENING_HALF,
  OPENING_OUT,
  OPENING_UP,
  measureMouthOpening,
  nearestVertex,
} from '../core/head/mouth-opening';
import type { MouthOpeningUniforms } from './materials';

/**
 * Lights the teeth, gums and tongue through the lips' opening, whenever the skin shows a new frame: measures the
 * opening on the skin (core/head/mouth-opening.ts) and hands it, in world space, to the parts' shader, which lets in
 * the key light only where its ray crosses the opening and the room's light by how much of the room the opening shows.
 * Closed lips leave the mouth dark (no white line through the slit at rest); a jaw dropped wide lights the front teeth
 * and leaves the back of the mouth and the far side's teeth in shade, as in a photograph.
 */
export class MouthShade {
  private readonly slit: LipSlit | null;
  private readonly left: number;
  private readonly right: number;
  private readonly positions: BufferAttribute;
  /** The opening in the skin's frame, as last measured. */
  private readonly opening = new Float64Array(MOUTH_OPENING_SIZE);
  private readonly meshes: Mesh[] = [];
  private readonly openings: MouthOpeningUniforms[] = [];
  /** Hands the opening to the shader before the first of the parts is drawn in a frame (they share it). */
  private readonly place = (renderer: WebGLRenderer): void => {
    const frame = renderer.info.render.frame;
    if (frame === this.placedFrame && renderer === this.placedBy) return;
    this.placedFrame = frame;
    this.placedBy = renderer;
    this.toWorld();
  };
  private placedFrame = -1;
  private placedBy: WebGLRenderer | null = null;
  private readonly axis = new Vector3();

  /**
   * Finds the slit and the mouth corners on `skin` as it is now (at rest; the corners from landmarks in the skin's own
   * frame) and lights the meshes of `parts` that carry a mouth opening in their material.
   */
  constructor(
    private readonly skin: Mesh,
    mouthL: Vec3,
    mouthR: Vec3,
    parts: readonly Object3D[],
  ) {
    const geometry = skin.geometry;
    this.positions = geometry.getAttribute('position') as BufferAttribute;
    const normals = geometry.getAttribute('normal') as BufferAttribute;
    this.slit = findLipSlit(this.positions.array, normals.array, mouthL, mouthR);
    this.left = nearestVertex(this.positions.array, mouthL);
    this.right = nearestVertex(this.positions.array, mouthR);
    for (const part of parts) {
      part.traverse((o) => {
        const mesh = o as Mesh;
        if (mesh.isMesh && materialsOf(mesh).some((m) => m.userData.mouth)) this.meshes.push(mesh);
      });
    }
    for (const mesh of this.meshes) {
      for (const m of materialsOf(mesh)) {
        const u = m.userData.mouth as MouthOpeningUniforms | undefined;
        if (u && !this.openings.includes(u)) this.openings.push(u);
      }
      // The opening goes to the shader just before each part is drawn, when the head's world transform is current.
      mesh.onBeforeRender = this.place;
    }
    this.skinChanged();
  }

  /** Measures the opening on the skin mesh's current positions (call after the skin took a new frame). */
  skinChanged(): void {
    if (this.slit) measureMouthOpening(this.positions.array, this.slit, this.left, this.right, this.opening);
  }

  /** Lets the parts be lit as if the lips were not there (the head leaves the view, or the shade is no longer wanted). */
  dispose(): void {
    for (const mesh of this.meshes) if (mesh.onBeforeRender === this.place) mesh.onBeforeRender = () => {};
    for (const u of this.openings) u.sfMouth.value = 0;
    this.placedBy = null;
  }

  private toWorld(): void {
    const o = this.opening;
    const m = this.skin.matrixWorld;
    // The head is scaled evenly if at all: one factor for both half sizes.
    const scale = this.axis.setFromMatrixColumn(m, 0).length();
    for (const u of this.openings) {
      u.sfMouth.value = this.slit ? 1 : 0;
      u.sfMouthCentre.value.set(o[OPENING_CENTRE], o[OPENING_CENTRE + 1], o[OPENING_CENTRE + 2]).applyMatrix4(m);
      u.sfMouthAcross.value.set(o[OPENING_ACROSS], o[OPENING_ACROSS + 1], o[OPENING_ACROSS + 2]).transformDirection(m);
      u.sfMouthUp.value.set(o[OPENING_UP], o[OPENING_UP + 1], o[OPENING_UP + 2]).transformDirection(m);
      u.sfMouthOut.value.set(o[OPENING_OUT], o[OPENING_OUT + 1], o[OPENING_OUT + 2]).transformDirection(m);
      u.sfMouthHalf.value.set(o[OPENING_HALF] * scale, o[OPENING_HALF + 1] * scale);
    }
  }
}

function materialsOf(mesh: Mesh): Material[] {
  const material = mesh.material;
  return Array.isArray(material) ? material : material ? [material] : [];
}
