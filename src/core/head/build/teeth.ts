/**
 * Procedural dental arches: per arch sixteen crowns (incisors, canines, premolars, three molars a side) of
 * typical adult sizes set along an arch curve, and a gum band with papillae between them. The arch curve and the
 * occlusal plane are fitted to where the base mesh's low-poly teeth sit, so that the crowns fit inside its lips.
 */
import type { TriGeometry } from './head-spec';

const MM = 0.001;

/**
 * One tooth type's crown, millimetres: mesiodistal width, labiolingual depth, crown height, its shape, and how far
 * its edge stops short of its neighbours' (the upper lateral incisors' edges sit a little higher than the centrals').
 */
interface ToothSpec {
  width: number;
  depth: number;
  height: number;
  kind: 'incisor' | 'canine' | 'premolar' | 'molar';
  short?: number;
}

/** Typical adult crowns from the midline back (central incisor to third molar). */
const UPPER_TEETH: ToothSpec[] = [
  { width: 8.5, depth: 7, height: 10.5, kind: 'incisor' },
  { width: 6.5, depth: 6, height: 9, kind: 'incisor', short: 0.8 },
  { width: 7.5, depth: 8, height: 10, kind: 'canine' },
  { width: 7, depth: 9, height: 8, kind: 'premolar' },
  { width: 6.5, depth: 9, height: 7.5, kind: 'premolar' },
  { width: 10, depth: 11, height: 7, kind: 'molar' },
  { width: 9, depth: 10.5, height: 6.5, kind: 'molar' },
  { width: 8.5, depth: 10, height: 6, kind: 'molar' },
];
const LOWER_TEETH: ToothSpec[] = [
  { width: 5.3, depth: 5.8, height: 9, kind: 'incisor' },
  { width: 5.9, depth: 6.2, height: 9.5, kind: 'incisor' },
  { width: 7, depth: 7.5, height: 10.5, kind: 'canine' },
  { width: 7, depth: 7.5, height: 8.5, kind: 'premolar' },
  { width: 7, depth: 8, height: 8, kind: 'premolar' },
  { width: 11, depth: 10.5, height: 7.5, kind: 'molar' },
  { width: 10.5, depth: 10, height: 7, kind: 'molar' },
  { width: 10, depth: 9.5, height: 6.5, kind: 'molar' },
];

/** How an arch is laid out, millimetres. */
export interface ArchOptions {
  /** How far the labial/buccal faces sit inside the fitted outline of the base mesh's teeth. */
  inset: number;
  /** How far the incisal edges reach past the occlusal plane (the overbite is the sum of both arches'). */
  incisorOverlap: number;
  /** Points around each crown's cross-section, and rows from the gum to the biting edge. */
  segments: number;
  /** Gum samples along each crown. */
  gumSamples: number;
}

/** The arches of the default head. */
const ARCH_DEFAULTS: ArchOptions = { inset: 1.8, incisorOverlap: 1.4, segments: 20, gumSamples: 6 };

/** A built arch: the crowns as one geometry, the gum as another (metres, head space). */
export interface DentalArch {
  teeth: TriGeometry;
  gums: TriGeometry;
}

/** A plane curve in x-z (the arch seen from above), sampled densely from the midline to one side. */
export interface ArchCurve {
  x: number[];
  z: number[];
  /** Arc length at each sample. */
  s: number[];
}

/**
 * The outline of a row of teeth seen from above, from the midline round to the back on the +x side: the outermost
 * vertex in each of a fan of directions about a point in the middle of the arch, smoothed and resampled.
 */
export function fitArchOutline(positions: ArrayLike<number>, bins = 12): ArchCurve {
  const n = Math.floor(positions.length / 3);
  let minZ = Infinity;
  let maxZ = -Infinity;
  for (let i = 0; i < n; i++) {
    minZ = Math.min(minZ, positions[3 * i + 2]);
    maxZ = Math.max(maxZ, positions[3 * i + 2]);
  }
  // Seen from the back of the row, every direction forward of sideways meets the outline once.
  const cz = minZ;
  const best = Array.from({ length: bins }, () => ({ r: -1, x: 0, z: 0 }));
  let front = -Infinity;
  for (let i = 0; i < n; i++) {
    // Both sides count, mirrored onto +x: the outline is symmetric.
    const x = Math.abs(positions[3 * i]);
    const z = positions[3 * i + 2];
    const angle = Math.atan2(x, z - cz);
    const bin = Math.min(bins - 1, Math.floor((angle / (Math.PI / 2)) * bins));
    const r = Math.hypot(x, z - cz);
    if (r > best[bin].r) best[bin] = { r, x, z };
    front = Math.max(front, z);
  }
  const points = best.filter((b) => b.r >= 0);
  // The outline starts on the midline, at the front of the row.
  if (points.length === 0 || points[0].x > 1e-9) points.unshift({ r: 0, x: 0, z: front });
  const px = points.map((p) => p.x);
  const pz = points.map((p) => p.z);
  // A light neighbour average (ends fixed) takes out bin-to-bin jitter without pulling the outline in much.
  const sx = [...px];
  const sz = [...pz];
  for (let i = 1; i + 1 < px.length; i++) {
    px[i] = (sx[i - 1] + 4 * sx[i] + sx[i + 1]) / 6;
    pz[i] = (sz[i - 1] + 4 * sz[i] + sz[i + 1]) / 6;
  }
  // Catmull-Rom through the points (mirrored across the midline at the front, straight on at the back): smooth,
  // so that normals along it turn gradually.
  const at = (q: number[], i: number, mirror: number): number =>
    i < 0 ? mirror * q[-i] : i >= q.length ? 2 * q[q.length - 1] - q[2 * q.length - 2 - i] : q[i];
  const curve: ArchCurve = { x: [px[0]], z: [pz[0]], s: [0] };
  for (let i = 1; i < px.length; i++) {
    for (let k = 1; k <= 16; k++) {
      const t = k / 16;
      const spline = (q: number[], mirror: number): number => {
        const [p0, p1, p2, p3] = [at(q, i - 2, mirror), q[i - 1], q[i], at(q, i + 1, mirror)];
        return 0.5 * (2 * p1 + (-p0 + p2) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t * t + (-p0 + 3 * p1 - 3 * p2 + p3) * t * t * t);
      };
      const x = spline(px, -1);
      const z = spline(pz, 1);
      const last = curve.x.length - 1;
      curve.s.push(curve.s[last] + Math.hypot(x - curve.x[last], z - curve.z[last]));
      curve.x.push(x);
      curve.z.push(z);
    }
  }
  return curve;
}

/** A point on the curve at arc length `s` with its outward normal (in x-z); past the end, straight on. */
function pointAt(curve: ArchCurve, s: number): { x: number; z: number; nx: number; nz: number } {
  const { x, z } = curve;
  const position = (at: number): [number, number] => {
    // Before the midline, the mirror image; past the end, straight on.
    if (at < 0) {
      const [mx, mz] = position(-at);
      return [-mx, mz];
    }
    const last = x.length - 1;
    let i = 0;
    while (i < last - 1 && curve.s[i + 1] < at) i++;
    const t = (at - curve.s[i]) / (curve.s[i + 1] - curve.s[i] || 1);
    return [x[i] + t * (x[i + 1] - x[i]), z[i] + t * (z[i + 1] - z[i])];
  };
  const [px, pz] = position(s);
  // The tangent over a couple of millimetres, so that the normal turns smoothly.
  const [ax, az] = position(s - 0.002);
  const [bx, bz] = position(s + 0.002);
  const length = Math.hypot(bx - ax, bz - az) || 1;
  // Walking from the midline toward +x (seen from above, +z forward), (-tz, tx) points out of the arch.
  return { x: px, z: pz, nx: -(bz - az) / length, nz: (bx - ax) / length };
}

/** The occlusal plane's height along the arch as y = a + b z, from where the two rows of base-mesh teeth meet. */
export function fitOcclusalPlane(upper: ArrayLike<number>, lower: ArrayLike<number>, bins = 8): { a: number; b: number } {
  const range = (p: ArrayLike<number>) => {
    let lo = Infinity;
    let hi = -Infinity;
    for (let i = 2; i < p.length; i += 3) {
      lo = Math.min(lo, p[i]);
      hi = Math.max(hi, p[i]);
    }
    return [lo, hi];
  };
  const [z0, z1] = range(upper);
  const binOf = (z: number) => Math.min(bins - 1, Math.max(0, Math.floor(((z - z0) / (z1 - z0 || 1)) * bins)));
  const bottom = new Array(bins).fill(Infinity);
  const top = new Array(bins).fill(-Infinity);
  for (let i = 0; i + 2 < upper.length; i += 3) bottom[binOf(upper[i + 2])] = Math.min(bottom[binOf(upper[i + 2])], upper[i + 1]);
  for (let i = 0; i + 2 < lower.length; i += 3) top[binOf(lower[i + 2])] = Math.max(top[binOf(lower[i + 2])], lower[i + 1]);
  const zs: number[] = [];
  const ys: number[] = [];
  for (let k = 0; k < bins; k++) {
    if (!Number.isFinite(bottom[k]) || !Number.isFinite(top[k])) continue;
    zs.push(z0 + ((k + 0.5) / bins) * (z1 - z0));
    ys.push((bottom[k] + top[k]) / 2);
  }
  const m = zs.length;
  const mz = zs.reduce((a, b) => a + b, 0) / m;
  const my = ys.reduce((a, b) => a + b, 0) / m;
  let szz = 0;
  let szy = 0;
  for (let k = 0; k < m; k++) {
    szz += (zs[k] - mz) ** 2;
    szy += (zs[k] - mz) * (ys[k] - my);
  }
  const b = szz > 0 ? szy / szz : 0;
  return { a: my - b * mz, b };
}

/**
 * Baked occlusion (a grey vertex colour the material multiplies): the mouth's inside gets little light, so the back
 * teeth, the tongue side and the necks at the gum are darker than the front teeth's faces. `s` is the arc length
 * from the midline (metres), `inner` 0 on the lip side to 1 on the tongue side, `neck` 0 at the gum line to 1 away
 * from it.
 */
function occlusion(s: number, inner: number, neck: number): number {
  const t = Math.min(1, Math.max(0, (s - 0.012) / 0.04));
  const back = 1 - 0.5 * t * t * (3 - 2 * t);
  return back * (1 - 0.2 * inner) * (0.8 + 0.2 * Math.min(1, Math.max(0, neck)));
}

/** Growing lists of a triangle geometry. */
class Builder {
  positions: number[] = [];
  indices: number[] = [];
  uvs: number[] = [];
  colors: number[] = [];
  vertex(x: number, y: number, z: number, u: number, v: number, shade: number): number {
    this.positions.push(x, y, z);
    this.uvs.push(u, v);
    this.colors.push(shade, shade, shade);
    return this.positions.length / 3 - 1;
  }
  /** A quad a b c d, as two triangles. */
  quad(a: number, b: number, c: number, d: number): void {
    this.indices.push(a, b, c, a, c, d);
  }
  /** Smooth normals (area-weighted face normals), and every triangle wound to face along them from `inside`. */
  finish(inside: (i: number) => [number, number, number]): TriGeometry {
    const P = this.positions;
    const I = this.indices;
    // Orient each triangle away from its first vertex's interior point (the crown's axis, the gum's root line).
    for (let t = 0; t < I.length; t += 3) {
      const [a, b, c] = [I[t], I[t + 1], I[t + 2]];
      const n = cross(P, a, b, c);
      const o = inside(a);
      const out = [P[3 * a] - o[0], P[3 * a + 1] - o[1], P[3 * a + 2] - o[2]];
      if (n[0] * out[0] + n[1] * out[1] + n[2] * out[2] < 0) {
        I[t + 1] = c;
        I[t + 2] = b;
      }
    }
    const normals = new Float32Array(P.length);
    for (let t = 0; t < I.length; t += 3) {
      const n = cross(P, I[t], I[t + 1], I[t + 2]);
      for (const v of [I[t], I[t + 1], I[t + 2]]) for (let k = 0; k < 3; k++) normals[3 * v + k] += n[k];
    }
    for (let v = 0; v < normals.length; v += 3) {
      const l = Math.hypot(normals[v], normals[v + 1], normals[v + 2]) || 1;
      for (let k = 0; k < 3; k++) normals[v + k] /= l;
    }
    return {
      positions: Float32Array.from(P),
      normals,
      uvs: Float32Array.from(this.uvs),
      colors: Float32Array.from(this.colors),
      indices: Uint32Array.from(I),
    };
  }
}

function cross(P: number[], a: number, b: number, c: number): [number, number, number] {
  const u = [P[3 * b] - P[3 * a], P[3 * b + 1] - P[3 * a + 1], P[3 * b + 2] - P[3 * a + 2]];
  const w = [P[3 * c] - P[3 * a], P[3 * c + 1] - P[3 * a + 1], P[3 * c + 2] - P[3 * a + 2]];
  return [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
}

/**
 * Half-width, half-depth (fractions of the crown's) and labial set-back (mm) of a crown's cross-section at `v`
 * (0 at the gum line, 1 at the biting edge): incisors thin to a chisel edge, canines narrow to a cusp, back teeth
 * keep a broad table. The sections below the gum line (v < 0) narrow toward the root.
 */
function section(kind: ToothSpec['kind'], v: number): { a: number; b: number; back: number } {
  const bulge = 0.35 * (1 - 4 * v * (1 - v)); // the labial face is convex: set back at both ends
  const root = v < 0 ? 1 + 0.8 * v : 1;
  if (kind === 'incisor') {
    const a = v < 0.6 ? 0.72 + (0.28 * v) / 0.6 : 1 - 0.25 * ((v - 0.6) / 0.4) ** 3;
    const b = v < 0.25 ? 1 : 1 - 0.82 * ((v - 0.25) / 0.75) ** 1.3;
    return { a: a * root, b: b * root, back: bulge };
  }
  if (kind === 'canine') {
    const a = v < 0.5 ? 0.75 + (0.25 * v) / 0.5 : 1 - 0.7 * ((v - 0.5) / 0.5) ** 1.6;
    const b = v < 0.35 ? 1 : 1 - 0.65 * ((v - 0.35) / 0.65) ** 1.5;
    return { a: a * root, b: b * root, back: bulge };
  }
  const a = v < 0.55 ? 0.8 + (0.2 * v) / 0.55 : 1 - 0.22 * ((v - 0.55) / 0.45) ** 2;
  const b = v < 0.45 ? 0.85 + (0.15 * v) / 0.45 : 1 - 0.2 * ((v - 0.45) / 0.55) ** 2;
  return { a: a * root, b: b * root, back: 0.6 * bulge };
}

/** Rows of a crown, from inside the gum (negative) to the biting edge. */
const ROWS = [-0.3, 0, 0.2, 0.4, 0.58, 0.74, 0.87, 0.96, 1];

/**
 * Builds one arch in metres. `outline` is the fitted outline of the base mesh's row of teeth (metres), `occlusal`
 * the plane the rows meet on (y = a + b z, metres), `up` +1 for the upper arch (crowns point down) and -1 for the
 * lower.
 */
export function buildArch(
  outline: ArchCurve,
  occlusal: { a: number; b: number },
  up: 1 | -1,
  options: ArchOptions = ARCH_DEFAULTS,
): DentalArch {
  const specs = up > 0 ? UPPER_TEETH : LOWER_TEETH;
  const S = options.segments;
  const teeth = new Builder();
  const centres: [number, number, number][] = [];
  // The teeth's labial faces run along the outline set in by `inset`; arc lengths are measured along it.
  const labial = insetCurve(outline, options.inset * MM);
  const starts: number[] = [0];
  for (const t of specs) starts.push(starts[starts.length - 1] + t.width * MM);

  for (const side of [1, -1]) {
    specs.forEach((spec, k) => {
      const arc = (starts[k] + starts[k + 1]) / 2;
      const mid = pointAt(labial, arc);
      const tx = -mid.nz * side;
      const tz = mid.nx;
      const nx = mid.nx * side;
      const nz = mid.nz;
      const cx = mid.x * side;
      // Front teeth reach past the plane so that the upper ones overlap the lower ones; back teeth meet on it.
      const overlap = spec.kind === 'incisor' ? options.incisorOverlap : spec.kind === 'canine' ? 0.7 * options.incisorOverlap : 0.15;
      const tipY = occlusal.a + occlusal.b * mid.z - up * (overlap - (spec.short ?? 0)) * MM;
      const w = (spec.width * MM) / 2;
      const d = (spec.depth * MM) / 2;
      const h = spec.height * MM;
      const first = teeth.positions.length / 3;
      const ring = (v: number, lift = (_c: number, _s: number) => 0): void => {
        const { a, b, back } = section(spec.kind, v);
        for (let j = 0; j < S; j++) {
          const phi = (2 * Math.PI * j) / S;
          const c = Math.cos(phi);
          const s = Math.sin(phi);
          // A rounded box (superellipse, exponent 2.6): flat faces, round corners.
          const e = 2 / 2.6;
          const along = a * w * Math.sign(c) * Math.abs(c) ** e;
          const across = b * d * Math.sign(s) * Math.abs(s) ** e - d * b - back * MM;
          const y = tipY + up * (1 - v) * h - up * lift(c, s) * h;
          teeth.vertex(cx + along * tx + across * nx, y, mid.z + along * tz + across * nz, j / S, v, occlusion(arc, (1 - s) / 2, v / 0.3));
        }
      };
      for (const v of ROWS) {
        if (v < 1 || spec.kind === 'incisor' || spec.kind === 'canine') ring(v);
        // Back teeth: cusps rise at the table's corners (molars) or at its two sides (premolars).
        else ring(v, (c, s) => -0.06 * (spec.kind === 'molar' ? 1 - Math.abs(Math.sin(2 * Math.atan2(s, c))) : Math.abs(c)));
      }
      for (let r = 0; r + 1 < ROWS.length; r++) {
        for (let j = 0; j < S; j++) {
          const a = first + r * S + j;
          const b = first + r * S + ((j + 1) % S);
          teeth.quad(a, b, b + S, a + S);
        }
      }
      // Caps: the root end (hidden in the gum) and the biting surface, its middle a little sunk on back teeth.
      const axis = section(spec.kind, 1);
      const axisAcross = -d * axis.b - axis.back * MM;
      const root = teeth.vertex(
        cx + axisAcross * nx,
        tipY + up * (1 - ROWS[0]) * h,
        mid.z + axisAcross * nz,
        0.5,
        ROWS[0],
        occlusion(arc, 0.5, 0),
      );
      const sink = spec.kind === 'molar' || spec.kind === 'premolar' ? 0.1 : 0;
      const tip = teeth.vertex(
        cx + axisAcross * nx,
        tipY + up * sink * h,
        mid.z + axisAcross * nz,
        0.5,
        1,
        occlusion(arc, 0.5, 1 - sink * 4),
      );
      const last = first + (ROWS.length - 1) * S;
      for (let j = 0; j < S; j++) {
        teeth.indices.push(root, first + j, first + ((j + 1) % S));
        teeth.indices.push(tip, last + j, last + ((j + 1) % S));
      }
      const axisMid = section(spec.kind, 0.4);
      const centre: [number, number, number] = [
        cx - (d * axisMid.b + axisMid.back * MM) * nx,
        tipY + up * 0.5 * h,
        mid.z - (d * axisMid.b + axisMid.back * MM) * nz,
      ];
      for (let i = first; i <= tip; i++) centres[i] = centre;
    });
  }
  const teethGeometry = teeth.finish((i) => centres[i]);
  return { teeth: teethGeometry, gums: buildGum(labial, specs, starts, occlusal, up, options) };
}

/** The curve moved inward (against its outward normal) by `by`. */
function insetCurve(curve: ArchCurve, by: number): ArchCurve {
  const out: ArchCurve = { x: [], z: [], s: [] };
  for (let i = 0; i < curve.x.length; i++) {
    const p = pointAt(curve, curve.s[i]);
    const x = Math.max(0, curve.x[i] - by * p.nx);
    const z = curve.z[i] - by * p.nz;
    const last = out.x.length - 1;
    out.s.push(last < 0 ? 0 : out.s[last] + Math.hypot(x - out.x[last], z - out.z[last]));
    out.x.push(x);
    out.z.push(z);
  }
  return out;
}

/**
 * The gum: a band round the necks of the crowns, from a scalloped edge just outside them (rising to a papilla between
 * neighbours) up and over toward the root on both sides, across the midline from the back of one side to the other.
 */
function buildGum(
  labial: ArchCurve,
  specs: ToothSpec[],
  starts: number[],
  occlusal: { a: number; b: number },
  up: 1 | -1,
  options: ArchOptions,
): TriGeometry {
  const gum = new Builder();
  const K = options.gumSamples;
  const end = starts[starts.length - 1] + 0.6 * MM;
  // Samples along one side: K per crown, then one past the last crown's back.
  const along: { s: number; tooth: number; frac: number }[] = [];
  specs.forEach((_, k) => {
    for (let i = 0; i < K; i++) along.push({ s: starts[k] + ((starts[k + 1] - starts[k]) * i) / K, tooth: k, frac: i / K });
  });
  along.push({ s: end, tooth: specs.length - 1, frac: 1 });
  // Profile across the band: (outward offset from the labial line in mm, or from the lingual line; height above
  // the gum line in mm). The first and last are the edges against the crowns.
  const profile: { lingual: boolean; out: number; rise: number; edge?: boolean }[] = [
    { lingual: false, out: 0.45, rise: 0, edge: true },
    { lingual: false, out: 0.9, rise: 1.2 },
    { lingual: false, out: 1.1, rise: 3.5 },
    { lingual: false, out: 0.7, rise: 6.5 },
    { lingual: false, out: -1, rise: 7.5 },
    { lingual: true, out: 0.8, rise: 6 },
    { lingual: true, out: 1.1, rise: 3 },
    { lingual: true, out: 0.9, rise: 1.2 },
    { lingual: true, out: 0.45, rise: 0, edge: true },
  ];
  const rows: number[][] = [];
  const inner: [number, number, number][] = [];
  const ordered = [
    ...along
      .slice(1)
      .reverse()
      .map((a) => ({ ...a, side: -1 })),
    ...along.map((a) => ({ ...a, side: 1 })),
  ];
  for (const sample of ordered) {
    const spec = specs[sample.tooth];
    const next = specs[Math.min(sample.tooth + 1, specs.length - 1)];
    const prev = specs[Math.max(sample.tooth - 1, 0)];
    // Depth and crown height blend across a contact so that the band runs on smoothly.
    const blend = sample.frac < 0.5 ? 0.5 - sample.frac : sample.frac - 0.5;
    const other = sample.frac < 0.5 ? (sample.tooth === 0 ? spec : prev) : sample.tooth === specs.length - 1 ? spec : next;
    const mixD = spec.depth + (other.depth - spec.depth) * Math.max(0, blend - 0.25);
    const mixH = spec.height + (other.height - spec.height) * Math.max(0, blend - 0.25);
    const p = pointAt(labial, sample.s);
    const nx = p.nx * sample.side;
    const nz = p.nz;
    const x = p.x * sample.side;
    const overlap = spec.kind === 'incisor' ? options.incisorOverlap : spec.kind === 'canine' ? 0.7 * options.incisorOverlap : 0.15;
    const neck = occlusal.a + occlusal.b * p.z - up * (overlap - (spec.short ?? 0)) * MM + up * mixH * MM;
    // Papillae: the edge comes down toward the biting edge between crowns (about 3 mm in front, less at the back).
    const papilla = (spec.kind === 'molar' ? 1.6 : 2.8) * Math.abs(Math.cos(Math.PI * sample.frac)) ** 3;
    const row: number[] = [];
    for (const q of profile) {
      const across = q.lingual ? -mixD - q.out : q.out < 0 ? -mixD / 2 : q.out;
      const rise = q.edge ? -papilla : q.rise - (q.rise < 2 ? papilla * 0.4 : 0);
      const shade = occlusion(sample.s, q.lingual ? 1 : q.out < 0 ? 0.5 : 0, 1);
      row.push(gum.vertex(x + across * MM * nx, neck + up * rise * MM, p.z + across * MM * nz, sample.s / end, q.rise / 7.5, shade));
    }
    rows.push(row);
    inner.push([x - (mixD / 2) * MM * nx, neck - up * 2 * MM, p.z - (mixD / 2) * MM * nz]);
  }
  const centreOf: [number, number, number][] = [];
  for (let r = 0; r < rows.length; r++) for (const v of rows[r]) centreOf[v] = inner[r];
  for (let r = 0; r + 1 < rows.length; r++) {
    for (let c = 0; c + 1 < profile.length; c++) gum.quad(rows[r][c], rows[r][c + 1], rows[r + 1][c + 1], rows[r + 1][c]);
  }
  // Close both back ends behind the last molars.
  for (const r of [0, rows.length - 1]) {
    const centre = inner[r];
    const c = gum.vertex(centre[0], centre[1] + up * 3 * MM, centre[2], 0, 0.5, occlusion(end, 1, 1));
    // Faces out of the band's end: away from the next row in.
    centreOf[c] = inner[r === 0 ? 1 : rows.length - 2];
    for (let k = 0; k + 1 < profile.length; k++) gum.indices.push(c, rows[r][k], rows[r][k + 1]);
  }
  return gum.finish((i) => centreOf[i]);
}
