/**
 * The upper lid's folded skin: as a lid closes, the skin between it and the brow unfolds (it comes out of the lid
 * crease) instead of dragging the brow down.
 *
 * The thesis's lid (3.2.2, 4.4.3.1) turns the lid's skin about the eye; the skin above it was held only by its length
 * constraints, so the turn stretched it 30 to 80 % and pulled the brows 4 to 7 mm down with every blink. A real upper
 * lid carries its slack folded under the brow, which comes out as the lid closes. Here a closing lid muscle (positive
 * `maxAngle`) lets the edges above its centre stretch freely, up to `LID_SLACK` more of the part of each edge that runs
 * across its hinge (along the hinge the lid does not pull), in proportion to its closing past LID_FIRM; past that,
 * and under compression, they resist as any edge (see SolverBuffers.unfoldedLengths). An open lid (contraction 0)
 * leaves every edge as it was, so the face comes home exactly.
 */
import { eulerMatrix } from '../math3';
import type { Muscle } from './rig-types';

/** How much longer, at most, the skin above a closed lid may grow across the hinge before it resists: its fold. */
export const LID_SLACK = 2;
/** How far above the lid muscle's centre its slack reaches, in the ellipsoid's heights (radii[1]). */
const LID_SLACK_REACH = 4;
/** How far to each side its slack reaches, in the ellipsoid's widths (radii[0]): past the lid's corners. */
const LID_SLACK_WIDTH = 1.3;
/**
 * The contraction up to which nothing unfolds: a lid turned a little (AU4's fold of skin pushed over the lid, 8 %, or
 * a lid following the gaze down a few degrees) presses the skin above it together rather than stretching it; from
 * there the fold opens in proportion to the rest of the closing.
 */
export const LID_FIRM = 0.1;
/** Share of the reach over which the slack is whole; it fades (cosine) to none at the reach. */
const WHOLE = 0.6;

/** What the skin's rest lengths are made of (a SkinTopology has these). */
interface SlackSkin {
  rest: Float32Array;
  edges: Uint32Array;
  restLength: Float32Array;
}

/** The lengths to which the edges above each closing lid unfold, growing with its contraction. */
export class LidSlack {
  /** Edges that can unfold, their lid's muscle index, each edge's length along the hinge and across it, its share. */
  private readonly edges: Uint32Array;
  private readonly muscle: Uint32Array;
  private readonly along: Float32Array;
  private readonly across: Float32Array;
  private readonly share: Float32Array;
  private readonly restLength: Float32Array;

  constructor(skin: SlackSkin, muscles: readonly Muscle[]) {
    this.restLength = skin.restLength;
    const found: { e: number; m: number; along: number; across: number; share: number }[] = [];
    const F = new Float64Array(9);
    muscles.forEach((muscle, m) => {
      if (muscle.type !== 'lid' || muscle.maxAngle <= 0) return;
      eulerMatrix(muscle.rotation, F);
      const [cx, cy, cz] = muscle.center;
      const [rx0, ry, rz] = muscle.radii;
      const rx = LID_SLACK_WIDTH * rx0;
      const reach = LID_SLACK_REACH * ry;
      const depth = Math.max(rz, reach);
      const X = skin.rest;
      const E = skin.edges;
      for (let e = 0; e < skin.restLength.length; e++) {
        const a = 3 * E[2 * e];
        const b = 3 * E[2 * e + 1];
        const dx = 0.5 * (X[a] + X[b]) - cx;
        const dy = 0.5 * (X[a + 1] + X[b + 1]) - cy;
        const dz = 0.5 * (X[a + 2] + X[b + 2]) - cz;
        // Local coordinates: the frame's columns are its axes.
        const qx = F[0] * dx + F[3] * dy + F[6] * dz;
        const qy = F[1] * dx + F[4] * dy + F[7] * dz;
        const qz = F[2] * dx + F[5] * dy + F[8] * dz;
        if (qy <= 0) continue;
        const rho = Math.sqrt((qx / rx) ** 2 + (qy / reach) ** 2 + (qz / depth) ** 2);
        if (rho >= 1) continue;
        const share = rho <= WHOLE ? 1 : Math.cos(((rho - WHOLE) / (1 - WHOLE)) * (Math.PI / 2));
        const ex = X[b] - X[a];
        const ey = X[b + 1] - X[a + 1];
        const ez = X[b + 2] - X[a + 2];
        const along = Math.abs(F[0] * ex + F[3] * ey + F[6] * ez);
        const length = skin.restLength[e];
        found.push({ e, m, along, across: Math.sqrt(Math.max(0, length * length - along * along)), share });
      }
    });
    const n = found.length;
    this.edges = new Uint32Array(n);
    this.muscle = new Uint32Array(n);
    this.along = new Float32Array(n);
    this.across = new Float32Array(n);
    this.share = new Float32Array(n);
    found.forEach((f, i) => {
      this.edges[i] = f.e;
      this.muscle[i] = f.m;
      this.along[i] = f.along;
      this.across[i] = f.across;
      this.share[i] = f.share;
    });
  }

  /** Edges a closing lid can unfold. */
  get edgeCount(): number {
    return this.edges.length;
  }

  /**
   * Writes the unfolded lengths of its edges at these muscle contractions into `unfoldedLengths` (one per edge); an
   * edge in the zones of two lids takes the longer.
   */
  compute(contractions: ArrayLike<number>, unfoldedLengths: Float32Array): void {
    for (let i = 0; i < this.edges.length; i++) unfoldedLengths[this.edges[i]] = this.restLength[this.edges[i]];
    for (let i = 0; i < this.edges.length; i++) {
      const closing = (Math.min(contractions[this.muscle[i]], 1) - LID_FIRM) / (1 - LID_FIRM);
      if (!(closing > 0)) continue;
      const e = this.edges[i];
      const across = this.across[i] * (1 + LID_SLACK * this.share[i] * closing);
      const unfolded = Math.sqrt(this.along[i] * this.along[i] + across * across);
      if (unfolded > unfoldedLengths[e]) unfoldedLengths[e] = unfolded;
    }
  }
}
