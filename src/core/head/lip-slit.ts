/**
 * The two skin vertices that face each other across the mouth slit at the midline, one on each lip: how far apart they
 * are tells how open the lips are. Pure: no three.js, no DOM.
 */
import type { Vec3 } from '../rig/rig-types';

/** Render vertices of the upper and the lower lip at the midline, where the slit opens. */
export interface LipSlit {
  upper: number;
  lower: number;
}

/** How far from the midline (metres) a vertex may lie and count as on it. */
export const MIDLINE = 0.002;
/** How far above and below the mouth corners' height (metres) the lips' vertices are looked for. */
const REACH = 0.01;
/** A lip's side of the slit faces the other lip: its normal's vertical part is at least this, down or up. */
export const FACING = 0.5;

/**
 * The slit's two vertices for a skin's render `positions` and `normals` (xyz, metres, face toward +z, +y up) and its
 * mouth corners: of the vertices near the midline within REACH of the corners' height and in front of them, the
 * nearest pair of one facing down (the upper lip's underside) and one facing up (the lower lip's top). Null if a lip
 * has no such vertex. `across` (metres, toward +x) reads the slit that far to the side of the midline instead.
 */
export function findLipSlit(
  positions: ArrayLike<number>,
  normals: ArrayLike<number>,
  mouthL: Vec3,
  mouthR: Vec3,
  across = 0,
): LipSlit | null {
  const cx = 0.5 * (mouthL[0] + mouthR[0]) + across;
  const cy = 0.5 * (mouthL[1] + mouthR[1]);
  const cz = 0.5 * (mouthL[2] + mouthR[2]);
  const downs: number[] = [];
  const ups: number[] = [];
  for (let v = 0; v < positions.length / 3; v++) {
    const i = 3 * v;
    if (Math.abs(positions[i] - cx) >= MIDLINE || Math.abs(positions[i + 1] - cy) >= REACH || positions[i + 2] < cz) continue;
    if (normals[i + 1] <= -FACING) downs.push(v);
    else if (normals[i + 1] >= FACING) ups.push(v);
  }
  let best: LipSlit | null = null;
  let nearest = Infinity;
  for (const u of downs) {
    for (const l of ups) {
      // The upper lip's vertex lies above the lower lip's.
      if (positions[3 * u + 1] < positions[3 * l + 1]) continue;
      const d = Math.hypot(
        positions[3 * u] - positions[3 * l],
        positions[3 * u + 1] - positions[3 * l + 1],
        positions[3 * u + 2] - positions[3 * l + 2],
      );
      if (d < nearest) {
        nearest = d;
        best = { upper: u, lower: l };
      }
    }
  }
  return best;
}
