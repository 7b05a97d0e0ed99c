/**
 * The head positions of FACS (AU51 turn left, AU52 turn right, AU53 up, AU54 down, AU55 tilt left, AU56 tilt right,
 * AU57 forward, AU58 back) as a head pose: a rigid turn of the head about the neck's pivot and a shift along the
 * face's forward axis, each growing with its unit's intensity up to its E grade. Opposite units cancel. Left is the
 * subject's left (+x); +y is up and the face looks along +z. Pure: no DOM, no three.js.
 *
 * The skin is solved in the head's own frame, where the skull stands still: a turned head is, to the solver, a neck
 * whose base turns the other way (see neck-carry.ts), and the view turns the whole head by the pose, which puts the
 * neck's base back where the body holds it.
 */

/** How far each head position moves the head at intensity 1 (grade E): degrees, and metres for forward and back. */
export const HEAD_POSE_AT_E = Object.freeze({ turn: 45, up: 30, down: 30, tilt: 30, forward: 0.02, back: 0.02 });

/** A head pose: how the head positions turn and shift the whole head. */
export interface HeadPose {
  /** Degrees of turn toward the subject's left (AU51; negative: right, AU52). */
  yaw: number;
  /** Degrees up (AU53; negative: down, AU54). */
  pitch: number;
  /** Degrees of tilt, the crown toward the left shoulder (AU55; negative: right, AU56). */
  roll: number;
  /** Metres forward (AU57; negative: back, AU58). */
  forward: number;
}

/** The head-position units, in the order `actionUnitHeadPose` reads them. */
export const HEAD_POSITION_UNITS: readonly string[] = Object.freeze(['AU51', 'AU52', 'AU53', 'AU54', 'AU55', 'AU56', 'AU57', 'AU58']);

/** A pose at rest, for callers that need a starting value. */
export function restingHeadPose(): HeadPose {
  return { yaw: 0, pitch: 0, roll: 0, forward: 0 };
}

/** True for a pose that moves nothing. */
export function isRestingPose(pose: HeadPose): boolean {
  return pose.yaw === 0 && pose.pitch === 0 && pose.roll === 0 && pose.forward === 0;
}

/**
 * The pose the head positions ask for, from their effective intensities (0..1) as `read` gives them by id. Writes into
 * `out` and returns it: the expression calls this after every change.
 */
export function actionUnitHeadPose(read: (id: string) => number, out: HeadPose): HeadPose {
  const e = HEAD_POSE_AT_E;
  out.yaw = e.turn * (read('AU51') - read('AU52'));
  out.pitch = e.up * read('AU53') - e.down * read('AU54');
  out.roll = e.tilt * (read('AU55') - read('AU56'));
  out.forward = e.forward * read('AU57') - e.back * read('AU58');
  return out;
}

/** Floats in a pose transform: a row-major rotation (9), then a translation (3). */
export const POSE_TRANSFORM_SIZE = 12;

/**
 * The rigid transform of `fraction` of a pose (every angle and the shift times it) about `pivot`, into `out` (12
 * floats, see POSE_TRANSFORM_SIZE) as p' = R p + t: the turn is yaw about +y, then pitch about x, then roll about the
 * face's forward axis (R = Ry Rx Rz), so a pure tilt leaves the face looking ahead. Allocates nothing.
 */
export function poseTransform(pose: HeadPose, fraction: number, pivot: ArrayLike<number>, out: Float64Array | number[], offset = 0): void {
  const rad = (fraction * Math.PI) / 180;
  const a = pose.yaw * rad;
  const b = -pose.pitch * rad;
  const g = -pose.roll * rad;
  const ca = Math.cos(a),
    sa = Math.sin(a);
  const cb = Math.cos(b),
    sb = Math.sin(b);
  const cg = Math.cos(g),
    sg = Math.sin(g);
  // Ry(a) Rx(b) Rz(g), row-major.
  const r00 = ca * cg + sa * sb * sg;
  const r01 = -ca * sg + sa * sb * cg;
  const r02 = sa * cb;
  const r10 = cb * sg;
  const r11 = cb * cg;
  const r12 = -sb;
  const r20 = -sa * cg + ca * sb * sg;
  const r21 = sa * sg + ca * sb * cg;
  const r22 = ca * cb;
  const o = offset;
  out[o] = r00;
  out[o + 1] = r01;
  out[o + 2] = r02;
  out[o + 3] = r10;
  out[o + 4] = r11;
  out[o + 5] = r12;
  out[o + 6] = r20;
  out[o + 7] = r21;
  out[o + 8] = r22;
  // t = pivot - R pivot + the shift along +z.
  const px = pivot[0],
    py = pivot[1],
    pz = pivot[2];
  out[o + 9] = px - (r00 * px + r01 * py + r02 * pz);
  out[o + 10] = py - (r10 * px + r11 * py + r12 * pz);
  out[o + 11] = pz - (r20 * px + r21 * py + r22 * pz) + fraction * pose.forward;
}

/** Applies a pose transform (see poseTransform) to the point (x, y, z), into `out[offset..offset+2]`. */
export function transformPoint(
  m: ArrayLike<number>,
  x: number,
  y: number,
  z: number,
  out: Float64Array | Float32Array | number[],
  offset = 0,
): void {
  out[offset] = m[0] * x + m[1] * y + m[2] * z + m[9];
  out[offset + 1] = m[3] * x + m[4] * y + m[5] * z + m[10];
  out[offset + 2] = m[6] * x + m[7] * y + m[8] * z + m[11];
}

/** Applies the inverse of a pose transform (R^T (p - t)) to the point (x, y, z), into `out[offset..offset+2]`. */
export function inverseTransformPoint(
  m: ArrayLike<number>,
  x: number,
  y: number,
  z: number,
  out: Float64Array | Float32Array | number[],
  offset = 0,
): void {
  const dx = x - m[9],
    dy = y - m[10],
    dz = z - m[11];
  out[offset] = m[0] * dx + m[3] * dy + m[6] * dz;
  out[offset + 1] = m[1] * dx + m[4] * dy + m[7] * dz;
  out[offset + 2] = m[2] * dx + m[5] * dy + m[8] * dz;
}
