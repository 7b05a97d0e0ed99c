/**
 * A frame's passes over the constraint lists, run on this thread alone or, with a partner thread attached, half here
 * and half there at the same time, with the same result (see solver-partner.ts): what SkinSolver.step runs.
 */
import type { ActiveRegion } from './active-region';
import { LIP_CONTACT_SHARE, type LipContact } from './lip-contact';
import type { FrameTimings } from './solver-buffers';
import { PART_EVEN, PART_EVEN_SEAM, PART_ODD, PART_ODD_SEAM, PARTS } from './constraint-lists';
import { anyTurnedOver, ORIENT_AGAIN, ORIENT_FULL, projectOrientationPart } from './orientation-kernel';
import type { PartArrays } from './part-arrays';
import {
  JOB_BENDING,
  JOB_COLLISIONS,
  JOB_LENGTHS,
  JOB_NORMALS,
  JOB_ORIENTATION,
  JOB_POSITIONS,
  JOB_SECOND_RING,
  JOB_START_FRAME,
  JOB_STEPS,
} from './partner-board';
import type { PartnerLink } from './partner-link';
import type { SkinParameters } from './skin-parameters';
import { UNTANGLE_FLOOR, UNTANGLE_PASSES } from './solver-schedule';
import { ALONE, LEADER, runShare } from './solver-partner';
import { projectBendingPart } from './solver-kernels';
import { computeNormals } from './topology';

/** The passes of a SkinSolver's frames over its part arrays (see part-arrays.ts). */
export class FramePasses {
  /** The partner thread that takes half of each pass (see SkinSolver.attachPartner); null: this thread solves alone. */
  partner: PartnerLink | null = null;
  private readonly parts: PartArrays;
  private readonly direction = new Float32Array(3);
  /** The lips' contact, projected with the collisions (null without a mouth), and the region's flags it reads. */
  private readonly lips: LipContact | null;
  private readonly inside: Uint8Array;

  constructor(parts: PartArrays, lips: LipContact | null = null, inside: Uint8Array = new Uint8Array(0)) {
    this.parts = parts;
    this.lips = lips;
    this.inside = inside;
  }

  /**
   * A frame's outer iterations: positions and muscles, lengths, orientation, bending, then collisions, each pass's
   * time added to `time`. `orient`: the orientation passes' mode (see projectOrientation).
   */
  iterate(p: SkinParameters, maxBendPasses: number, count: number, orient: number, time: FrameTimings): void {
    for (let it = 0; it < p.positionIterations; it++) {
      let t0 = now();
      this.projectPositions(count, p);
      let t1 = now();
      time.positions += t1 - t0;
      this.projectLengths(p.lengthIterations, p);
      t0 = now();
      time.lengths += t0 - t1;
      this.projectOrientation(orient);
      t1 = now();
      time.orientation += t1 - t0;
      this.projectBending(p, maxBendPasses, count);
      t0 = now();
      time.bending += t0 - t1;
      this.projectCollisions();
      time.collisions += now() - t0;
    }
  }

  /**
   * Stores where each region vertex starts the frame (skin outside the region stays at rest, and so does `previous`
   * there; see SkinSolver.refreshLists), then carries its momentum. Heavy-ball acceleration (Polyak): each region vertex first
   * takes `beta` times its last move along the surface and `foldBeta` times its last move along its rest normal, then
   * the frame's projections. The soft position constraint lets a displaced sheet fade by only a few per cent an
   * iteration; the carried move makes the slow modes fade about as the square root of that factor per frame. A
   * carried move that overshoots turns back, and the relaxation treats that as any cycle.
   */
  startFrame(count: number, beta: number, foldBeta: number): void {
    this.share(JOB_START_FRAME, count, beta, foldBeta);
  }

  /** Stores each of the `count` region vertices' move of this frame and returns the largest. */
  recordSteps(count: number): number {
    const mine = this.share(JOB_STEPS, count);
    return Math.sqrt(this.partner ? Math.max(mine, this.partner.board.value[0]) : mine);
  }

  /**
   * Position and muscle constraints (thesis 4.3.2 and 4.3.4; see projectPositions in solver-kernels.ts), half on the
   * partner if any.
   */
  projectPositions(count: number, p: SkinParameters): void {
    const s = p.positionStiffness;
    const extra = s * (p.inwardResistance - 1);
    const m = p.muscleStiffness;
    this.share(JOB_POSITIONS, count, s, extra, m);
  }

  /**
   * `passes` passes of the length constraints (thesis 4.3.3; see projectLengths in length-kernels.ts), with the
   * partner if there is one (one job for all the passes).
   */
  projectLengths(passes: number, p: SkinParameters): void {
    this.share(JOB_LENGTHS, passes, p.lengthStiffness, p.bulge, p.pretension);
  }

  /**
   * Orientation constraints (see projectOrientationPart), part by part as the lengths; returns whether a triangle was
   * more than a hair under its bound.
   */
  projectOrientation(mode: number, floor = 1): boolean {
    const blocks = this.orientationPair(PART_EVEN, PART_ODD, mode, floor);
    return this.orientationPair(PART_EVEN_SEAM, PART_ODD_SEAM, mode, floor) || blocks;
  }

  /** Whether a listed triangle is turned over now (see anyTurnedOver); read on this thread between passes. */
  turnedOver(): boolean {
    return anyTurnedOver(this.parts);
  }

  /**
   * Up to `passes` orientation passes in a row at `floor` of the bound (the first checks every triangle, the others
   * those with a corner moved since), stopping once one corrects nothing.
   */
  orientationRounds(passes: number, floor = 1): void {
    for (let k = 0; k < passes && this.projectOrientation(k > 0 ? ORIENT_AGAIN : ORIENT_FULL, floor); k++);
  }

  /**
   * Still skin with a sliver turned over (the fans at the mouth's corners under AU20, fear and disgust on the high
   * head, the pressed lips' slit under anger): orientation passes alone, up to UNTANGLE_PASSES at UNTANGLE_FLOOR of
   * the bound, turn the slivers back (a few hundredths of a millimetre), so that the skin sleeps untangled. Waiting for
   * the frames to do it took hundreds of them, the fan's vertices slowed by the relaxation to a sixteenth of their
   * moves and less (docs/solver-notes.md, "Untangling as the skin comes to rest"). If a triangle stays turned over, the
   * `count` region vertices go back to where the frame left them. `keep` is scratch, 3 floats a vertex.
   */
  untangle(count: number, keep: Float32Array): void {
    const x = this.parts.positions;
    const V = this.parts.regionVertices;
    for (let k = 0; k < count; k++) {
      const i = 3 * V[k];
      keep[i] = x[i];
      keep[i + 1] = x[i + 1];
      keep[i + 2] = x[i + 2];
    }
    this.orientationRounds(UNTANGLE_PASSES, UNTANGLE_FLOOR);
    if (!this.turnedOver()) return;
    for (let k = 0; k < count; k++) {
      const i = 3 * V[k];
      x[i] = keep[i];
      x[i + 1] = keep[i + 1];
      x[i + 2] = keep[i + 2];
    }
  }

  private orientationPair(mine: number, theirs: number, mode: number, floor: number): boolean {
    const partner = this.partner;
    partner?.start(JOB_ORIENTATION, theirs, mode, floor);
    const corrected = projectOrientationPart(this.parts, mine, mode, floor);
    if (partner) return partner.finish() !== 0 || corrected;
    return projectOrientationPart(this.parts, theirs, mode, floor) || corrected;
  }

  /**
   * Bending: keeps the Laplacian of the normal displacement near zero (the rest curvature), scaled per vertex by the
   * local mesh spacing so that its balance against the position constraints gives folds of `wrinkleSpacing` at every
   * mesh resolution (thesis 3.1.2 wishes for such a skin parameter). A vertex whose share exceeds MAX_BENDING_SHARE
   * is projected in several passes, one after another over the region, each of an equal part of it. Each pass goes
   * part by part as the orientation passes (see projectBendingPart): the even blocks with the odd ones, then the even
   * seams with the odd ones, each part in vertex order, so that two threads share it and one gives the same shape.
   * Then, where the ring of neighbours cannot bend as stiffly as the spacing asks, a pass over the ring two edges out
   * of the `count` region vertices (see projectSecondRingPart), half on the partner if any.
   */
  projectBending(p: SkinParameters, maxBendPasses: number, count: number): void {
    if (p.wrinkleSpacing <= 0) return;
    for (let pass = 0; pass < maxBendPasses; pass++) {
      this.bendingPair(PART_EVEN, PART_ODD, pass);
      this.bendingPair(PART_EVEN_SEAM, PART_ODD_SEAM, pass);
    }
    if (this.parts.secondRing.active) this.share(JOB_SECOND_RING, count);
  }

  private bendingPair(mine: number, theirs: number, pass: number): void {
    const partner = this.partner;
    partner?.start(JOB_BENDING, theirs + PARTS * pass);
    projectBendingPart(this.parts, pass, mine);
    if (partner) partner.finish();
    else projectBendingPart(this.parts, pass, theirs);
  }

  /**
   * Collisions: a vertex that was outside a collider at rest keeps at least its rest clearance (capped at 1 mm).
   * Only the candidates in or next to the active region are checked (see listCandidates); half on the partner if any.
   */
  projectCollisions(): void {
    this.share(JOB_COLLISIONS, 0);
    // Then the lips' contact, on this thread alone with the partner idle between jobs: a few hundred pairs.
    this.lips?.project(this.parts.positions, this.inside, LIP_CONTACT_SHARE);
  }

  /** The lips' contact taken back whole (see LIP_CONTACT_SHARE), on this thread alone. */
  closeLips(): void {
    this.lips?.project(this.parts.positions, this.inside);
  }

  /**
   * Runs a job that splits in two (see runShare): all of it here, or the first half here and the second on the partner
   * thread at the same time. Returns this thread's result (JOB_STEPS: its largest squared move).
   */
  share(job: number, count: number, a = 0, b = 0, c = 0): number {
    const partner = this.partner;
    if (!partner) return runShare(this.parts, job, count, a, b, c, ALONE, null, this.direction);
    partner.start(job, count, a, b, c);
    const mine = runShare(this.parts, job, count, a, b, c, LEADER, partner.board.words, this.direction);
    partner.finish();
    return mine;
  }

  /**
   * Normals of the skin that may have moved in region `r`: the region and its ring (all of it without the active region), half on
   * the partner if any. The ring's outer neighbours, which the ring's triangles touch, keep their rest normals.
   */
  computeNormals(r: ActiveRegion, triangles: Uint32Array): void {
    const out = this.parts.normals;
    if (!r.enabled) {
      computeNormals(this.parts.positions, triangles, out);
      return;
    }
    const count = r.shadedCount;
    zeroAt(out, r.shadedVertices, count);
    zeroAt(out, r.outer, r.outerCount);
    this.share(JOB_NORMALS, count);
    const N = this.parts.restNormals;
    for (let k = 0; k < r.outerCount; k++) {
      const i = 3 * r.outer[k];
      out[i] = N[i];
      out[i + 1] = N[i + 1];
      out[i + 2] = N[i + 2];
    }
  }
}

/** Zeroes the xyz of the first `count` listed vertices. */
function zeroAt(out: Float32Array, vertices: Uint32Array, count: number): void {
  for (let k = 0; k < count; k++) {
    const i = 3 * vertices[k];
    out[i] = out[i + 1] = out[i + 2] = 0;
  }
}

/** Milliseconds from a monotonic clock (performance.now exists in browsers, workers and Node). */
const now = (): number => performance.now();
