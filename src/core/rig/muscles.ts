/**
 * Muscles (thesis 3.2 and 4.4): the displacement field of each muscle type in the rig (Waters' linear and sphincter
 * muscles, the thesis's lid and jaw rotation muscles) and their combination into the skin solver's muscle inputs, a
 * target and two weights per vertex (`SolverBuffers.targets/weights/normalWeights`). Pure: no three.js, no DOM.
 *
 * The thesis's printed formulas carry typos (a garbled radial falloff, an ellipsoid test without squares); each field
 * below says which of its ideas it implements and uses the smooth form that was meant.
 */
import { DEGREES, eulerMatrix, rotationOffset, rotationOffsetBy } from '../math3';
import type { MuscleInputs } from '../solver/solver';
import type { BrushSphere, Muscle, Vec3 } from './rig-types';

const HALF_PI = Math.PI / 2;

// A muscle packed into a flat Float64Array, so the per-vertex loops read numbers, not objects.
const STRIDE = 32;
const TYPE = 0;
/** Linear: the origin; others: the centre. Also the centre of the bounding sphere. */
const ANCHOR = 1;
/** Squared radius of a sphere around ANCHOR that holds the whole zone: outside it the field is zero. */
const BOUND_SQUARED = 4;
const STRENGTH = 5;
/** Share of the hold that acts along the skin's normal: the muscle's normalWeight, 1 for rotation muscles. */
const NORMAL_SHARE = 6;
/** Row-major rotation of the local frame (9 numbers); its columns are the local axes in the head's frame. */
const FRAME = 7;
// Per type, from 16 on.
const LINEAR_AXIS = 16; // unit vector origin -> insertion (3)
const LINEAR_ANGLE = 19; // half-angle of the cone, radians
const LINEAR_FALLOFF_START = 20; // Rs, metres
const LINEAR_FALLOFF_END = 21; // Rf, metres
const INVERSE_RADII = 16; // sphincter, lid: 1 / radii (3)
const INVERSE_INNER_RADII = 19; // sphincter: 1 / innerRadii (3)
const SCALE = 22; // sphincter: per local axis (3)
const HALF_SIZE = 16; // jaw: half edge lengths (3)
const JOINT = 25; // lid, jaw: the hinge point (3)
const MAX_ANGLE = 28; // lid, jaw: radians at contraction 1
const INNER_FRACTION = 29; // lid
const CURVE = 29; // jaw
const FADE = 30; // jaw, metres
const LIP_FADE = 31; // jaw, metres: the top face's fade

const LINEAR = 0;
const SPHINCTER = 1;
const LID = 2;
const JAW = 3;

/** Throws an error naming the muscle if its field would be undefined or stepped, or a value is out of its documented range. */
export function validateMuscle(m: Muscle): void {
  const name = typeof m?.name === 'string' ? m.name : '(unnamed)';
  const fail = (what: string): never => {
    throw new Error(`muscle ${name}: ${what}`);
  };
  const finite = (v: unknown, field: string): number => {
    if (typeof v !== 'number' || !Number.isFinite(v)) fail(`${field} must be a finite number, got ${String(v)}`);
    return v as number;
  };
  const within = (v: unknown, field: string, lo: number, hi: number): number => {
    const x = finite(v, field);
    if (x < lo || x > hi) fail(`${field} must be from ${lo} to ${hi}, got ${x}`);
    return x;
  };
  const vector = (v: unknown, field: string, positive = false): Vec3 => {
    if (!Array.isArray(v) || v.length !== 3) fail(`${field} must be three numbers`);
    const a = v as Vec3;
    for (let i = 0; i < 3; i++) {
      const x = finite(a[i], `${field}[${i}]`);
      if (positive && !(x > 0)) fail(`${field}[${i}] must be greater than 0, got ${x}`);
    }
    return a;
  };
  if (m?.brush !== undefined) {
    for (const kind of ['add', 'remove'] as const) {
      const list = (m.brush as unknown as Record<string, unknown> | null)?.[kind];
      if (!Array.isArray(list)) fail(`brush.${kind} must be an array of spheres`);
      (list as unknown[]).forEach((s, i) => {
        if (!Array.isArray(s) || s.length !== 4) fail(`brush.${kind}[${i}] must be [x, y, z, radius]`);
        const sphere = s as number[];
        for (let k = 0; k < 3; k++) finite(sphere[k], `brush.${kind}[${i}][${k}]`);
        if (!(finite(sphere[3], `brush.${kind}[${i}][3]`) > 0)) fail(`brush.${kind}[${i}] radius must be greater than 0, got ${sphere[3]}`);
      });
    }
  }
  switch (m?.type) {
    case 'linear': {
      const o = vector(m.origin, 'origin');
      const p = vector(m.insertion, 'insertion');
      if (o[0] === p[0] && o[1] === p[1] && o[2] === p[2]) fail('origin and insertion must differ');
      within(m.angle, 'angle', 0, 90);
      const start = finite(m.falloffStart, 'falloffStart');
      const end = finite(m.falloffEnd, 'falloffEnd');
      // The radial falloff divides by Rs and by Rf - Rs.
      if (!(start > 0 && end > start)) fail(`falloffs must satisfy 0 < falloffStart < falloffEnd, got ${start} and ${end}`);
      within(m.strength, 'strength', 0, 1);
      within(m.normalWeight, 'normalWeight', 0, 1);
      return;
    }
    case 'sphincter': {
      vector(m.center, 'center');
      vector(m.rotation, 'rotation');
      const radii = vector(m.radii, 'radii', true);
      const inner = vector(m.innerRadii, 'innerRadii', true);
      // An inner ellipsoid poking out of the outer one would make the pull stop in a step over a patch of skin. Equal
      // radii on an axis are allowed (a rig may want no fade along the depth): the step is then only at that axis's
      // two poles, the outer ellipsoid's tips, and the fade is steep only near them.
      for (let i = 0; i < 3; i++)
        if (!(inner[i] <= radii[i])) fail(`innerRadii[${i}] must not exceed radii[${i}] (${radii[i]}), got ${inner[i]}`);
      vector(m.scale, 'scale');
      if (finite(m.strength, 'strength') < 0) fail(`strength must not be negative, got ${m.strength}`);
      within(m.normalWeight, 'normalWeight', 0, 1);
      return;
    }
    case 'lid': {
      vector(m.center, 'center');
      vector(m.rotation, 'rotation');
      vector(m.radii, 'radii', true);
      within(m.maxAngle, 'maxAngle', -90, 90);
      const inner = finite(m.innerFraction, 'innerFraction');
      // innerFraction 1 would leave no room for the fade: a step at the surface.
      if (!(inner >= 0 && inner < 1)) fail(`innerFraction must be at least 0 and less than 1, got ${inner}`);
      return;
    }
    case 'jaw': {
      vector(m.center, 'center');
      vector(m.rotation, 'rotation');
      vector(m.size, 'size', true);
      if (m.joint !== undefined) vector(m.joint, 'joint');
      within(m.maxAngle, 'maxAngle', -90, 90);
      finite(m.curve, 'curve');
      // Without a fade the turn would stop abruptly at the box's faces.
      if (!(finite(m.fade, 'fade') > 0)) fail(`fade must be greater than 0, got ${m.fade}`);
      if (m.lipFade !== undefined && !(finite(m.lipFade, 'lipFade') > 0)) fail(`lipFade must be greater than 0, got ${m.lipFade}`);
      return;
    }
    default:
      fail(`unknown muscle type ${String((m as { type?: unknown })?.type)}`);
  }
}

/** Writes a validated muscle into `P[o..o+STRIDE]`. */
function packMuscle(m: Muscle, P: Float64Array, o: number): void {
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
    P[o + BOUND_SQUARED] = hx * hx + hy * hy + hz * hz;
    // The real hinge sits well above the lip line, so a box fitted to the moving skin gets its own joint.
    const joint = m.joint ?? [m.center[0] - hz * zx, m.center[1] - hz * zy, m.center[2] - hz * zz];
    P[o + JOINT] = joint[0];
    P[o + JOINT + 1] = joint[1];
    P[o + JOINT + 2] = joint[2];
    P[o + MAX_ANGLE] = m.maxAngle * DEGREES;
    P[o + CURVE] = m.curve;
    P[o + FADE] = m.fade;
    P[o + LIP_FADE] = m.lipFade ?? m.fade;
    P[o + STRENGTH] = 1;
    P[o + NORMAL_SHARE] = 1;
  }
}

/** Where displace puts a rotation muscle's turn (sine and versine) unless told otherwise. */
const TURN = new Float64Array(2);

/**
 * Displacement of the point (x, y, z) by packed muscle `o` at contraction `c`, into `out[0..3]`; returns the
 * muscle's falloff (0..1; 0 outside its zone, where the displacement is zero too). Linear and sphincter fields are
 * asked where the skin is now (so skin sliding out of a zone is pulled less); a rotation muscle's zone is asked at the
 * skin's rest point (rx, ry, rz), because the lid or jaw carries its skin with it: skin it has turned is still its
 * skin, and a lid closing would otherwise leave its own zone halfway. Allocates nothing.
 */
function displace(
  P: Float64Array,
  o: number,
  c: number,
  x: number,
  y: number,
  z: number,
  out: Float64Array | number[],
  rx = x,
  ry = y,
  rz = z,
  turn: Float64Array = TURN,
  at = 0,
): number {
  out[0] = 0;
  out[1] = 0;
  out[2] = 0;
  const type = P[o + TYPE];
  const rotates = type === LID || type === JAW;
  const px = rotates ? rx : x;
  const py = rotates ? ry : y;
  const pz = rotates ? rz : z;
  const dx = px - P[o + ANCHOR];
  const dy = py - P[o + ANCHOR + 1];
  const dz = pz - P[o + ANCHOR + 2];
  if (dx * dx + dy * dy + dz * dz >= P[o + BOUND_SQUARED]) return 0;
  if (type === LINEAR) return displaceLinear(P, o, c, dx, dy, dz, out);
  // Local coordinates: the transposed frame times the offset from the centre.
  const F = o + FRAME;
  const qx = P[F] * dx + P[F + 3] * dy + P[F + 6] * dz;
  const qy = P[F + 1] * dx + P[F + 4] * dy + P[F + 7] * dz;
  const qz = P[F + 2] * dx + P[F + 5] * dy + P[F + 8] * dz;
  if (type === SPHINCTER) return displaceSphincter(P, o, c, qx, qy, qz, out);
  const falloff = turnAt(P, o, c, qx, qy, qz, turn, at);
  // Thesis 3.2.2 and 4.4.3: rotation muscles turn their skin about a joint, about the local x axis (the frame's first
  // column); the turn moves skin farther from the joint farther, as the thesis wants.
  if (falloff !== 0) turnPoint(P, o, x, y, z, turn, at, out);
  return falloff;
}

/**
 * A rotation muscle's falloff at local coordinates (qx, qy, qz) of the skin's rest point, and, where it is above 0,
 * the turn's sine and versine (1 - cos) at contraction `c` into `into[at]` and `into[at + 1]`.
 */
function turnAt(P: Float64Array, o: number, c: number, qx: number, qy: number, qz: number, into: Float64Array, at: number): number {
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
function turnPoint(
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
 * Rotation muscles turn the skin by an amount that depends on its rest point only (see displace), the same at every
 * substep of a compute: so each vertex's turn by each rotation muscle is found once (`vertex[m]` is the vertex it was
 * found for; -1 for none), and its falloff and turn kept.
 */
interface TurnCache {
  vertex: Int32Array;
  falloff: Float64Array;
  /** Sine and versine per muscle. */
  turn: Float64Array;
}

/** displace, with the turn of a rotation muscle `m` (at `o`) for vertex `v` taken from `cache` once displace found it. */
function displaceVertex(
  P: Float64Array,
  o: number,
  m: number,
  v: number,
  c: number,
  x: number,
  y: number,
  z: number,
  out: Float64Array,
  rx: number,
  ry: number,
  rz: number,
  cache: TurnCache,
): number {
  const type = P[o + TYPE];
  if (type !== LID && type !== JAW) return displace(P, o, c, x, y, z, out, rx, ry, rz);
  if (cache.vertex[m] !== v) {
    // First asked for this vertex: displace finds the turn, and keeps it in the cache.
    cache.vertex[m] = v;
    cache.falloff[m] = displace(P, o, c, x, y, z, out, rx, ry, rz, cache.turn, 2 * m);
    return cache.falloff[m];
  }
  const falloff = cache.falloff[m];
  if (falloff === 0) {
    out[0] = 0;
    out[1] = 0;
    out[2] = 0;
    return 0;
  }
  turnPoint(P, o, x, y, z, cache.turn, 2 * m, out);
  return falloff;
}

/**
 * Waters' linear muscle (thesis 3.2.1.1, 4.4.1): v = c K A R (origin - p). The angular falloff A = cos(mu / angle *
 * pi/2) (printed as mu / pi, which would never reach zero at the cone's edge); the radial falloff R = cos((1 - D/Rs)
 * pi/2) up to Rs (zero at the bone, full at Rs) and cos((D - Rs) / (Rf - Rs) pi/2) from Rs to Rf (printed as
 * (D - Rs/Rf - Rs), which is not a fraction of the falloff band).
 */
function displaceLinear(P: Float64Array, o: number, c: number, dx: number, dy: number, dz: number, out: Float64Array | number[]): number {
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
function displaceSphincter(
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

/**
 * The displacement packed muscle `o` gives (x, y, z) as if its falloff there were 1, at contraction `c`: every field
 * is its falloff times this (the turn's angle, for the rotation muscles), so `c` times a falloff gives the field at
 * that falloff. Used where a brush sets the falloff, also outside the muscle's zone. Allocates nothing.
 */
function displaceAtFalloff(
  P: Float64Array,
  o: number,
  c: number,
  x: number,
  y: number,
  z: number,
  out: Float64Array | number[],
  rx: number,
  ry: number,
  rz: number,
): void {
  const type = P[o + TYPE];
  const F = o + FRAME;
  if (type === LINEAR) {
    const k = -c * P[o + STRENGTH];
    out[0] = k * (x - P[o + ANCHOR]);
    out[1] = k * (y - P[o + ANCHOR + 1]);
    out[2] = k * (z - P[o + ANCHOR + 2]);
    return;
  }
  const rotates = type === LID || type === JAW;
  const dx = (rotates ? rx : x) - P[o + ANCHOR];
  const dy = (rotates ? ry : y) - P[o + ANCHOR + 1];
  const dz = (rotates ? rz : z) - P[o + ANCHOR + 2];
  const qx = P[F] * dx + P[F + 3] * dy + P[F + 6] * dz;
  const qy = P[F + 1] * dx + P[F + 4] * dy + P[F + 7] * dz;
  const qz = P[F + 2] * dx + P[F + 5] * dy + P[F + 8] * dz;
  if (type === SPHINCTER) {
    const k = -c * P[o + STRENGTH];
    const wx = k * P[o + SCALE] * qx;
    const wy = k * P[o + SCALE + 1] * qy;
    const wz = k * P[o + SCALE + 2] * qz;
    out[0] = P[F] * wx + P[F + 1] * wy + P[F + 2] * wz;
    out[1] = P[F + 3] * wx + P[F + 4] * wy + P[F + 5] * wz;
    out[2] = P[F + 6] * wx + P[F + 7] * wy + P[F + 8] * wz;
    return;
  }
  let angle = c * P[o + MAX_ANGLE];
  if (type === JAW) {
    const across = Math.max(-1, Math.min(1, qx / P[o + HALF_SIZE]));
    angle *= 1 + P[o + CURVE] * (1 - across * across);
  }
  rotationOffset(x, y, z, P[o + JOINT], P[o + JOINT + 1], P[o + JOINT + 2], P[F], P[F + 3], P[F + 6], angle, out);
}

/**
 * A brush sphere's weight at a rest point: 1 in its inner half, fading (cosine) to 0 at its surface, so painted
 * influence has no step at a dab's edge.
 */
function sphereWeight(s: BrushSphere, x: number, y: number, z: number): number {
  const d = Math.hypot(x - s[0], y - s[1], z - s[2]);
  const r = s[3];
  if (d >= r) return 0;
  if (d <= r / 2) return 1;
  return Math.cos(((d - r / 2) / (r / 2)) * HALF_PI);
}

/** The falloff a brushed vertex gets: at least what the add spheres give, less what the remove spheres take. */
function brushed(falloff: number, add: number, keep: number): number {
  return (falloff > add ? falloff : add) * keep;
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
  const gy = P[o + HALF_SIZE + 1] - Math.abs(qy);
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

/**
 * Whether a rest point is a candidate of packed muscle `o`: within `margin` of its zone, by a test that may say yes
 * too often but never too rarely (the thesis's membership tests of 4.4, grown by the margin).
 */
function reaches(P: Float64Array, o: number, margin: number, x: number, y: number, z: number): boolean {
  const dx = x - P[o + ANCHOR];
  const dy = y - P[o + ANCHOR + 1];
  const dz = z - P[o + ANCHOR + 2];
  const type = P[o + TYPE];
  if (type === LINEAR) {
    const D = Math.sqrt(dx * dx + dy * dy + dz * dz);
    if (D > P[o + LINEAR_FALLOFF_END] + margin) return false;
    if (D <= margin) return true;
    const cosMu = (dx * P[o + LINEAR_AXIS] + dy * P[o + LINEAR_AXIS + 1] + dz * P[o + LINEAR_AXIS + 2]) / D;
    const outside = Math.acos(cosMu > 1 ? 1 : cosMu < -1 ? -1 : cosMu) - P[o + LINEAR_ANGLE];
    // Distance to the cone's side is D sin(outside) while the nearest point is on the side, D beyond a right angle.
    return outside <= 0 || (outside < HALF_PI ? D * Math.sin(outside) : D) <= margin;
  }
  const F = o + FRAME;
  const qx = P[F] * dx + P[F + 3] * dy + P[F + 6] * dz;
  const qy = P[F + 1] * dx + P[F + 4] * dy + P[F + 7] * dz;
  const qz = P[F + 2] * dx + P[F + 5] * dy + P[F + 8] * dz;
  if (type === JAW) {
    return (
      Math.abs(qx) <= P[o + HALF_SIZE] + margin &&
      Math.abs(qy) <= P[o + HALF_SIZE + 1] + margin &&
      Math.abs(qz) <= P[o + HALF_SIZE + 2] + margin
    );
  }
  // Ellipsoids: dividing by the radii stretches distances by at most 1 / (smallest radius), so a point within
  // `margin` of the ellipsoid has a normalised distance of at most 1 + margin / (smallest radius).
  const ix = P[o + INVERSE_RADII];
  const iy = P[o + INVERSE_RADII + 1];
  const iz = P[o + INVERSE_RADII + 2];
  const stretch = Math.max(ix, iy, iz);
  const rho = Math.sqrt((qx * ix) ** 2 + (qy * iy) ** 2 + (qz * iz) ** 2);
  return rho <= 1 + margin * stretch;
}

/** Copies contractions into `out` clamped to 0..1; throws, naming the muscle and changing nothing, if one is not finite. */
function clampContractions(muscles: readonly Muscle[], contractions: ArrayLike<number>, out: Float64Array | Float32Array | number[]): void {
  if (contractions.length !== muscles.length) {
    throw new Error(`contractions: the rig has ${muscles.length} muscles, got ${contractions.length} contractions`);
  }
  for (let m = 0; m < muscles.length; m++) {
    const c = contractions[m];
    if (typeof c !== 'number' || !Number.isFinite(c))
      throw new Error(`muscle ${muscles[m].name}: contraction must be a finite number, got ${String(c)}`);
  }
  for (let m = 0; m < muscles.length; m++) {
    const c = contractions[m];
    out[m] = c < 0 ? 0 : c > 1 ? 1 : c;
  }
}

/** One muscle's displacement field, for tools and tests; MuscleRig runs the same code per vertex. */
export class MuscleField {
  readonly muscle: Muscle;
  private readonly packed = new Float64Array(STRIDE);

  /** Throws, naming the muscle, if it is not valid (see validateMuscle). */
  constructor(muscle: Muscle) {
    validateMuscle(muscle);
    this.muscle = muscle;
    packMuscle(muscle, this.packed, 0);
  }

  /** Displacement at (x, y, z) for contraction `c` (not clamped) into `out[0..3]`; returns the falloff, 0 outside. */
  displace(c: number, x: number, y: number, z: number, out: Float64Array | number[]): number {
    return displace(this.packed, 0, c, x, y, z, out);
  }

  /** Whether a rest point at (x, y, z) is within `margin` of the zone (conservatively: may say yes too often). */
  reaches(x: number, y: number, z: number, margin: number): boolean {
    return reaches(this.packed, 0, margin, x, y, z);
  }

  /** The hinge a lid or jaw muscle turns its skin about, in the head's frame; null for linear and sphincter. */
  joint(): Vec3 | null {
    const P = this.packed;
    return P[TYPE] === LID || P[TYPE] === JAW ? [P[JOINT], P[JOINT + 1], P[JOINT + 2]] : null;
  }

  /** The axis a lid or jaw muscle turns about (the local x axis, unit); null for linear and sphincter. */
  axis(): Vec3 | null {
    const P = this.packed;
    return P[TYPE] === LID || P[TYPE] === JAW ? [P[FRAME], P[FRAME + 3], P[FRAME + 6]] : null;
  }
}

export interface MuscleRigOptions {
  /** Substeps of the combined contraction (the 2003 improvement the thesis cites); default 8. */
  substeps?: number;
  /**
   * How far outside a muscle's zone (metres) rest vertices still count as its candidates; default 0.005. It changes
   * only the speed: skin that slides farther than this from rest is checked against every active muscle.
   */
  margin?: number;
  /**
   * Contraction over which a muscle's hold on its skin grows from none to its full falloff; default 0.1, 0 holds fully
   * as soon as it contracts. Without it a muscle starting to contract would, in one frame, pin skin that other muscles
   * were moving to a target near rest: the solved skin would jump though no target does.
   */
  holdFadeIn?: number;
}

const MUSCLE_RIG_DEFAULTS: Readonly<Required<MuscleRigOptions>> = { substeps: 8, margin: 0.005, holdFadeIn: 0.1 };

/** How many rest vertices each muscle may move, as the editor and the app's outputs show them. */
export interface MuscleCandidates {
  name: string;
  type: Muscle['type'];
  candidates: number;
}

/**
 * A rig's muscles over one skin: candidates chosen once from rest geometry (so one rig works at every mesh
 * resolution), then `compute()` turns contractions into the solver's targets and weights, allocating nothing.
 */
export class MuscleRig {
  readonly vertexCount: number;
  readonly substeps: number;
  readonly margin: number;
  readonly holdFadeIn: number;
  /** Candidate vertices per muscle, in the rig's muscle order. */
  readonly candidateCounts: Uint32Array;
  /** Muscles with a contraction above 0 in the last compute(). */
  lastActive = 0;
  /** Vertices the last compute() integrated (candidates of an active muscle). */
  lastReached = 0;
  /** Vertices the last compute() gave a muscle constraint (weight above 0). */
  lastHeld = 0;
  /** Farthest any target of the last compute() lies from rest (metres). */
  lastLargestMove = 0;
  private readonly rest: Float32Array;
  private readonly muscleList: Muscle[];
  private readonly packed: Float64Array;
  private readonly candidateLists: Uint32Array[];
  /**
   * Per muscle, per candidate (in candidate order): the falloff its brush's add spheres give at least, and the share
   * of its hold its remove spheres leave; null for a muscle without a brush.
   */
  private readonly brushAdd: (Float32Array | null)[];
  private readonly brushKeep: (Float32Array | null)[];
  /** The same, in the order of `vertexMuscles` (0 and 1 where no brush reaches). */
  private rowAdd: Float32Array = new Float32Array(0);
  private rowKeep: Float32Array = new Float32Array(0);
  /** 1 for a vertex some brush reaches (an add or keep in its row that is not 0 or 1). */
  private rowBrushed: Uint8Array = new Uint8Array(0);
  /** Muscles of vertex v (those it is a candidate of) are `vertexMuscles[vertexMuscleStart[v]..vertexMuscleStart[v+1]]`. */
  private readonly vertexMuscleStart: Uint32Array;
  private vertexMuscles: Uint32Array;
  // Scratch for compute(), allocated once.
  private readonly contraction: Float64Array;
  private readonly stepContraction: Float64Array;
  private readonly holdScale: Float64Array;
  private readonly active: Uint32Array;
  private readonly marked: Uint8Array;
  private readonly reached: Uint32Array;
  private readonly step = new Float64Array(3);
  private readonly turns: TurnCache;

  /** Throws if the rest positions, a muscle (naming it) or an option is not valid. */
  constructor(rest: Float32Array, muscles: readonly Muscle[], options: MuscleRigOptions = {}) {
    if (rest.length % 3 !== 0) throw new Error(`rest positions: ${rest.length} numbers is not a whole number of xyz triples`);
    for (let i = 0; i < rest.length; i++) {
      if (!Number.isFinite(rest[i]))
        throw new Error(`rest positions: vertex ${Math.floor(i / 3)} has a non-finite coordinate (${rest[i]})`);
    }
    const o = { ...MUSCLE_RIG_DEFAULTS, ...options };
    if (!Number.isInteger(o.substeps) || o.substeps < 1 || o.substeps > 64)
      throw new Error(`substeps must be a whole number from 1 to 64, got ${o.substeps}`);
    if (!Number.isFinite(o.margin) || o.margin < 0)
      throw new Error(`margin must be a finite number of metres, at least 0, got ${o.margin}`);
    if (!Number.isFinite(o.holdFadeIn) || o.holdFadeIn < 0 || o.holdFadeIn > 1)
      throw new Error(`holdFadeIn must be a number from 0 to 1, got ${o.holdFadeIn}`);
    for (const m of muscles) validateMuscle(m);
    this.substeps = o.substeps;
    this.margin = o.margin;
    this.holdFadeIn = o.holdFadeIn;
    this.rest = Float32Array.from(rest);
    const n = rest.length / 3;
    const count = muscles.length;
    this.vertexCount = n;
    this.muscleList = [...muscles];
    this.packed = new Float64Array(count * STRIDE);
    this.candidateLists = new Array<Uint32Array>(count);
    this.brushAdd = new Array<Float32Array | null>(count).fill(null);
    this.brushKeep = new Array<Float32Array | null>(count).fill(null);
    this.candidateCounts = new Uint32Array(count);
    for (let m = 0; m < count; m++) this.place(m, muscles[m]);
    this.vertexMuscleStart = new Uint32Array(n + 1);
    this.vertexMuscles = new Uint32Array(0);
    this.indexByVertex();
    this.contraction = new Float64Array(count);
    this.stepContraction = new Float64Array(count);
    this.holdScale = new Float64Array(count);
    this.active = new Uint32Array(count);
    this.marked = new Uint8Array(n);
    this.reached = new Uint32Array(n);
    this.turns = { vertex: new Int32Array(count), falloff: new Float64Array(count), turn: new Float64Array(2 * count) };
  }

  /** The rig's muscles, in the order contractions are given. */
  get muscles(): readonly Muscle[] {
    return this.muscleList;
  }

  /** Candidate vertices of muscle `index` (a view; do not change it). */
  candidates(index: number): Uint32Array {
    return this.candidateLists[index];
  }

  /** Per-muscle candidate counts with names, for display. */
  candidateReport(): MuscleCandidates[] {
    return this.muscleList.map((m, i) => ({ name: m.name, type: m.type, candidates: this.candidateCounts[i] }));
  }

  /** Replaces muscle `index` (an editor dragging it) and re-chooses its candidates; throws, changing nothing, if invalid. */
  setMuscle(index: number, muscle: Muscle): void {
    if (!Number.isInteger(index) || index < 0 || index >= this.muscleList.length)
      throw new Error(`muscle index ${index} is not one of the ${this.muscleList.length} muscles`);
    validateMuscle(muscle);
    this.place(index, muscle);
    this.indexByVertex();
  }

  /**
   * Writes the solver's muscle inputs for per-muscle contractions (clamped to 0..1; a non-finite one throws, naming
   * its muscle, before anything is written). Returns how many vertices are held. Allocates nothing.
   *
   * The 2003 improvement the thesis cites (Waters muscles acting together): instead of each muscle's full contraction
   * on top of the others, every active muscle moves the skin a 1/substeps share at a time, its field evaluated where
   * the skin is now, so skin that slides out of one zone (or into another) is pulled less (or more) from then on, and
   * gradually. A vertex's weight is the sum of the active muscles' falloffs at rest (capped at 1; each scaled by
   * contraction / holdFadeIn below holdFadeIn); its normal weight sums each falloff times the muscle's normalWeight (1
   * for lid and jaw, which carry the skin bodily). Vertices no active muscle reaches keep weight 0 and target = rest.
   *
   * A vertex is integrated through the muscles it is a candidate of (those within `margin` of it at rest) while it is
   * within `margin` of its rest position, where it cannot be in any other zone, and through every active muscle once
   * it has slid farther: the result is that of asking every muscle everywhere, only faster.
   */
  compute(contractions: ArrayLike<number>, out: MuscleInputs): number {
    const n = this.vertexCount;
    const { targets, weights, normalWeights } = out;
    if (targets.length !== 3 * n || weights.length !== n || normalWeights.length !== n) {
      throw new Error(
        `muscle outputs must hold ${n} vertices (targets ${3 * n}, weights ${n}, ` +
          `normalWeights ${n}), got ${targets.length}, ${weights.length}, ${normalWeights.length}`,
      );
    }
    clampContractions(this.muscleList, contractions, this.contraction);
    const turns = this.turns;
    // The turns found in the last compute were for its contractions.
    turns.vertex.fill(-1);
    const rest = this.rest;
    targets.set(rest);
    weights.fill(0);
    normalWeights.fill(0);

    const P = this.packed;
    const S = this.substeps;
    const fadeIn = this.holdFadeIn;
    const stepContraction = this.stepContraction;
    const holdScale = this.holdScale;
    let activeCount = 0;
    for (let m = 0; m < this.muscleList.length; m++) {
      const c = this.contraction[m];
      // A contraction of c / S is a 1/S share of the pull, and of the turn, of the linear and rotation fields alike;
      // 0 marks a muscle that takes no part.
      stepContraction[m] = c / S;
      holdScale[m] = fadeIn > 0 && c < fadeIn ? c / fadeIn : 1;
      if (c > 0) this.active[activeCount++] = m;
    }

    // The vertices some active muscle reaches at rest; no other vertex can move.
    let reachedCount = 0;
    const marked = this.marked;
    const reached = this.reached;
    for (let a = 0; a < activeCount; a++) {
      const list = this.candidateLists[this.active[a]];
      for (let j = 0; j < list.length; j++) {
        const v = list[j];
        if (marked[v] === 0) {
          marked[v] = 1;
          reached[reachedCount++] = v;
        }
      }
    }

    const rowStart = this.vertexMuscleStart;
    const row = this.vertexMuscles;
    const rowAdd = this.rowAdd;
    const rowKeep = this.rowKeep;
    const rowBrushed = this.rowBrushed;
    const step = this.step;
    const marginSquared = this.margin * this.margin;
    let held = 0;
    let largestMoveSquared = 0;
    for (let r = 0; r < reachedCount; r++) {
      const v = reached[r];
      marked[v] = 0;
      const i = 3 * v;
      const j0 = rowStart[v];
      const j1 = rowStart[v + 1];
      let x = rest[i];
      let y = rest[i + 1];
      let z = rest[i + 2];
      let weight = 0;
      let normalWeight = 0;
      for (let k = 0; k < S; k++) {
        let sx = 0;
        let sy = 0;
        let sz = 0;
        const moved = (x - rest[i]) ** 2 + (y - rest[i + 1]) ** 2 + (z - rest[i + 2]) ** 2;
        if (moved <= marginSquared) {
          // Within `margin` of its rest position the skin can only be in the zones of muscles it is a candidate of.
          for (let j = j0; j < j1; j++) {
            const m = row[j];
            const c = stepContraction[m];
            if (c === 0) continue;
            const o = m * STRIDE;
            let falloff = displaceVertex(P, o, m, v, c, x, y, z, step, rest[i], rest[i + 1], rest[i + 2], turns);
            if (rowAdd[j] !== 0 || rowKeep[j] !== 1) {
              falloff = brushed(falloff, rowAdd[j], rowKeep[j]);
              displaceAtFalloff(P, o, c * falloff, x, y, z, step, rest[i], rest[i + 1], rest[i + 2]);
            }
            if (k === 0 && falloff > 0) {
              const hold = falloff * holdScale[m];
              weight += hold;
              normalWeight += hold * P[o + NORMAL_SHARE];
            }
            sx += step[0];
            sy += step[1];
            sz += step[2];
          }
        } else {
          // Slid farther: it may have entered any zone, so every active muscle is asked (most reject at their bound).
          const anyBrush = rowBrushed[v] === 1;
          for (let a = 0; a < activeCount; a++) {
            const m = this.active[a];
            const falloff = displaceVertex(
              P,
              m * STRIDE,
              m,
              v,
              stepContraction[m],
              x,
              y,
              z,
              step,
              rest[i],
              rest[i + 1],
              rest[i + 2],
              turns,
            );
            // A brush on this vertex for this muscle (found in its row; rows are short) sets the falloff here too.
            for (let j = anyBrush ? j0 : j1; j < j1; j++) {
              if (row[j] !== m) continue;
              if (rowAdd[j] !== 0 || rowKeep[j] !== 1)
                displaceAtFalloff(
                  P,
                  m * STRIDE,
                  stepContraction[m] * brushed(falloff, rowAdd[j], rowKeep[j]),
                  x,
                  y,
                  z,
                  step,
                  rest[i],
                  rest[i + 1],
                  rest[i + 2],
                );
              break;
            }
            sx += step[0];
            sy += step[1];
            sz += step[2];
          }
        }
        // Outside every active zone at rest: nothing moves it, now or later.
        if (k === 0 && weight === 0) break;
        x += sx;
        y += sy;
        z += sz;
      }
      if (weight === 0) continue;
      held++;
      targets[i] = x;
      targets[i + 1] = y;
      targets[i + 2] = z;
      weights[v] = weight < 1 ? weight : 1;
      normalWeights[v] = normalWeight < 1 ? normalWeight : 1;
      const moveSquared = (x - rest[i]) ** 2 + (y - rest[i + 1]) ** 2 + (z - rest[i + 2]) ** 2;
      if (moveSquared > largestMoveSquared) largestMoveSquared = moveSquared;
    }
    this.lastActive = activeCount;
    this.lastReached = reachedCount;
    this.lastHeld = held;
    this.lastLargestMove = Math.sqrt(largestMoveSquared);
    return held;
  }

  /** Lists, per vertex, the muscles it is a candidate of (CSR), so compute() visits only those. */
  private indexByVertex(): void {
    const n = this.vertexCount;
    const start = this.vertexMuscleStart;
    start.fill(0);
    for (const list of this.candidateLists) for (let j = 0; j < list.length; j++) start[list[j] + 1]++;
    for (let v = 0; v < n; v++) start[v + 1] += start[v];
    const muscles = new Uint32Array(start[n]);
    const add = new Float32Array(start[n]);
    const keep = new Float32Array(start[n]).fill(1);
    const fill = start.slice(0, n);
    for (let m = 0; m < this.candidateLists.length; m++) {
      const list = this.candidateLists[m];
      const a = this.brushAdd[m];
      const k = this.brushKeep[m];
      for (let j = 0; j < list.length; j++) {
        const at = fill[list[j]]++;
        muscles[at] = m;
        if (a && k) {
          add[at] = a[j];
          keep[at] = k[j];
        }
      }
    }
    const brushed = new Uint8Array(n);
    for (let v = 0; v < n; v++) for (let j = start[v]; j < start[v + 1]; j++) if (add[j] !== 0 || keep[j] !== 1) brushed[v] = 1;
    this.vertexMuscles = muscles;
    this.rowAdd = add;
    this.rowKeep = keep;
    this.rowBrushed = brushed;
  }

  /** Packs muscle `m` and chooses its candidates from the rest positions. */
  private place(m: number, muscle: Muscle): void {
    const P = this.packed;
    const o = m * STRIDE;
    packMuscle(muscle, P, o);
    const X = this.rest;
    const n = X.length / 3;
    const add = muscle.brush?.add ?? [];
    const remove = muscle.brush?.remove ?? [];
    // Skin in an add sphere is a candidate wherever the muscle's zone is.
    const painted = (x: number, y: number, z: number): number => {
      let w = 0;
      for (const s of add) w = Math.max(w, sphereWeight(s, x, y, z));
      return w;
    };
    const candidate = (v: number): boolean =>
      reaches(P, o, this.margin, X[3 * v], X[3 * v + 1], X[3 * v + 2]) ||
      (add.length > 0 && painted(X[3 * v], X[3 * v + 1], X[3 * v + 2]) > 0);
    let count = 0;
    for (let v = 0; v < n; v++) if (candidate(v)) count++;
    const list = new Uint32Array(count);
    count = 0;
    for (let v = 0; v < n; v++) if (candidate(v)) list[count++] = v;
    this.candidateLists[m] = list;
    this.candidateCounts[m] = count;
    this.muscleList[m] = muscle;
    if (add.length === 0 && remove.length === 0) {
      this.brushAdd[m] = null;
      this.brushKeep[m] = null;
      return;
    }
    const a = new Float32Array(count);
    const k = new Float32Array(count).fill(1);
    for (let j = 0; j < count; j++) {
      const v = list[j];
      const [x, y, z] = [X[3 * v], X[3 * v + 1], X[3 * v + 2]];
      if (add.length > 0) a[j] = painted(x, y, z);
      for (const s of remove) k[j] = Math.min(k[j], 1 - sphereWeight(s, x, y, z));
    }
    this.brushAdd[m] = a;
    this.brushKeep[m] = k;
  }
}

/**
 * One-shot form of MuscleRig: builds the rig and computes once (use a MuscleRig to compute every frame). Returns how
 * many vertices are held.
 */
export function computeMuscleTargets(
  rest: Float32Array,
  muscles: readonly Muscle[],
  contractions: ArrayLike<number>,
  out: MuscleInputs,
  options: MuscleRigOptions = {},
): number {
  return new MuscleRig(rest, muscles, options).compute(contractions, out);
}
