/**
 * Mirroring muscles across the face's midplane x = 0 (the subject's left is +x): points get x negated, Euler angles
 * (R = Rz Ry Rx) get y and z negated, brush spheres move with the points, and `-l` / `-r` names and left / right sides
 * swap. This is how the default rig's right side is made from its left. Pure: no DOM, no three.js.
 */
import type { BrushSphere, Muscle, MuscleSide, Vec3 } from './rig-types';

const POINT_KEYS = ['origin', 'insertion', 'center', 'joint'] as const;

/** The other side: left and right swap, mid stays. */
export function otherSide(side: MuscleSide): MuscleSide {
  return side === 'left' ? 'right' : side === 'right' ? 'left' : 'mid';
}

/** The name of a muscle's left/right twin (`zygomaticus-major-l` <-> `-r`), or undefined for names without a side suffix. */
export function twinName(name: string): string | undefined {
  if (/-l$/.test(name)) return `${name.slice(0, -2)}-r`;
  if (/-r$/.test(name)) return `${name.slice(0, -2)}-l`;
  return undefined;
}

/** `muscle` reflected across x = 0, with its twin's name and side (a new object; the input is not changed). */
export function mirrorMuscle(muscle: Muscle, name = twinName(muscle.name) ?? muscle.name): Muscle {
  const out = structuredClone(muscle) as Muscle & Record<string, unknown>;
  for (const key of POINT_KEYS) {
    const p = out[key] as Vec3 | undefined;
    // `|| 0` keeps -0 out of documents: a mirrored 0 stays 0.
    if (p) out[key] = [-p[0] || 0, p[1], p[2]];
  }
  const r = out.rotation as Vec3 | undefined;
  if (r) out.rotation = [r[0], -r[1] || 0, -r[2] || 0];
  if (out.brush) {
    const flip = (s: BrushSphere): BrushSphere => [-s[0] || 0, s[1], s[2], s[3]];
    out.brush = { add: out.brush.add.map(flip), remove: out.brush.remove.map(flip) };
  }
  out.name = name;
  out.side = otherSide(muscle.side);
  return out;
}
