/**
 * Where an eye is in the front view, as the hair's placement lays brows and lashes out: its frame from the eye
 * corners, in eye widths, and its lid margins, found by rays from the front. Pure: no three.js, no DOM.
 */
import type { Vec3 } from '../rig/rig-types';
import type { FrontCaster, FrontHit } from './front-caster';

/** A ray hit deeper than this behind the column's front falls into the eye's opening (the socket is 3 cm back). */
const DEEP = 0.005;
/** Step of the rays that look for the lid margins, in metres. */
export const MARGIN_STEP = 0.0001;

/** One eye's frame in the front view: the inner corner, a unit vector along the eye and one up, and the eye's width. */
export interface EyeFrame {
  x: number;
  y: number;
  u: [number, number];
  v: [number, number];
  width: number;
}

/** The frame of the eye with corners `inner` and `outer`. */
export function eyeFrame(inner: Vec3, outer: Vec3): EyeFrame {
  const dx = outer[0] - inner[0],
    dy = outer[1] - inner[1];
  const width = Math.hypot(dx, dy);
  const u: [number, number] = [dx / width, dy / width];
  // Up: the perpendicular that points to +y, whichever side the eye is on.
  const v: [number, number] = u[0] >= 0 ? [-u[1], u[0]] : [u[1], -u[0]];
  return { x: inner[0], y: inner[1], u, v, width };
}

/** The front-view point at (a, b) eye widths along and up from the inner corner. */
export function at(e: EyeFrame, a: number, b: number): [number, number] {
  return [e.x + e.width * (a * e.u[0] + b * e.v[0]), e.y + e.width * (a * e.u[1] + b * e.v[1])];
}

/** A lid margin as the rays found it: per column across the eye, where along the eye (a) and up (b), in eye widths. */
export interface LidMargin {
  a: number[];
  upper: number[];
  lower: number[];
}

/**
 * Finds an eye's lid margins: in columns across the eye, rays from the front step up and down from the corners'
 * line; where they fall deep (into the opening, past the eyeball to the socket, or through nothing) is the opening,
 * and the first ray above and below it that meets the lid's front is the margin.
 */
export function findLidMargin(caster: FrontCaster, e: EyeFrame, columns = 40): LidMargin {
  const out: LidMargin = { a: [], upper: [], lower: [] };
  const hit: FrontHit = { triangle: 0, w0: 0, w1: 0, w2: 0, z: 0 };
  const reach = 0.4 * e.width;
  const steps = Math.round(reach / MARGIN_STEP);
  const z = new Float64Array(2 * steps + 1);
  for (let c = 0; c < columns; c++) {
    const a = 0.04 + (0.92 * c) / (columns - 1);
    let front = -Infinity;
    for (let i = -steps; i <= steps; i++) {
      const [x, y] = at(e, a, (i * MARGIN_STEP) / e.width);
      z[i + steps] = caster.cast(x, y, hit) ? hit.z : -Infinity;
      front = Math.max(front, z[i + steps]);
    }
    const deep = (i: number): boolean => z[i + steps] < front - DEEP;
    // The opening: the run of deep rays nearest the corners' line.
    let start = NaN;
    for (let r = 0; r <= steps / 2 && Number.isNaN(start); r++) {
      if (deep(r)) start = r;
      else if (deep(-r)) start = -r;
    }
    if (Number.isNaN(start)) continue;
    let top = start,
      bottom = start;
    while (top < steps && deep(top + 1)) top++;
    while (bottom > -steps && deep(bottom - 1)) bottom--;
    if (top === steps || bottom === -steps) continue;
    out.a.push(a);
    out.upper.push(((top + 1) * MARGIN_STEP) / e.width);
    out.lower.push(((bottom - 1) * MARGIN_STEP) / e.width);
  }
  return out;
}
