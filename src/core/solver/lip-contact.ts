/**
 * Contact between the lips: pressed together (AU23, AU24, anger), the lips meet instead of passing through each
 * other. The thesis had no collisions; the colliders (colliders.ts) keep skin out of rigid shapes, and this is the
 * same one-sided projection, in the thesis's projection scheme (3.1.2), between two pieces of the skin. Pure: no
 * three.js, no DOM.
 */

/** Where the mouth's corners are (xyz, the skin's space, +y up, the face toward +z). */
export interface MouthCorners {
  left: ArrayLike<number>;
  right: ArrayLike<number>;
}

/** How far above and below the corners' height (metres) the lips' facing skin is looked for. */
const REACH = 0.012;
/** The share of the mouth's half width the contact spans: at the corners the lips are one skin, in dense fans. */
const CORNER_SHARE = 0.8;
/** How far behind the corners (metres) the lips' facing skin may lie: at the corners the slit turns back. */
const BEHIND = 0.004;
/** Skin faces the other lip where its rest normal's vertical part is at least this (down on the upper lip, up on the lower). */
const FACING = 0.5;
/** The lips' facing skin lies within this (metres) of the corners' height; farther, it faces the mouth's inside. */
const SLIT_REACH = 0.003;
/** Facing vertices of the two lips closer than this at rest (metres) are paired across the slit. */
const PAIR_REACH = 0.004;
/**
 * The share of a pair's crossing each outer iteration takes back (see SkinSolver.step for the whole step after them).
 * Taken back whole in every iteration, the pressed lips' slit under anger stood still for 50 frames on the high head
 * and then slid, its pairs handing the skin back and forth with the sphincters and the orientation bound (153 frames to
 * sleep); at a half, with a whole step once the iterations are done, 110, the lips crossing as little (0.12 mm;
 * docs/solver-notes.md, "The lips' contact at a half").
 */
export const LIP_CONTACT_SHARE = 0.5;

/**
 * Pairs of skin vertices across the mouth's slit, one on each lip: a vertex of one lip and the nearest vertex of the
 * other lip's facing skin (the upper lip's underside, the lower lip's top), kept on its own side of that vertex's
 * tangent plane at rest. A plane fixed at rest, not the surface as it moves: the lips slide along
 * each other by millimetres at most, and a fixed direction keeps the projection a linear one-sided constraint that
 * the solver's other passes cannot make cycle. Found once from the rest shape and the mouth's corners.
 */
export class LipContact {
  /** Per pair: the upper lip's vertex, the lower lip's vertex. */
  readonly upper: Uint32Array;
  readonly lower: Uint32Array;
  /**
   * Per pair: the unit direction from the lower vertex toward the upper one (xyz), along which they may come together
   * but not pass. No gap is kept: one of 0.2 mm held the pairs that lie closer at rest from the start of a smile, and
   * the high head's happiness slept after 58 frames instead of 35.
   */
  private readonly direction: Float32Array;

  private constructor(upper: number[], lower: number[], direction: number[]) {
    this.upper = Uint32Array.from(upper);
    this.lower = Uint32Array.from(lower);
    this.direction = Float32Array.from(direction);
  }

  /** Pairs across the slit. */
  get count(): number {
    return this.upper.length;
  }

  /**
   * The pairs of a skin at rest (`rest`, `restNormals`: xyz per vertex) with its mouth at `corners`: each vertex near
   * the slit with the nearest facing vertex of the other lip within PAIR_REACH. The mouth's outer fifths are left
   * out: at the corners the lips are one skin, and pairs there held the corners' fans (fear slept after 75 frames
   * instead of 36 on the medium head). Null where no pair is found (a skin without lips there).
   */
  static find(rest: ArrayLike<number>, restNormals: ArrayLike<number>, corners: MouthCorners): LipContact | null {
    const L = corners.left;
    const R = corners.right;
    const cx = 0.5 * (L[0] + R[0]);
    const cy = 0.5 * (L[1] + R[1]);
    const cz = 0.5 * (L[2] + R[2]);
    const halfWidth = 0.5 * Math.hypot(L[0] - R[0], L[1] - R[1], L[2] - R[2]);
    const downs: number[] = [];
    const ups: number[] = [];
    const near: number[] = [];
    for (let v = 0; v < rest.length / 3; v++) {
      const i = 3 * v;
      if (Math.abs(rest[i] - cx) > CORNER_SHARE * halfWidth || Math.abs(rest[i + 1] - cy) > REACH || rest[i + 2] < cz - BEHIND) continue;
      near.push(v);
      if (Math.abs(rest[i + 1] - cy) > SLIT_REACH) continue;
      if (restNormals[i + 1] <= -FACING) downs.push(v);
      else if (restNormals[i + 1] >= FACING) ups.push(v);
    }
    const upper: number[] = [];
    const lower: number[] = [];
    const direction: number[] = [];
    // Squared distances: Math.hypot in this loop took a tenth of a second of the fine head's start.
    const nearest = (v: number, among: number[]): number => {
      let best = -1;
      let bestDistance = PAIR_REACH * PAIR_REACH;
      const x = rest[3 * v];
      const y = rest[3 * v + 1];
      const z = rest[3 * v + 2];
      for (let k = 0; k < among.length; k++) {
        const w = among[k];
        const dx = x - rest[3 * w];
        const dy = y - rest[3 * w + 1];
        const dz = z - rest[3 * w + 2];
        const d = dx * dx + dy * dy + dz * dz;
        if (d < bestDistance) {
          bestDistance = d;
          best = w;
        }
      }
      return best;
    };
    // Vertex `v` of one lip, the nearest facing vertex `f` of the other lip, whose outward rest normal `sign` * n_f
    // points from the lower lip to the upper one: v stays on its side of f's tangent plane.
    const pair = (v: number, f: number, sign: number, vIsUpper: boolean): void => {
      const dx = sign * restNormals[3 * f];
      const dy = sign * restNormals[3 * f + 1];
      const dz = sign * restNormals[3 * f + 2];
      const u = vIsUpper ? v : f;
      const l = vIsUpper ? f : v;
      const apart = (rest[3 * u] - rest[3 * l]) * dx + (rest[3 * u + 1] - rest[3 * l + 1]) * dy + (rest[3 * u + 2] - rest[3 * l + 2]) * dz;
      // Skin on the other lip's side of that plane at rest (where the lips curl at the corners) is not held by it, nor
      // skin not below the upper lip's (the upper lip's own curves under the nose).
      if (!(apart > 0) || !(rest[3 * u + 1] > rest[3 * l + 1])) return;
      upper.push(u);
      lower.push(l);
      direction.push(dx, dy, dz);
    };
    // Each vertex near the slit against the nearest facing vertex of each lip: it is on the other lip where it lies
    // on the far side of that vertex's tangent plane (the upper lip's underside faces down, the lower lip's top up).
    for (const v of near) {
      const u = nearest(v, downs);
      if (u >= 0 && u !== v) pair(v, u, -1, false);
      const l = nearest(v, ups);
      if (l >= 0 && l !== v) pair(v, l, 1, true);
    }
    return upper.length > 0 ? new LipContact(upper, lower, direction) : null;
  }

  /** How deep (metres) the deepest pair has passed through its plane in `x`; 0 if none has. */
  deepestCrossing(x: ArrayLike<number>): number {
    let deepest = 0;
    const D = this.direction;
    for (let k = 0; k < this.upper.length; k++) {
      const u = 3 * this.upper[k];
      const l = 3 * this.lower[k];
      const apart = (x[u] - x[l]) * D[3 * k] + (x[u + 1] - x[l + 1]) * D[3 * k + 1] + (x[u + 2] - x[l + 2]) * D[3 * k + 2];
      if (-apart > deepest) deepest = -apart;
    }
    return deepest;
  }

  /**
   * Pushes each pair that has passed through its plane back toward it by `share` of the crossing (1: onto it), half
   * each; a vertex outside the solved region (`inside[v]` 0) stays, and its partner takes the whole push. Allocates
   * nothing.
   */
  project(x: Float32Array, inside: Uint8Array, share = 1): void {
    const U = this.upper;
    const Lw = this.lower;
    const D = this.direction;
    for (let k = 0; k < U.length; k++) {
      const u = 3 * U[k];
      const l = 3 * Lw[k];
      const dx = D[3 * k];
      const dy = D[3 * k + 1];
      const dz = D[3 * k + 2];
      const crossing = -((x[u] - x[l]) * dx + (x[u + 1] - x[l + 1]) * dy + (x[u + 2] - x[l + 2]) * dz);
      if (crossing <= 0) continue;
      const short = share * crossing;
      const upIn = inside[U[k]];
      const lowIn = inside[Lw[k]];
      if (upIn === 0 && lowIn === 0) continue;
      const su = lowIn === 0 ? short : upIn === 0 ? 0 : 0.5 * short;
      const sl = short - su;
      x[u] += su * dx;
      x[u + 1] += su * dy;
      x[u + 2] += su * dz;
      x[l] -= sl * dx;
      x[l + 1] -= sl * dy;
      x[l + 2] -= sl * dz;
    }
  }
}
