/**
 * A carried jaw's top face put back between the lips. The jaw turns the skin inside its box, fading over `lipFade`
 * below the top face; on the default head that face lies in the gap between the lips, so the lower lip turns whole up
 * to the slit. A warp carries the box to another head's shape but not to its lips' gap to a fraction of a millimetre:
 * with the face inside the lower lip, its top band stays behind as the jaw opens and is pulled into a tall red wall.
 * Pure: no three.js, no DOM.
 */
import { findLipSlit } from '../head/lip-slit';
import { eulerMatrix } from '../math3';
import type { JawMuscle, Rig, Vec3 } from './rig-types';

/** Of the gap between the lips, the most the top face may sit above the lower lip (the rest is the upper lip's). */
const GAP_SHARE = 0.8;

/**
 * The rig with its jaw's top face `lipFade` above the lower lip's top at the midline (or 0.8 of the way to the upper
 * lip where the gap is narrower, the fade shortened to match), its bottom face where it was. `upper` and `lower` are
 * the slit's vertices on the two lips (see findLipSlit); with the lips pressed (no gap) the rig is returned as it is.
 */
export function fitJawToLips(rig: Rig, upper: Vec3, lower: Vec3): Rig {
  if (!rig.muscles.some((m) => m.type === 'jaw')) return rig;
  // A new document throughout: the input rig shares no muscle with it.
  const out = structuredClone(rig);
  out.muscles = out.muscles.map((m) => (m.type === 'jaw' ? jawToLips(m, upper, lower) : m));
  return out;
}

/** `fitJawToLips` for a skin at rest (render positions and normals, metres) and its mouth corners; as it is if no slit. */
export function fitJawToSkinLips(rig: Rig, positions: ArrayLike<number>, normals: ArrayLike<number>, mouthL: Vec3, mouthR: Vec3): Rig {
  const slit = findLipSlit(positions, normals, mouthL, mouthR);
  if (!slit) return rig;
  const at = (v: number): Vec3 => [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
  return fitJawToLips(rig, at(slit.upper), at(slit.lower));
}

function jawToLips(m: JawMuscle, upper: Vec3, lower: Vec3): JawMuscle {
  const R = new Array<number>(9);
  eulerMatrix(m.rotation, R);
  // Heights along the box's local y axis (the rotation's second column), from its centre.
  const height = (p: Vec3): number => (p[0] - m.center[0]) * R[1] + (p[1] - m.center[1]) * R[4] + (p[2] - m.center[2]) * R[7];
  const gap = height(upper) - height(lower);
  if (!(gap > 0)) return m;
  const fade = Math.min(m.lipFade ?? m.fade, GAP_SHARE * gap);
  const top = height(lower) + fade;
  const bottom = -m.size[1] / 2;
  if (!(top > bottom)) return m;
  const shift = (top + bottom) / 2;
  const back = m.size[2] / 2;
  const j = { ...m };
  // The hinge stays where it was, also where it was the back face's centre by default.
  j.joint = m.joint ?? [m.center[0] - back * R[2], m.center[1] - back * R[5], m.center[2] - back * R[8]];
  j.center = [m.center[0] + shift * R[1], m.center[1] + shift * R[4], m.center[2] + shift * R[7]].map(roundLength) as Vec3;
  j.size = [m.size[0], roundLength(top - bottom), m.size[2]];
  j.lipFade = Math.max(1e-6, roundLength(fade));
  return j;
}

const roundLength = (x: number): number => Math.round(x * 1e6) / 1e6;
