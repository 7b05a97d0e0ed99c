/**
 * A carried jaw's top face put back between the lips. The jaw turns the skin inside its box, fading over `lipFade`
 * below the top face; on the default head that face lies in the gap between the lips, so the lower lip turns whole up
 * to the slit. A warp carries the box to another head's shape but not to its lips' gap to a fraction of a millimetre:
 * with the face inside the lower lip, its top band stays behind as the jaw opens and is pulled into a tall red wall.
 * Pure: no three.js, no DOM.
 */
import { FACING, MIDLINE, findLipSlit } from '../head/lip-slit';
import { eulerMatrix } from '../math3';
import type { JawMuscle, Rig, Vec3 } from './rig-types';

/** Of the gap between the lips, the most the top face may sit above the lower lip (the rest is the upper lip's). */
const GAP_SHARE = 0.8;
/** Largest bend of the top face, metres (the rig's range allows 20 mm; a lip line falls a few). */
const MAX_DROP = 0.01;
/** The gap between the lips the top face's tilt seeks at the midline, metres (the default head's is 0.4 to 1 mm). */
const TILT_GAP = 0.0004;
/** Largest tilt of the box about its hinge's axis, degrees, and the step it is sought in. */
const MAX_TILT = 12;
const TILT_STEP = 0.25;
/** How far behind the slit (metres) the lips' facing skin at the midline counts for the tilt. */
const BAND_DEPTH = 0.004;

/** The lips' facing skin along the midline: the upper lip's underside and the lower lip's top, near the slit. */
export interface LipBand {
  upper: readonly Vec3[];
  lower: readonly Vec3[];
}

/**
 * The rig with its jaw's top face `lipFade` above the lower lip's top at the midline (or 0.8 of the way to the upper
 * lip where the gap is narrower, the fade shortened to match), its bottom face where it was. `upper` and `lower` are
 * the slit's vertices on the two lips (see findLipSlit); with the lips pressed (no gap) the rig is returned as it is.
 * `corners`, the mouth's corners, bend the face (`lipDrop`, `lipHalfWidth`) down (or up) to pass through them: a
 * mouth whose line falls toward its corners otherwise has its corners and the upper lip's sides inside the box, and
 * the opening jaw pulls the upper lip down with it. The box is levelled first (its hinge kept where it was): the warp
 * turns it with the face's slope (up to 12 degrees forward and 3.6 of roll on the stock identities), which is not the
 * lips' (its top face cut into the upper lip's inner side, its roll into one corner). `band`, the lips' facing skin at
 * the midline, then tilts the box about its hinge's axis (the least tilt that leaves TILT_GAP between the two lips'
 * skin, or the most gap within MAX_TILT): full lips whose underside falls behind the slit to the lower lip's height
 * otherwise lie partly inside the level box, and the upper lip's middle follows the jaw down in a V.
 */
export function fitJawToLips(rig: Rig, upper: Vec3, lower: Vec3, corners: readonly Vec3[] = [], band?: LipBand): Rig {
  if (!rig.muscles.some((m) => m.type === 'jaw')) return rig;
  // A new document throughout: the input rig shares no muscle with it.
  const out = structuredClone(rig);
  out.muscles = out.muscles.map((m) => (m.type === 'jaw' ? jawToLips(m, upper, lower, corners, band) : m));
  return out;
}

/** `fitJawToLips` for a skin at rest (render positions and normals, metres) and its mouth corners; as it is if no slit. */
export function fitJawToSkinLips(rig: Rig, positions: ArrayLike<number>, normals: ArrayLike<number>, mouthL: Vec3, mouthR: Vec3): Rig {
  const slit = findLipSlit(positions, normals, mouthL, mouthR);
  if (!slit) return rig;
  const at = (v: number): Vec3 => [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
  const upper = at(slit.upper);
  const lower = at(slit.lower);
  // The lips' facing skin along the midline, from the slit to BAND_DEPTH behind it.
  const band: { upper: Vec3[]; lower: Vec3[] } = { upper: [], lower: [] };
  const cx = 0.5 * (mouthL[0] + mouthR[0]);
  const front = Math.min(upper[2], lower[2]) - BAND_DEPTH;
  for (let v = 0; v < positions.length / 3; v++) {
    const i = 3 * v;
    if (Math.abs(positions[i] - cx) >= MIDLINE || positions[i + 2] < front) continue;
    if (normals[i + 1] <= -FACING && positions[i + 1] > lower[1] - 0.003) band.upper.push(at(v));
    else if (normals[i + 1] >= FACING && positions[i + 1] < upper[1] + 0.003) band.lower.push(at(v));
  }
  return fitJawToLips(rig, upper, lower, [mouthL, mouthR], band);
}

/** The least tilt (degrees about local x) that leaves TILT_GAP between the band's lips, or the one with the most gap. */
function bandTilt(m: JawMuscle, band: LipBand | undefined): number {
  if (!band || band.upper.length === 0 || band.lower.length === 0) return 0;
  const R = new Array<number>(9);
  let best = 0;
  let bestGap = -Infinity;
  for (let k = 0; k <= 2 * (MAX_TILT / TILT_STEP); k++) {
    // 0, +step, -step, +2 step, ...: the least tilt first.
    const tilt = (k % 2 === 1 ? 1 : -1) * Math.ceil(k / 2) * TILT_STEP;
    eulerMatrix([tilt, 0, 0], R);
    const height = (p: Vec3): number => (p[0] - m.center[0]) * R[1] + (p[1] - m.center[1]) * R[4] + (p[2] - m.center[2]) * R[7];
    const gap = Math.min(...band.upper.map(height)) - Math.max(...band.lower.map(height));
    if (gap >= TILT_GAP) return tilt;
    if (gap > bestGap + 1e-6) {
      bestGap = gap;
      best = tilt;
    }
  }
  return best;
}

function jawToLips(carried: JawMuscle, upper: Vec3, lower: Vec3, corners: readonly Vec3[], band: LipBand | undefined): JawMuscle {
  const R0 = new Array<number>(9);
  eulerMatrix(carried.rotation, R0);
  const back0 = carried.size[2] / 2;
  // Levelled, then tilted to the lips; the hinge stays where it was, also where it was the back face's centre by default.
  const m: JawMuscle = {
    ...carried,
    joint: carried.joint ?? [carried.center[0] - back0 * R0[2], carried.center[1] - back0 * R0[5], carried.center[2] - back0 * R0[8]],
  };
  m.rotation = [bandTilt(m, band), 0, 0];
  const R = new Array<number>(9);
  eulerMatrix(m.rotation, R);
  // Heights along the box's local y axis (the rotation's second column), from its centre.
  const height = (p: Vec3): number => (p[0] - m.center[0]) * R[1] + (p[1] - m.center[1]) * R[4] + (p[2] - m.center[2]) * R[7];
  // The gap between the lips: their facing skin along the midline where it is apart, else the slit's two vertices.
  let lowerTop = height(lower);
  let gap = height(upper) - lowerTop;
  if (band && band.upper.length > 0 && band.lower.length > 0) {
    const bandTop = Math.max(...band.lower.map(height));
    const bandGap = Math.min(...band.upper.map(height)) - bandTop;
    if (bandGap > 0) {
      lowerTop = bandTop;
      gap = bandGap;
    }
  }
  if (!(gap > 0)) return carried;
  const fade = Math.min(m.lipFade ?? m.fade, GAP_SHARE * gap);
  const top = lowerTop + fade;
  const bottom = -m.size[1] / 2;
  if (!(top > bottom)) return carried;
  const shift = (top + bottom) / 2;
  const j = { ...m };
  j.center = [m.center[0] + shift * R[1], m.center[1] + shift * R[4], m.center[2] + shift * R[7]].map(roundLength) as Vec3;
  j.size = [m.size[0], roundLength(top - bottom), m.size[2]];
  j.lipFade = Math.max(1e-6, roundLength(fade));
  // The bend: the face through the corners, where the lips are one skin (the fade below them turns them part way).
  // Read halfway to them instead, from the slit there, the face left the upper lip's sides inside the box on most
  // stock identities (down 13 to 21 mm under AU27; through the corners 1 to 8).
  if (corners.length > 0) {
    let drop = 0;
    let width = 0;
    for (const c of corners) {
      drop += top - height(c);
      width += Math.abs((c[0] - m.center[0]) * R[0] + (c[1] - m.center[1]) * R[3] + (c[2] - m.center[2]) * R[6]);
    }
    if (width > 0) {
      j.lipDrop = roundLength(Math.max(-MAX_DROP, Math.min(MAX_DROP, drop / corners.length)));
      j.lipHalfWidth = roundLength(width / corners.length);
    }
  }
  return j;
}

const roundLength = (x: number): number => Math.round(x * 1e6) / 1e6;
