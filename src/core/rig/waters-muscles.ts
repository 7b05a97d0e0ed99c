/**
 * Waters' linear and sphincter muscles (thesis 3.2.1 and 4.4.1-2): fields that pull the skin where it is now toward
 * an origin or a centre, with the smooth falloffs the thesis meant.
 */
import {
  FRAME,
  HALF_PI,
  INVERSE_INNER_RADII,
  INVERSE_RADII,
  LINEAR_ANGLE,
  LINEAR_AXIS,
  LINEAR_FALLOFF_END,
  LINEAR_FALLOFF_START,
  SCALE,
  STRENGTH,
} from './muscle-packing';

/**
 * Waters' linear muscle (thesis 3.2.1.1, 4.4.1): v = c K A R (origin - p). The angular falloff A = cos(mu / angle *
 * pi/2) (printed as mu / pi, which would never reach zero at the cone's edge); the radial falloff R = cos((1 - D/Rs)
 * pi/2) up to Rs (zero at the bone, full at Rs) and cos((D - Rs) / (Rf - Rs) pi/2) from Rs to Rf (printed as
 * (D - Rs/Rf - Rs), which is not a fraction of the falloff band).
 */
export function displaceLinear(
  P: Float64Array,
  o: number,
  c: number,
  dx: number,
  dy: number,
  dz: number,
  out: Float64Array | number[],
): number {
  const D = Math.sqrt(dx * dx + dy * dy + dz * dz);
  if (D === 0) return 0;
  let cosMu = (dx * P[o + LINEAR_AXIS] + dy * P[o + LINEAR_AXIS + 1] + dz * P[o + LINEAR_AXIS + 2]) / D;
  cosMu = cosMu > 1 ? 1 : cosMu < -1 ? -1 : cosMu;
  const mu = Math.acos(cosMu);
  const angle = P[o + LINEAR_ANGLE];
  if (mu >= angle) return 0;
  const A = Math.cos((mu / angle) * HALF_PI);
  const Rs = P[o + LINEAR_FALLOFF_START];
  const Rf = P[o + LINEAR_FALLOFF_END];
  // sin(D/Rs pi/2) is cos((1 - D/Rs) pi/2), written so that it is exactly zero at the bone.
  const R = D < Rs ? Math.sin((D / Rs) * HALF_PI) : Math.cos(((D - Rs) / (Rf - Rs)) * HALF_PI);
  const falloff = A * R;
  // Toward the origin: origin - p = -(dx, dy, dz).
  const k = -c * P[o + STRENGTH] * falloff;
  out[0] = k * dx;
  out[1] = k * dy;
  out[2] = k * dz;
  return falloff;
}

/**
 * Waters' sphincter as the thesis extends it (3.2.1.2, 4.4.2): an ellipsoid (membership by squared normalised
 * distances; the printed test lacks the squares), an inner ellipsoid where the pull is reduced toward the centre (the
 * thesis's fix for over-compressed skin there), and a per-axis scale of the pull. Inside the inner ellipsoid
 * R = cos((1 - t) pi/2) with t its normalised distance, so the pull is zero at the centre and full on the inner surface;
 * between the ellipsoids R = cos((rho - rho_s) / (1 - rho_s) pi/2), rho the outer normalised distance and rho_s = rho / t
 * that of the inner surface along the same ray, so it falls from full on the inner surface to zero on the outer one.
 */
export function displaceSphincter(
  P: Float64Array,
  o: number,
  c: number,
  qx: number,
  qy: number,
  qz: number,
  out: Float64Array | number[],
): number {
  const ox = qx * P[o + INVERSE_RADII];
  const oy = qy * P[o + INVERSE_RADII + 1];
  const oz = qz * P[o + INVERSE_RADII + 2];
  const rhoSquared = ox * ox + oy * oy + oz * oz;
  if (rhoSquared >= 1) return 0;
  const ix = qx * P[o + INVERSE_INNER_RADII];
  const iy = qy * P[o + INVERSE_INNER_RADII + 1];
  const iz = qz * P[o + INVERSE_INNER_RADII + 2];
  const t = Math.sqrt(ix * ix + iy * iy + iz * iz);
  let falloff: number;
  if (t <= 1) {
    // cos((1 - t) pi/2), as a sine so that it is exactly zero at the centre.
    falloff = Math.sin(t * HALF_PI);
  } else {
    const rho = Math.sqrt(rhoSquared);
    // Below rho < 1, as t > 1 here: the band between the surfaces never has zero width where it is used.
    const rhoInner = rho / t;
    falloff = Math.cos(((rho - rhoInner) / (1 - rhoInner)) * HALF_PI);
  }
  if (falloff === 0) return 0;
  // Toward the centre, each local component scaled: M (center - p) with M = F diag(scale) F^T.
  const k = -c * P[o + STRENGTH] * falloff;
  const wx = k * P[o + SCALE] * qx;
  const wy = k * P[o + SCALE + 1] * qy;
  const wz = k * P[o + SCALE + 2] * qz;
  const F = o + FRAME;
  out[0] = P[F] * wx + P[F + 1] * wy + P[F + 2] * wz;
  out[1] = P[F + 3] * wx + P[F + 4] * wy + P[F + 5] * wz;
  out[2] = P[F + 6] * wx + P[F + 7] * wy + P[F + 8] * wz;
  return falloff;
}
