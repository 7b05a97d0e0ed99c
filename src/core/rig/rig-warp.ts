/**
 * Carries a rig from the head it was made on to another head: every point of every muscle goes through a thin-plate
 * warp fitted on landmarks, frames turn and radii stretch with the warp's local derivative, and lengths that are
 * not tied to a direction (fades, brush radii) scale with its affine part. Pure: no three.js, no DOM.
 */
import { eulerMatrix } from '../math3';
import type { BrushSphere, EulerDegrees, Muscle, Rig, Vec3 } from './rig-types';
import { warpJacobian, warpPoint, type ThinPlateWarp } from '../head/thin-plate';

/** The rig on the warped head: a new document, the input is not changed. */
export function warpRig(rig: Rig, warp: ThinPlateWarp): Rig {
  const out = structuredClone(rig);
  out.muscles = rig.muscles.map((m) => warpMuscle(m, warp));
  return out;
}

/** One muscle through the warp (a new object). */
function warpMuscle(muscle: Muscle, warp: ThinPlateWarp): Muscle {
  const m = structuredClone(muscle);
  const s = warp.scale;
  if (m.brush) {
    const dab = ([x, y, z, r]: BrushSphere): BrushSphere => [...round(warpPoint(warp, [x, y, z])), roundLength(r * s)];
    m.brush = { add: m.brush.add.map(dab), remove: m.brush.remove.map(dab) };
  }
  if (m.type === 'linear') {
    m.origin = round(warpPoint(warp, m.origin));
    m.insertion = round(warpPoint(warp, m.insertion));
    return m;
  }
  // A frame's axes go through the derivative at its centre: their new lengths stretch the radii (or the box),
  // their new directions, made orthonormal again, give the rotation.
  const { rotation, stretch } = warpFrame(warp, m.center, m.rotation);
  if (m.type === 'jaw') {
    const frame = new Array<number>(9);
    eulerMatrix(m.rotation, frame);
    const back = m.size[2] / 2;
    const joint = m.joint ?? [m.center[0] - back * frame[2], m.center[1] - back * frame[5], m.center[2] - back * frame[8]];
    m.joint = round(warpPoint(warp, joint));
    m.size = [roundLength(m.size[0] * stretch[0]), roundLength(m.size[1] * stretch[1]), roundLength(m.size[2] * stretch[2])];
    m.fade = roundLength(m.fade * s);
    if (m.lipFade !== undefined) m.lipFade = roundLength(m.lipFade * s);
    if (m.lipDrop !== undefined) m.lipDrop = roundLength(m.lipDrop * stretch[1]);
    if (m.lipHalfWidth !== undefined) m.lipHalfWidth = roundLength(m.lipHalfWidth * stretch[0]);
  } else {
    m.radii = [roundLength(m.radii[0] * stretch[0]), roundLength(m.radii[1] * stretch[1]), roundLength(m.radii[2] * stretch[2])];
    if (m.type === 'sphincter') {
      // Inner radii stay within the outer ones, as the schema asks, after rounding too.
      m.innerRadii = [0, 1, 2].map((k) => Math.min(m.radii[k], roundLength(m.innerRadii[k] * stretch[k]))) as Vec3;
    }
  }
  m.center = round(warpPoint(warp, m.center));
  m.rotation = rotation;
  return m;
}

/**
 * The warped frame at `center`: the derivative times each local axis gives the new axis; its length is how much the
 * frame stretches along it. The axes are made orthonormal (Gram-Schmidt, x first) and read back as Euler angles.
 */
function warpFrame(warp: ThinPlateWarp, center: Vec3, rotation: EulerDegrees): { rotation: EulerDegrees; stretch: Vec3 } {
  const R = new Array<number>(9);
  eulerMatrix(rotation, R);
  const J = warpJacobian(warp, center);
  const axes = [0, 1, 2].map((c) => [0, 1, 2].map((row) => J[row * 3] * R[c] + J[row * 3 + 1] * R[3 + c] + J[row * 3 + 2] * R[6 + c]));
  const stretch = axes.map((v) => Math.hypot(v[0], v[1], v[2])) as Vec3;
  const x = normalise(axes[0]);
  const yRaw = axes[1];
  const d = dot(yRaw, x);
  const y = normalise([yRaw[0] - d * x[0], yRaw[1] - d * x[1], yRaw[2] - d * x[2]]);
  let z = cross(x, y);
  // A mirroring warp would flip the frame; keep it right-handed along the warped z axis.
  if (dot(z, axes[2]) < 0) z = [-z[0], -z[1], -z[2]];
  // Columns x, y, z as a row-major matrix M[row * 3 + col].
  const M = [x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2]];
  return { rotation: eulerDegrees(M), stretch };
}

/** The Euler angles (degrees, R = Rz * Ry * Rx as `eulerMatrix` builds it) of a row-major rotation matrix. */
export function eulerDegrees(M: readonly number[]): EulerDegrees {
  const sy = Math.max(-1, Math.min(1, -M[6]));
  const ay = Math.asin(sy);
  let ax: number;
  let az: number;
  if (Math.abs(sy) < 1 - 1e-9) {
    ax = Math.atan2(M[7], M[8]);
    az = Math.atan2(M[3], M[0]);
  } else {
    // Gimbal lock: only ax - az (or ax + az) is defined; take az = 0.
    az = 0;
    ax = Math.atan2(-M[5], M[4]);
  }
  const deg = (a: number): number => Math.round(((a * 180) / Math.PI) * 1e4) / 1e4;
  return [deg(ax), deg(ay), deg(az)];
}

/** Rig files hold tenths of a millimetre and better: micrometres keep them readable. */
const round = (p: readonly number[]): Vec3 => [roundLength(p[0]), roundLength(p[1]), roundLength(p[2])];
const roundLength = (x: number): number => Math.round(x * 1e6) / 1e6;
const dot = (a: readonly number[], b: readonly number[]): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: readonly number[], b: readonly number[]): number[] => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
function normalise(v: readonly number[]): number[] {
  const l = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / l, v[1] / l, v[2] / l];
}
