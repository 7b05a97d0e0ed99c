/**
 * The opening between the lips as a flat ellipse, and how much light reaches a point inside the mouth through it. Pure:
 * no three.js, no DOM. The teeth, gums and tongue are lit through this opening only (the render's shader does the
 * same sums per pixel; these are its reference, for tests and for reading).
 */
import { smoothstep } from '../math3';
import type { Vec3 } from '../rig/rig-types';
import type { LipSlit } from './lip-slit';

/** Offsets in an opening array: centre (xyz), unit axes across (toward the face's left), up and out of the mouth. */
export const OPENING_CENTRE = 0;
export const OPENING_ACROSS = 3;
export const OPENING_UP = 6;
export const OPENING_OUT = 9;
/** Offset of the half width and half height (metres). */
export const OPENING_HALF = 12;
/** Numbers in an opening array. */
export const MOUTH_OPENING_SIZE = 14;

/**
 * The opening's half width as a share of half the distance between the mouth corners: the lips part in a lens, pointed
 * at the corners, whose area is that of an ellipse of 0.85 its width.
 */
const WIDTH_SHARE = 0.85;
/**
 * Metres of the skin's up direction added to the lips' gap before it is taken as the opening's up axis: a wide gap sets
 * the axis (the plane tilts as the jaw drops), lips that touch fall back on the face's up.
 */
const UP_BIAS = 0.001;
/** How close behind the opening (metres) a point counts as lying in it: keeps the sums finite at the opening itself. */
const NEAREST_DEPTH = 2e-4;
/** Half sides of the rectangle of the ellipse's area and proportions (sqrt(pi) / 2 of the half axes). */
const RECTANGLE_SHARE = Math.sqrt(Math.PI) / 2;

/** The render vertex of `positions` nearest to `point`. */
export function nearestVertex(positions: ArrayLike<number>, point: Vec3): number {
  let best = 0;
  let nearest = Infinity;
  for (let v = 0; v < positions.length / 3; v++) {
    const d = (positions[3 * v] - point[0]) ** 2 + (positions[3 * v + 1] - point[1]) ** 2 + (positions[3 * v + 2] - point[2]) ** 2;
    if (d < nearest) {
      nearest = d;
      best = v;
    }
  }
  return best;
}

/**
 * Writes the opening of the skin's current `positions` (xyz, face toward +z, +y up) into `out` (MOUTH_OPENING_SIZE
 * numbers): centred between the slit's two vertices, as wide as the corner vertices `left` and `right` allow, as high as
 * the lips' gap at the midline, its plane across the mouth through the gap. Allocates nothing.
 */
export function measureMouthOpening(positions: ArrayLike<number>, slit: LipSlit, left: number, right: number, out: Float64Array): void {
  const u = 3 * slit.upper;
  const l = 3 * slit.lower;
  let ax = positions[3 * left] - positions[3 * right];
  let ay = positions[3 * left + 1] - positions[3 * right + 1];
  let az = positions[3 * left + 2] - positions[3 * right + 2];
  const width = Math.hypot(ax, ay, az) || 1e-9;
  ax /= width;
  ay /= width;
  az /= width;
  const gx = positions[u] - positions[l];
  const gy = positions[u + 1] - positions[l + 1];
  const gz = positions[u + 2] - positions[l + 2];
  // The up axis: the gap (plus a little of the face's up), without its part along the across axis.
  let ux = gx;
  let uy = gy + UP_BIAS;
  let uz = gz;
  const along = ux * ax + uy * ay + uz * az;
  ux -= along * ax;
  uy -= along * ay;
  uz -= along * az;
  const up = Math.hypot(ux, uy, uz) || 1e-9;
  ux /= up;
  uy /= up;
  uz /= up;
  out[OPENING_CENTRE] = 0.5 * (positions[u] + positions[l]);
  out[OPENING_CENTRE + 1] = 0.5 * (positions[u + 1] + positions[l + 1]);
  out[OPENING_CENTRE + 2] = 0.5 * (positions[u + 2] + positions[l + 2]);
  out[OPENING_ACROSS] = ax;
  out[OPENING_ACROSS + 1] = ay;
  out[OPENING_ACROSS + 2] = az;
  out[OPENING_UP] = ux;
  out[OPENING_UP + 1] = uy;
  out[OPENING_UP + 2] = uz;
  // Out of the mouth: across (the face's left) cross up points toward the face's front.
  out[OPENING_OUT] = ay * uz - az * uy;
  out[OPENING_OUT + 1] = az * ux - ax * uz;
  out[OPENING_OUT + 2] = ax * uy - ay * ux;
  out[OPENING_HALF] = 0.5 * WIDTH_SHARE * width;
  out[OPENING_HALF + 1] = 0.5 * Math.hypot(gx, gy, gz);
}

/** The point's offset from the opening's centre along across, up and out. */
function local(opening: ArrayLike<number>, p: Vec3, axis: number): number {
  return (
    (p[0] - opening[OPENING_CENTRE]) * opening[axis] +
    (p[1] - opening[OPENING_CENTRE + 1]) * opening[axis + 1] +
    (p[2] - opening[OPENING_CENTRE + 2]) * opening[axis + 2]
  );
}

/** Twice pi times the view factor of a rectangle from its corner at the foot (0, 0) to (x, y), seen from depth 1. */
function corner(x: number, y: number): number {
  const sx = Math.sqrt(1 + x * x);
  const sy = Math.sqrt(1 + y * y);
  return (x / sx) * Math.atan(y / sx) + (y / sy) * Math.atan(x / sy);
}

/**
 * The share of a point's view that is the opening, 0..1: the view factor of a small patch at `p`, facing out of the
 * mouth, to a rectangle of the opening's area and proportions in its plane (exact for the rectangle: the four corner
 * terms of the parallel-rectangle formula). How much of the room's diffuse light reaches the point through the lips.
 */
export function openingView(opening: ArrayLike<number>, p: Vec3): number {
  const depth = Math.max(-local(opening, p, OPENING_OUT), NEAREST_DEPTH);
  const fx = local(opening, p, OPENING_ACROSS);
  const fy = local(opening, p, OPENING_UP);
  const hx = RECTANGLE_SHARE * opening[OPENING_HALF];
  const hy = RECTANGLE_SHARE * opening[OPENING_HALF + 1];
  const x0 = (-hx - fx) / depth;
  const x1 = (hx - fx) / depth;
  const y0 = (-hy - fy) / depth;
  const y1 = (hy - fy) / depth;
  const sum = corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0);
  return Math.min(Math.max(sum / (2 * Math.PI), 0), 1);
}

/**
 * How much of a directional light reaching `p` from direction `toLight` (unit) comes through the opening, 0..1: 1 where
 * the ray toward the light crosses the opening's plane inside its ellipse, 0 outside it or for light from behind the
 * mouth, soft over the ellipse's edge (the lips are round, not a knife's edge).
 */
export function lightThroughOpening(opening: ArrayLike<number>, p: Vec3, toLight: Vec3): number {
  const depth = Math.max(-local(opening, p, OPENING_OUT), NEAREST_DEPTH);
  const dot = (axis: number) => toLight[0] * opening[axis] + toLight[1] * opening[axis + 1] + toLight[2] * opening[axis + 2];
  const c = dot(OPENING_OUT);
  if (c < 0.05) return 0;
  const t = depth / c;
  const qx = (local(opening, p, OPENING_ACROSS) + t * dot(OPENING_ACROSS)) / Math.max(opening[OPENING_HALF], 1e-5);
  const qy = (local(opening, p, OPENING_UP) + t * dot(OPENING_UP)) / Math.max(opening[OPENING_HALF + 1], 1e-5);
  const r = Math.hypot(qx, qy);
  return 1 - smoothstep(0.8, 1.2, r);
}
