/**
 * The thesis's rotation muscles (3.2.2 and 4.4.3), the lid and the jaw: they turn their skin about a hinge by an angle
 * that fades from the zone's inside to its surface.
 */
import { rotationOffsetBy } from '../math3';
import {
  CURVE,
  FADE,
  FRAME,
  HALF_PI,
  HALF_SIZE,
  INNER_FRACTION,
  INVERSE_RADII,
  JAW,
  JOINT,
  LID,
  LIP_DROP,
  LIP_FADE,
  LIP_INVERSE_HALF_WIDTH,
  MAX_ANGLE,
  TYPE,
} from './muscle-packing';

/**
 * A rotation muscle's falloff at local coordinates (qx, qy, qz) of the skin's rest point, and, where it is above 0,
 * the turn's sine and versine (1 - cos) at contraction `c` into `into[at]` and `into[at + 1]`.
 */
export function turnAt(P: Float64Array, o: number, c: number, qx: number, qy: number, qz: number, into: Float64Array, at: number): number {
  const type = P[o + TYPE];
  const falloff = type === LID ? lidFalloff(P, o, qx, qy, qz) : jawFalloff(P, o, qx, qy, qz);
  if (falloff === 0) return 0;
  let angle = c * P[o + MAX_ANGLE] * falloff;
  if (type === JAW) {
    // Thesis 4.4.3.2: the lower lip stayed too straight, so its middle opens further. The thesis adds a vertical
    // term sqrt((Lx - |dx|)(Ly - |dy|)) * n; here the extra is a turn, `curve` of the angle at the centre line,
    // falling as a parabola to none at the sides, so the skin still moves on arcs about the hinge.
    const across = qx / P[o + HALF_SIZE];
    angle *= 1 + P[o + CURVE] * (1 - across * across);
  }
  const h = Math.sin(0.5 * angle);
  into[at] = Math.sin(angle);
  into[at + 1] = 2 * h * h;
  return falloff;
}

/** The offset of (x, y, z) turned by rotation muscle `o` by the turn in `turn[at..at+2]` (see turnAt), into `out`. */
export function turnPoint(
  P: Float64Array,
  o: number,
  x: number,
  y: number,
  z: number,
  turn: Float64Array,
  at: number,
  out: Float64Array | number[],
): void {
  const F = o + FRAME;
  rotationOffsetBy(x, y, z, P[o + JOINT], P[o + JOINT + 1], P[o + JOINT + 2], P[F], P[F + 3], P[F + 6], turn[at], turn[at + 1], out);
}

/**
 * The lid muscle's share of its turn (thesis 4.4.3.1): the whole turn inside `innerFraction` of the ellipsoid (squared
 * normalised distances, as for the sphincter), fading (cosine) to none at its surface, none outside. The thesis turns
 * every vertex inside by the full angle, a step at the surface.
 */
function lidFalloff(P: Float64Array, o: number, qx: number, qy: number, qz: number): number {
  const ox = qx * P[o + INVERSE_RADII];
  const oy = qy * P[o + INVERSE_RADII + 1];
  const oz = qz * P[o + INVERSE_RADII + 2];
  const rhoSquared = ox * ox + oy * oy + oz * oz;
  if (rhoSquared >= 1) return 0;
  const inner = P[o + INNER_FRACTION];
  if (rhoSquared <= inner * inner) return 1;
  return Math.cos(((Math.sqrt(rhoSquared) - inner) / (1 - inner)) * HALF_PI);
}

/**
 * The jaw muscle's share of its turn (thesis 4.4.3.2, a cuboid): a cosine fade from none on each face to all at `fade`
 * inside it, multiplied over the three axes so that it is 1 farther than `fade` from every face and has no creases
 * along the box's diagonals (a minimum of the face distances would); none outside.
 */
function jawFalloff(P: Float64Array, o: number, qx: number, qy: number, qz: number): number {
  const gx = P[o + HALF_SIZE] - Math.abs(qx);
  // The top face follows the lip line: lower by LIP_DROP at the lip's half width and beyond, a parabola between.
  const across = Math.min(1, (qx * P[o + LIP_INVERSE_HALF_WIDTH]) ** 2);
  const gy = qy > 0 ? P[o + HALF_SIZE + 1] - P[o + LIP_DROP] * across - qy : P[o + HALF_SIZE + 1] + qy;
  const gz = P[o + HALF_SIZE + 2] - Math.abs(qz);
  if (gx <= 0 || gy <= 0 || gz <= 0) return 0;
  const fade = P[o + FADE];
  // The top face runs along the lips, which part sharply; the other faces lie in skin the jaw stretches.
  const fadeY = qy > 0 ? P[o + LIP_FADE] : fade;
  // sin(g/fade pi/2) = cos((1 - g/fade) pi/2): zero on the face, 1 with a level slope at `fade` inside.
  const fx = gx >= fade ? 1 : Math.sin((gx / fade) * HALF_PI);
  const fy = gy >= fadeY ? 1 : Math.sin((gy / fadeY) * HALF_PI);
  const fz = gz >= fade ? 1 : Math.sin((gz / fade) * HALF_PI);
  return fx * fy * fz;
}
