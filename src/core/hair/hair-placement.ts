/**
 * Where a head's eyebrows and eyelashes grow, found from its eye corners and its skin alone, so that any head gets
 * them: the brows in a band above each eye laid out in units of the eye's width (the usual proportions of a face),
 * the lashes along the lid margins, which are found where rays from the front stop meeting the lids' front and fall
 * into the eye's opening. Each hair is then anchored to the skin triangle under its root (see hair.ts). Seeded: the
 * same head gets the same hairs. Pure: no three.js, no DOM.
 */
import { clamp01 } from '../math3';
import { at, eyeFrame, findLidMargin, MARGIN_STEP } from './eye-frame';
import { FrontCaster, type FrontHit } from './front-caster';
import { ribbonTriangles, strandsAtRest, type HairStrands } from './hair';
import { mulberry32 } from '../random';
import type { Vec3 } from '../rig/rig-types';

/** The skin at rest: positions and normals (xyz per render vertex) and its triangles. */
export interface HairSurface {
  positions: ArrayLike<number>;
  normals: ArrayLike<number>;
  triangles: ArrayLike<number>;
}

/** An eyeball the lashes keep out of: its centre and radius, in the skin's frame. */
export interface HairEye {
  centre: Vec3;
  radius: number;
}

/** The eye corners hair is laid out from (metres, +y up, the face toward +z, the subject's left at +x). */
export interface HairLandmarks {
  'eye-inner-l': Vec3;
  'eye-outer-l': Vec3;
  'eye-inner-r': Vec3;
  'eye-outer-r': Vec3;
}

/** Points along one hair; its ribbon has two vertices at each. */
const POINTS = 5;
const VERTICES_PER_HAIR = 2 * POINTS;
const RIBBON = ribbonTriangles(POINTS);

/**
 * The brow's shape in units of the eye's width L, measured from the inner eye corner along the eye (u) and up (v):
 * from its head a little inside the inner corner to its tail past the outer one, its lower edge rising to the arch
 * two thirds of the way out and falling to the tail, thickest at the head and thin at the tail; the head and the tail
 * at about one height, the arch a quarter eye width above them (the usual proportions: the brow's lower edge about half
 * an eye width above the corners, its peak two thirds of the way out).
 */
const BROW = {
  hairs: 520,
  uStart: -0.12,
  uEnd: 1.22,
  lowHead: 0.52,
  lowArch: 0.64,
  lowTail: 0.52,
  archAt: 0.62,
  thickHead: 0.24,
  thickArch: 0.2,
  thickTail: 0.07,
  /** Hair length in L at the head and along the body, and the share each hair differs by. */
  lengthHead: 0.15,
  lengthBody: 0.24,
  lengthSpread: 0.35,
  /** Ribbon width at the root, in metres (tapering to a fifth at the tip). */
  width: 0.00011,
  /** Height over the skin at the root and at the tip, in metres: the hair lies on the skin, lifting a little. */
  liftRoot: 0.00004,
  liftTip: 0.0005,
  seed: 0x5eb0,
} as const;

/** Lash counts per eye, lengths in L, widths and the angles the lashes leave the lid at and curl to (degrees from forward). */
const LASHES = {
  upper: 140,
  lower: 30,
  upperLength: 0.26,
  lowerLength: 0.09,
  /** Ribbon width at the root, upper and lower lashes (m): wide enough that the dense roots make the lid's dark line. */
  width: 0.0003,
  lowerWidth: 0.00015,
  upperRootAngle: 22,
  upperTipAngle: 68,
  /** Lower lashes lie along the lid, down its front, standing off it by this much at the root and at the tip (m). */
  lowerLiftRoot: 0.0002,
  lowerLiftTip: 0.0007,
  /** How far the lash roots sit from the margin the rays find, in metres (rows spread over this much again). */
  /** Where along the eye (in eye widths from the inner corner) the lashes start. */
  start: 0.12,
  rootInset: 0.0001,
  rows: 0.0002,
  /** The least gap between a lash's root and an eyeball; the lid's margin itself tucks a little under the eye's surface. */
  eyeGap: 0.0002,
  seed: 0x1a5e,
} as const;

/** A hair laid out in world space at rest, before it is anchored in its triangle's frame. */
interface LaidHair {
  corners: [number, number, number];
  weights: [number, number, number];
  tangentEnds?: [number, number];
  pivot?: [number, number, number];
  vertices: Float32Array;
  shade: Float32Array;
}

function smooth(t: number): number {
  const c = clamp01(t);
  return c * c * (3 - 2 * c);
}

/** The surface's unit normal at a hit, interpolated from its vertex normals. */
function hitNormal(s: HairSurface, hit: FrontHit, out: number[]): void {
  const t = 3 * hit.triangle;
  let x = 0,
    y = 0,
    z = 0;
  const w = [hit.w0, hit.w1, hit.w2];
  for (let k = 0; k < 3; k++) {
    const v = 3 * s.triangles[t + k];
    x += w[k] * s.normals[v];
    y += w[k] * s.normals[v + 1];
    z += w[k] * s.normals[v + 2];
  }
  const n = Math.hypot(x, y, z) || 1;
  out[0] = x / n;
  out[1] = y / n;
  out[2] = z / n;
}

function anchor(s: HairSurface, hit: FrontHit): Pick<LaidHair, 'corners' | 'weights'> {
  const t = 3 * hit.triangle;
  return { corners: [s.triangles[t], s.triangles[t + 1], s.triangles[t + 2]], weights: [hit.w0, hit.w1, hit.w2] };
}

/** How far either side of a lash's root (in eye widths) the margin's vertices lie that set its tangent: about 3 mm. */
const TANGENT_REACH = 0.1;

/**
 * The skin vertices nearest two front-view points either side of a hair's root (`points`, xy pairs), for its tangent
 * (see HairStrands.tangentEnds); undefined where a point misses the skin, falls more than `reach` deeper or shallower
 * than the root (into an eye's opening), or both find one vertex.
 */
function tangentEndsAround(s: HairSurface, caster: FrontCaster, hit: FrontHit, points: number[], reach: number): LaidHair['tangentEnds'] {
  const probe: FrontHit = { triangle: 0, w0: 0, w1: 0, w2: 0, z: 0 };
  const found: number[] = [];
  for (let k = 0; k < 2; k++) {
    if (!caster.cast(points[2 * k], points[2 * k + 1], probe) || Math.abs(probe.z - hit.z) > reach) return undefined;
    const w = [probe.w0, probe.w1, probe.w2];
    found.push(s.triangles[3 * probe.triangle + (w[0] >= w[1] && w[0] >= w[2] ? 0 : w[1] >= w[2] ? 1 : 2)]);
  }
  return found[0] === found[1] ? undefined : [found[0], found[1]];
}

/** The centre of the eye nearest the front-view point (x, y), or undefined without eyes. */
function nearestEye(eyes: readonly HairEye[], x: number, y: number): [number, number, number] | undefined {
  let best: HairEye | undefined;
  for (const eye of eyes)
    if (!best || Math.hypot(eye.centre[0] - x, eye.centre[1] - y) < Math.hypot(best.centre[0] - x, best.centre[1] - y)) best = eye;
  return best ? [best.centre[0], best.centre[1], best.centre[2]] : undefined;
}

/** Writes a ribbon around the hair's centre line `line` (POINTS xyz), `across` a unit vector, tapering from `width`. */
function ribbon(line: number[], across: number[], width: number, shade: number, into: LaidHair): void {
  for (let p = 0; p < POINTS; p++) {
    const half = (width * (1 - (0.8 * p) / (POINTS - 1))) / 2;
    for (let side = 0; side < 2; side++) {
      const s = side === 0 ? -half : half;
      const o = 3 * (2 * p + side);
      into.vertices[o] = line[3 * p] + s * across[0];
      into.vertices[o + 1] = line[3 * p + 1] + s * across[1];
      into.vertices[o + 2] = line[3 * p + 2] + s * across[2];
      // Tips lighter than roots: a hair thins and lets light through toward its end.
      into.shade[2 * p + side] = shade * (1 + (0.35 * p) / (POINTS - 1));
    }
  }
}

function normalize(v: number[]): number[] {
  const n = Math.hypot(v[0], v[1], v[2]) || 1;
  return [v[0] / n, v[1] / n, v[2] / n];
}

function cross(a: number[], b: number[]): number[] {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

/** Shuffles in place (seeded), so that any prefix of the hairs is spread evenly over both sides. */
function shuffle<T>(list: T[], random: () => number): T[] {
  for (let i = list.length - 1; i > 0; i--) {
    const j = Math.floor(random() * (i + 1));
    [list[i], list[j]] = [list[j], list[i]];
  }
  return list;
}

/** The brow's lower edge and thickness (in eye widths) at `a` eye widths along from the inner corner. */
function browBand(a: number): { low: number; thick: number } {
  const s = (a - BROW.uStart) / (BROW.uEnd - BROW.uStart);
  const low =
    s <= BROW.archAt
      ? BROW.lowHead + (BROW.lowArch - BROW.lowHead) * smooth(s / BROW.archAt)
      : BROW.lowArch + (BROW.lowTail - BROW.lowArch) * smooth((s - BROW.archAt) / (1 - BROW.archAt));
  let thick =
    s <= 0.5
      ? BROW.thickHead + (BROW.thickArch - BROW.thickHead) * (s / 0.5)
      : BROW.thickArch + (BROW.thickTail - BROW.thickArch) * ((s - 0.5) / 0.5);
  // The head is rounded, not cut square.
  if (s < 0.06) thick *= Math.sqrt(Math.max(0, 1 - ((0.06 - s) / 0.06) ** 2));
  return { low, thick };
}

/** Eyebrow hairs over both eyes of a skin: `BROW.hairs` per brow, shuffled between the two. */
export function placeBrows(
  surface: HairSurface,
  landmarks: HairLandmarks,
  caster = new FrontCaster(surface.positions, surface.triangles),
): HairStrands {
  const random = mulberry32(BROW.seed);
  const hairs: LaidHair[] = [];
  const hit: FrontHit = { triangle: 0, w0: 0, w1: 0, w2: 0, z: 0 };
  const n = [0, 0, 0];
  for (const [inner, outer] of [
    [landmarks['eye-inner-l'], landmarks['eye-outer-l']],
    [landmarks['eye-inner-r'], landmarks['eye-outer-r']],
  ] as const) {
    const e = eyeFrame(inner, outer);
    let made = 0;
    for (let tries = 0; made < BROW.hairs && tries < 50 * BROW.hairs; tries++) {
      const a = BROW.uStart + (BROW.uEnd - BROW.uStart) * random();
      const band = browBand(a);
      const b = band.low - 0.05 + (band.thick + 0.1) * random();
      const r = (b - band.low) / Math.max(band.thick, 1e-6);
      // Fewer hairs toward the edges: a soft outline, as a brow has.
      const s = (a - BROW.uStart) / (BROW.uEnd - BROW.uStart);
      const edge = Math.min(r, 1 - r) * band.thick;
      // The head's upright hairs grow sparser than the body's.
      const keep = smooth(edge / 0.06 + 0.35) * smooth(s / 0.04) * smooth((1 - s) / 0.08) * (s < 0.15 ? 0.55 + 0.45 * (s / 0.15) : 1);
      if (r < -0.15 || r > 1.15 || random() >= keep) continue;
      const [x0, y0] = at(e, a, b);
      if (!caster.cast(x0, y0, hit)) continue;
      // The hair's direction in the front view, in degrees from along the eye toward up: upright at the head,
      // turning to lie along the brow in its body and down a little at the tail; above and below the brow's middle
      // line hairs lean toward it (the herringbone of a real brow).
      let angle = s < 0.1 ? 65 : s < 0.35 ? 65 - ((s - 0.1) / 0.25) * 45 : 20 - ((s - 0.35) / 0.65) * 32;
      if (s > 0.25) angle += (0.5 - r) * 28;
      angle += (random() - 0.5) * 18;
      const rad = (angle * Math.PI) / 180;
      const d2 = [Math.cos(rad) * e.u[0] + Math.sin(rad) * e.v[0], Math.cos(rad) * e.u[1] + Math.sin(rad) * e.v[1]];
      const length =
        e.width * (BROW.lengthHead + (BROW.lengthBody - BROW.lengthHead) * smooth(s / 0.3)) * (1 + BROW.lengthSpread * (random() - 0.5));
      // A brow hair keeps its own triangle's frame: where the skin under the brow folds (AU4 bunches the brow's
      // head), its hairs tilt with the fold; a frame 3 mm across turned twice as many of them past 45 degrees.
      const laid: LaidHair = {
        ...anchor(surface, hit),
        vertices: new Float32Array(3 * VERTICES_PER_HAIR),
        shade: new Float32Array(VERTICES_PER_HAIR),
      };
      // The centre line follows the skin, lifting a little toward the tip; a point off the skin ends the hair there.
      const line: number[] = [];
      const point: FrontHit = { ...hit };
      for (let p = 0; p < POINTS; p++) {
        const f = p / (POINTS - 1);
        if (p > 0 && !caster.cast(x0 + d2[0] * length * f, y0 + d2[1] * length * f, point)) {
          line.push(line[3 * p - 3], line[3 * p - 2], line[3 * p - 1]);
          continue;
        }
        hitNormal(surface, point, n);
        const lift = BROW.liftRoot + (BROW.liftTip - BROW.liftRoot) * f * f;
        const px = x0 + d2[0] * length * f,
          py = y0 + d2[1] * length * f;
        line.push(px + lift * n[0], py + lift * n[1], point.z + lift * n[2]);
      }
      hitNormal(surface, hit, n);
      const along = normalize([
        line[3 * (POINTS - 1)] - line[0],
        line[3 * (POINTS - 1) + 1] - line[1],
        line[3 * (POINTS - 1) + 2] - line[2],
      ]);
      ribbon(line, normalize(cross(n, along)), BROW.width, 0.85 + 0.3 * random(), laid);
      hairs.push(laid);
      made++;
    }
  }
  return strandsAtRest(surface, shuffle(hairs, random), VERTICES_PER_HAIR, RIBBON);
}

/**
 * A lash's centre line from `root`: `length` long, leaving at `rootAngle` degrees from forward toward `up` and curling
 * to `tipAngle`, leaning `fan` toward `lateral`; null if a point of it lies behind the skin's front surface (inside the
 * lid) by more than 0.05 mm.
 */
function lashLine(
  caster: FrontCaster,
  root: number[],
  length: number,
  rootAngle: number,
  tipAngle: number,
  up: number[],
  lateral: number[],
  fan: number,
): number[] | null {
  const line = [...root];
  const segment = length / (POINTS - 1);
  const hit: FrontHit = { triangle: 0, w0: 0, w1: 0, w2: 0, z: 0 };
  for (let p = 1; p < POINTS; p++) {
    const angle = ((rootAngle + (tipAngle - rootAngle) * ((p - 0.5) / (POINTS - 1)) ** 1.5) * Math.PI) / 180;
    const d = normalize([Math.sin(angle) * up[0] + fan * lateral[0], Math.sin(angle) * up[1] + fan * lateral[1], Math.cos(angle)]);
    const o = 3 * (p - 1);
    const x = line[o] + segment * d[0],
      y = line[o + 1] + segment * d[1],
      z = line[o + 2] + segment * d[2];
    if (caster.cast(x, y, hit) && z < hit.z - 0.00005) return null;
    line.push(x, y, z);
  }
  return line;
}

/**
 * A lash's centre line down a lid's front from the front-view point (x, y): `length` long in the front view along
 * `direction` (normalised here), each point on the skin under it and standing off it along its normal, more toward the
 * tip; null where the skin ends under it.
 */
function lidLine(surface: HairSurface, caster: FrontCaster, x: number, y: number, length: number, direction: number[]): number[] | null {
  const hit: FrontHit = { triangle: 0, w0: 0, w1: 0, w2: 0, z: 0 };
  const n = [0, 0, 0];
  const d = Math.hypot(direction[0], direction[1]);
  const line: number[] = [];
  for (let p = 0; p < POINTS; p++) {
    const f = p / (POINTS - 1);
    const px = x + (direction[0] / d) * length * f,
      py = y + (direction[1] / d) * length * f;
    if (!caster.cast(px, py, hit)) return null;
    hitNormal(surface, hit, n);
    const lift = p === 0 ? 0 : LASHES.lowerLiftRoot + (LASHES.lowerLiftTip - LASHES.lowerLiftRoot) * f;
    line.push(px + lift * n[0], py + lift * n[1], hit.z + lift * n[2]);
  }
  return line;
}

/** Whether a point is inside an eyeball or nearer its surface than `LASHES.eyeGap`. */
function insideEye(eyes: readonly HairEye[], x: number, y: number, z: number): boolean {
  return eyes.some((e) => Math.hypot(x - e.centre[0], y - e.centre[1], z - e.centre[2]) < e.radius + LASHES.eyeGap);
}

/** Linear interpolation of `values` over ascending `at`, held at the ends. */
function interpolate(at: number[], values: number[], x: number): number {
  if (x <= at[0]) return values[0];
  for (let i = 1; i < at.length; i++) {
    if (x <= at[i]) {
      const f = (x - at[i - 1]) / (at[i] - at[i - 1]);
      return values[i - 1] + f * (values[i] - values[i - 1]);
    }
  }
  return values[values.length - 1];
}

/**
 * Eyelashes along both eyes' lid margins: upper lashes leave the lid forward and a little up and curl upward, longest
 * two thirds of the way out; lower lashes are shorter and sparser and point down. An eye whose margins the rays do not
 * find (a head without eye openings) gets none.
 */
export function placeLashes(
  surface: HairSurface,
  landmarks: HairLandmarks,
  eyes: readonly HairEye[] = [],
  caster = new FrontCaster(surface.positions, surface.triangles),
): HairStrands {
  const random = mulberry32(LASHES.seed);
  const hairs: LaidHair[] = [];
  const hit: FrontHit = { triangle: 0, w0: 0, w1: 0, w2: 0, z: 0 };
  for (const [inner, outer] of [
    [landmarks['eye-inner-l'], landmarks['eye-outer-l']],
    [landmarks['eye-inner-r'], landmarks['eye-outer-r']],
  ] as const) {
    const e = eyeFrame(inner, outer);
    const margin = findLidMargin(caster, e);
    if (margin.a.length < 4) continue;
    const up = [e.v[0], e.v[1], 0];
    const lateral = [e.u[0], e.u[1], 0];
    for (const lid of ['upper', 'lower'] as const) {
      const count = lid === 'upper' ? LASHES.upper : LASHES.lower;
      const sign = lid === 'upper' ? 1 : -1;
      for (let k = 0; k < count; k++) {
        // Evenly along the margin with a jitter, inner to outer, from past the lacrimal part of the lid (its inner
        // eighth, which has no lashes) to near the outer corner.
        const first = Math.max(margin.a[0], LASHES.start);
        const a = first + (margin.a[margin.a.length - 1] - first) * ((k + 0.2 + 0.6 * random()) / count);
        let b = interpolate(margin.a, margin[lid], a) + (sign * (LASHES.rootInset + LASHES.rows * random())) / e.width;
        let [x, y] = at(e, a, b);
        if (!caster.cast(x, y, hit)) continue;
        // Where the margin lies against the eyeball, the root moves out onto the lid's front, up to 2 mm.
        for (let step = 0; step < 20 && insideEye(eyes, x, y, hit.z); step++) {
          b += (sign * MARGIN_STEP) / e.width;
          [x, y] = at(e, a, b);
          if (!caster.cast(x, y, hit)) break;
        }
        const s = (a - margin.a[0]) / (margin.a[margin.a.length - 1] - margin.a[0]);
        // Longest two thirds of the way out, short at the inner corner.
        const bump = Math.sin(Math.PI * Math.min(1, s / 0.66) * 0.5) * (s > 0.66 ? 1 - 0.5 * ((s - 0.66) / 0.34) : 1);
        const length =
          e.width * (lid === 'upper' ? LASHES.upperLength : LASHES.lowerLength) * (0.45 + 0.55 * bump) * (0.85 + 0.3 * random());

        // Fanned: the inner lashes lean toward the nose a little, the outer ones out, more so the further out.
        const fan = (s - 0.3) * 0.55 + (random() - 0.5) * 0.15;
        // A lash that would pass into the lid (where the margin runs steeply, near the corners) leaves it more
        // forward; one that cannot is left out.
        let line: number[] | null = null;
        if (lid === 'upper') {
          for (let turn = 1; turn >= 0.2 && !line; turn -= 0.2)
            line = lashLine(caster, [x, y, hit.z], length, LASHES.upperRootAngle * turn, LASHES.upperTipAngle * turn, up, lateral, fan);
        } else {
          // Down the lower lid's front, close to it: where the closed upper lid comes down over the lower margin, the
          // lower lashes are already below it rather than standing out into it.
          line = lidLine(surface, caster, x, y, length, [-up[0] + fan * lateral[0], -up[1] + fan * lateral[1]]);
        }
        if (!line) continue;
        // The tangent: along the margin both ways, at the root's inset.
        const inset = b - interpolate(margin.a, margin[lid], a);
        const [xa, ya] = at(e, a - TANGENT_REACH, interpolate(margin.a, margin[lid], a - TANGENT_REACH) + inset);
        const [xb, yb] = at(e, a + TANGENT_REACH, interpolate(margin.a, margin[lid], a + TANGENT_REACH) + inset);
        const laid: LaidHair = {
          ...anchor(surface, hit),
          tangentEnds: tangentEndsAround(surface, caster, hit, [xa, ya, xb, yb], 2 * TANGENT_REACH * e.width),
          pivot: nearestEye(eyes, x, y),
          vertices: new Float32Array(3 * VERTICES_PER_HAIR),
          shade: new Float32Array(VERTICES_PER_HAIR),
        };
        ribbon(line, lateral, lid === 'upper' ? LASHES.width : LASHES.lowerWidth, 0.9 + 0.2 * random(), laid);
        hairs.push(laid);
      }
    }
  }
  return strandsAtRest(surface, shuffle(hairs, random), VERTICES_PER_HAIR, RIBBON);
}
