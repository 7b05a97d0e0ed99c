/**
 * Small 3D helpers for the muscle fields, on plain numbers and flat arrays (no three.js, no allocation), because
 * they run once per vertex, muscle and substep.
 */
import type { EulerDegrees } from './rig/rig-types';

/** Radians per degree. */
export const DEGREES = Math.PI / 180;

/**
 * Writes the rotation matrix of Euler angles (degrees) into `out[offset..offset+9]`, row-major: R = Rz * Ry * Rx,
 * i.e. the frame is turned about the head's x axis first, then its y axis, then its z axis ("applied in XYZ order"
 * about fixed axes). Its columns are the local x, y and z axes in the head's frame. In three.js the same matrix comes
 * from `new Euler(x, y, z, 'ZYX')` (radians): three.js names orders by intrinsic axes, so its default 'XYZ' is
 * Rx * Ry * Rz, a different frame.
 */
export function eulerMatrix(rotation: EulerDegrees, out: Float64Array | number[], offset = 0): void {
  const ax = rotation[0] * DEGREES;
  const ay = rotation[1] * DEGREES;
  const az = rotation[2] * DEGREES;
  const cx = Math.cos(ax);
  const sx = Math.sin(ax);
  const cy = Math.cos(ay);
  const sy = Math.sin(ay);
  const cz = Math.cos(az);
  const sz = Math.sin(az);
  out[offset] = cz * cy;
  out[offset + 1] = cz * sy * sx - sz * cx;
  out[offset + 2] = cz * sy * cx + sz * sx;
  out[offset + 3] = sz * cy;
  out[offset + 4] = sz * sy * sx + cz * cx;
  out[offset + 5] = sz * sy * cx - cz * sx;
  out[offset + 6] = -sy;
  out[offset + 7] = cy * sx;
  out[offset + 8] = cy * cx;
}

/**
 * Writes into `out[offset..offset+3]` how far the point (x, y, z) moves when turned by `angle` radians about the
 * unit axis (ux, uy, uz) through (px, py, pz), right-handed (Rodrigues' formula). Written as an offset, with
 * 1 - cos(angle) as 2 sin^2(angle / 2), so a small turn gives a small offset without cancellation and a zero turn
 * gives exactly zero.
 */
export function rotationOffset(
  x: number,
  y: number,
  z: number,
  px: number,
  py: number,
  pz: number,
  ux: number,
  uy: number,
  uz: number,
  angle: number,
  out: Float64Array | number[],
  offset = 0,
): void {
  const h = Math.sin(0.5 * angle);
  rotationOffsetBy(x, y, z, px, py, pz, ux, uy, uz, Math.sin(angle), 2 * h * h, out, offset);
}

/**
 * rotationOffset with the turn given as its sine and versine (1 - cos, computed as 2 sin^2(angle / 2)): a turn that
 * moves many points, or one point many times, takes its sines once.
 */
export function rotationOffsetBy(
  x: number,
  y: number,
  z: number,
  px: number,
  py: number,
  pz: number,
  ux: number,
  uy: number,
  uz: number,
  s: number,
  versine: number,
  out: Float64Array | number[],
  offset = 0,
): void {
  const wx = x - px;
  const wy = y - py;
  const wz = z - pz;
  const along = (ux * wx + uy * wy + uz * wz) * versine;
  out[offset] = (uy * wz - uz * wy) * s + ux * along - wx * versine;
  out[offset + 1] = (uz * wx - ux * wz) * s + uy * along - wy * versine;
  out[offset + 2] = (ux * wy - uy * wx) * s + uz * along - wz * versine;
}

/** Rotates the point (x, y, z) by `angle` radians about the unit axis (ux, uy, uz) through (px, py, pz), into `out`. */
export function rotateAboutAxis(
  x: number,
  y: number,
  z: number,
  px: number,
  py: number,
  pz: number,
  ux: number,
  uy: number,
  uz: number,
  angle: number,
  out: Float64Array | number[],
  offset = 0,
): void {
  rotationOffset(x, y, z, px, py, pz, ux, uy, uz, angle, out, offset);
  out[offset] += x;
  out[offset + 1] += y;
  out[offset + 2] += z;
}

/** `x` clamped to 0..1. */
export function clamp01(x: number): number {
  return x < 0 ? 0 : x > 1 ? 1 : x;
}

/** 0 at or below `a`, 1 at or above `b`, and a smooth cubic between (GLSL's smoothstep). */
export function smoothstep(a: number, b: number, x: number): number {
  const t = clamp01((x - a) / (b - a));
  return t * t * (3 - 2 * t);
}
