/**
 * A muscle packed into a flat Float64Array (STRIDE numbers from an offset), so that the per-vertex loops of the muscle
 * fields read numbers, not objects: the layout and the packing of a validated muscle.
 */
import { DEGREES, eulerMatrix } from '../math3';
import type { Muscle } from './rig-types';

export const HALF_PI = Math.PI / 2;

// The layout: where each value sits among a muscle's STRIDE numbers.
export const STRIDE = 32;
export const TYPE = 0;
/** Linear: the origin; others: the centre. Also the centre of the bounding sphere. */
export const ANCHOR = 1;
/** Squared radius of a sphere around ANCHOR that holds the whole zone: outside it the field is zero. */
export const BOUND_SQUARED = 4;
export const STRENGTH = 5;
/** Share of the hold that acts along the skin's normal: the muscle's normalWeight, 1 for rotation muscles. */
export const NORMAL_SHARE = 6;
/** Row-major rotation of the local frame (9 numbers); its columns are the local axes in the head's frame. */
export const FRAME = 7;
// Per type, from 16 on.
export const LINEAR_AXIS = 16; // unit vector origin -> insertion (3)
export const LINEAR_ANGLE = 19; // half-angle of the cone, radians
export const LINEAR_FALLOFF_START = 20; // Rs, metres
export const LINEAR_FALLOFF_END = 21; // Rf, metres
export const INVERSE_RADII = 16; // sphincter, lid: 1 / radii (3)
export const INVERSE_INNER_RADII = 19; // sphincter: 1 / innerRadii (3)
export const SCALE = 22; // sphincter: per local axis (3)
export const HALF_SIZE = 16; // jaw: half edge lengths (3)
export const JOINT = 25; // lid, jaw: the hinge point (3)
export const MAX_ANGLE = 28; // lid, jaw: radians at contraction 1
export const INNER_FRACTION = 29; // lid
export const CURVE = 29; // jaw
export const FADE = 30; // jaw, metres
export const LIP_FADE = 31; // jaw, metres: the top face's fade
export const LIP_DROP = 19; // jaw, metres: how far the top face bends down toward the sides
export const LIP_INVERSE_HALF_WIDTH = 20; // jaw: 1 / the half width the top face bends over

export const LINEAR = 0;
export const SPHINCTER = 1;
export const LID = 2;
export const JAW = 3;

/** Writes a validated muscle into `P[o..o+STRIDE]`. */
export function packMuscle(m: Muscle, P: Float64Array, o: number): void {
  P.fill(0, o, o + STRIDE);
  if (m.type === 'linear') {
    const ax = m.insertion[0] - m.origin[0];
    const ay = m.insertion[1] - m.origin[1];
    const az = m.insertion[2] - m.origin[2];
    const length = Math.sqrt(ax * ax + ay * ay + az * az);
    P[o + TYPE] = LINEAR;
    P.set(m.origin, o + ANCHOR);
    P[o + LINEAR_AXIS] = ax / length;
    P[o + LINEAR_AXIS + 1] = ay / length;
    P[o + LINEAR_AXIS + 2] = az / length;
    P[o + LINEAR_ANGLE] = m.angle * DEGREES;
    P[o + LINEAR_FALLOFF_START] = m.falloffStart * length;
    P[o + LINEAR_FALLOFF_END] = m.falloffEnd * length;
    P[o + BOUND_SQUARED] = (m.falloffEnd * length) ** 2;
    P[o + STRENGTH] = m.strength;
    P[o + NORMAL_SHARE] = m.normalWeight;
    eulerMatrix([0, 0, 0], P, o + FRAME);
    return;
  }
  P.set(m.center, o + ANCHOR);
  eulerMatrix(m.rotation, P, o + FRAME);
  // The local z axis (third column), along which the rotation muscles put their joint behind the centre.
  const zx = P[o + FRAME + 2];
  const zy = P[o + FRAME + 5];
  const zz = P[o + FRAME + 8];
  if (m.type === 'sphincter') {
    P[o + TYPE] = SPHINCTER;
    for (let i = 0; i < 3; i++) {
      P[o + INVERSE_RADII + i] = 1 / m.radii[i];
      P[o + INVERSE_INNER_RADII + i] = 1 / m.innerRadii[i];
      P[o + SCALE + i] = m.scale[i];
    }
    P[o + BOUND_SQUARED] = Math.max(m.radii[0], m.radii[1], m.radii[2]) ** 2;
    P[o + STRENGTH] = m.strength;
    P[o + NORMAL_SHARE] = m.normalWeight;
  } else if (m.type === 'lid') {
    P[o + TYPE] = LID;
    for (let i = 0; i < 3; i++) P[o + INVERSE_RADII + i] = 1 / m.radii[i];
    P[o + BOUND_SQUARED] = Math.max(m.radii[0], m.radii[1], m.radii[2]) ** 2;
    P[o + JOINT] = m.center[0] - m.radii[2] * zx;
    P[o + JOINT + 1] = m.center[1] - m.radii[2] * zy;
    P[o + JOINT + 2] = m.center[2] - m.radii[2] * zz;
    P[o + MAX_ANGLE] = m.maxAngle * DEGREES;
    P[o + INNER_FRACTION] = m.innerFraction;
    P[o + STRENGTH] = 1;
    P[o + NORMAL_SHARE] = 1;
  } else {
    P[o + TYPE] = JAW;
    const hx = m.size[0] / 2;
    const hy = m.size[1] / 2;
    const hz = m.size[2] / 2;
    P[o + HALF_SIZE] = hx;
    P[o + HALF_SIZE + 1] = hy;
    P[o + HALF_SIZE + 2] = hz;
    // A top face bent up toward the sides (a negative lipDrop) reaches above the box's half height.
    const hyTop = hy + Math.max(0, -(m.lipDrop ?? 0));
    P[o + BOUND_SQUARED] = hx * hx + hyTop * hyTop + hz * hz;
    // The real hinge sits well above the lip line, so a box fitted to the moving skin gets its own joint.
    const joint = m.joint ?? [m.center[0] - hz * zx, m.center[1] - hz * zy, m.center[2] - hz * zz];
    P[o + JOINT] = joint[0];
    P[o + JOINT + 1] = joint[1];
    P[o + JOINT + 2] = joint[2];
    P[o + MAX_ANGLE] = m.maxAngle * DEGREES;
    P[o + CURVE] = m.curve;
    P[o + FADE] = m.fade;
    P[o + LIP_FADE] = m.lipFade ?? m.fade;
    P[o + LIP_DROP] = m.lipDrop ?? 0;
    P[o + LIP_INVERSE_HALF_WIDTH] = 1 / (m.lipHalfWidth ?? hx);
    P[o + STRENGTH] = 1;
    P[o + NORMAL_SHARE] = 1;
  }
}
