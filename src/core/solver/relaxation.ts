/**
 * The relaxation that turns the frame's cycles into convergence (SkinSolver.relax, relaxPart) and the loop breaking
 * that does the same for slow loops, with the per-vertex state they keep across a motion's frames.
 *
 * Each vertex takes a share of its solved move. Where the hard constraints (collisions, orientation) meet stiff
 * bending, the frame's map can hand a vertex back and forth between two shapes (a period-2 cycle: its move turns back
 * on the last one). Such a vertex takes half as much of its moves from then on (down to MIN_RELAXATION), which turns
 * the cycle into a contraction toward the shape between. A cycle repeats: a single turn (a lip bouncing off a tooth as
 * the skin sets off) halves nothing, a second within CYCLE_TURNS_WITHIN frames does (halving at the first turn left
 * vertices creeping: docs/solver-notes.md). Shares only shrink within a motion (a new input restores whole moves), so
 * the frame's map stops changing after a few halvings instead of starting cycles of its own. An under-relaxed step has
 * the same fixed points as a whole one: the skin comes to rest in the shape the constraints ask for, by convergence,
 * not by being slowed down (the thesis's iteration has no such step). A safety net remains for skin still drifting
 * LATE_MOTION frames after an input (a few lid and lip vertices, by micrometres a frame): from then on every share
 * shrinks each frame.
 */
import { allocate, type Memory, type Room } from './memory';
import {
  LATE_MOTION,
  LATE_SLOWING,
  LOOP_LEAST_SHARE,
  LOOP_SLOWING,
  LOOP_WINDOW,
  STALL,
  STALL_PART,
  STALL_STEP,
  STILL_MOVE,
} from './solver-schedule';
import type { SkinTopology } from './topology';

/** A SkinSolver's relaxation shares, turn marks and ways per vertex, and the age of its motion. */
export class Relaxation {
  /** Share of its solved move each vertex takes this frame (see relaxPart). */
  readonly share: Float32Array;
  /** 1 for a vertex whose last move turned back on the one before: it carries no momentum into the next frame. */
  readonly restart: Uint8Array;
  /** Frames since each vertex last turned back, up to 255 (see relaxPart). */
  readonly calm: Uint8Array;
  /** Each vertex's way (the sum of its moves) since breakLoops last looked (see LOOP_STEP). */
  readonly path: Float32Array;
  /** Frames solved since the last input or parameter change. */
  motionFrames = 0;
  /** Scratch marks of the vertices breakLoops slows. */
  private readonly looping: Uint8Array;
  /** Each vertex's way in the LOOP_STEP frames before the last look: with `path`, its way over a whole window. */
  private readonly stepPath: Float32Array;
  /** The longest way a vertex went over the window that ended at the last look. */
  private longestStepAgo = 0;
  /** The longest way a vertex went over the window that ended a whole window ago: the one a way is weighed against. */
  private longestWindowAgo = 0;
  /** The motion frame breakLoops last slowed skin at. */
  private slowedAt = -LOOP_WINDOW;

  /** Shares, marks and ways for `n` vertices, in `room` while it has room (the kernel memory), else in `memory`. */
  constructor(n: number, memory: Memory, room: Room | null = null) {
    this.share = allocate(Float32Array, n, memory, room).fill(1);
    this.restart = allocate(Uint8Array, n, memory, room);
    this.calm = allocate(Uint8Array, n, memory, room).fill(255);
    this.path = allocate(Float32Array, n, memory, room);
    this.looping = new Uint8Array(n);
    this.stepPath = new Float32Array(n);
  }

  /** A new motion (new inputs or parameters): every vertex may take whole steps again. */
  restartMotion(): void {
    this.motionFrames = 0;
    this.share.fill(1);
    this.calm.fill(255);
    this.path.fill(0);
    this.stepPath.fill(0);
    this.longestStepAgo = 0;
    this.longestWindowAgo = 0;
    this.slowedAt = -LOOP_WINDOW;
  }

  /** Skin that left the region (`inside[v]` 0) is at rest: it carries no way into a later look (see restOutside). */
  restOutside(inside: Uint8Array): void {
    const stepPath = this.stepPath;
    for (let v = 0; v < inside.length; v++) if (inside[v] === 0) stepPath[v] = 0;
  }

  /** Counts a relaxed frame and returns the cap on every share in it: 1, shrinking each frame after LATE_MOTION. */
  nextCap(): number {
    const late = this.motionFrames++ - LATE_MOTION;
    return late > 0 ? LATE_SLOWING ** late : 1;
  }

  /**
   * Every LOOP_STEP frames, over the region's vertices `V[0..count]`: if the longest way a vertex went in the last
   * LOOP_WINDOW frames is not clearly shorter than in the window before, the skin has stalled: it circles (a smooth loop
   * of a few dozen frames a turn, where no move turns back on the one before, so the relaxation does not see it) or
   * chatters at its least share where the hard constraints take turns. The vertices that went far (over STALL_PART of
   * the longest way) and their neighbours (the loop is a mode of the patch: slowing one vertex moves the loop next to
   * it) take a quarter of their moves from then on (LOOP_SLOWING). An under-relaxed step has the same fixed points, so
   * where the constraints have one the skin converges to it; where they only chatter, the patch slows until it sleeps,
   * long before the safety net (see LATE_MOTION). Skin that converges shortens its way by more than a tenth a window (a
   * third of a per cent a frame) and is left alone (the threshold's choice: docs/solver-notes.md, "Relaxation and
   * loops"). The windows slide by half their length: a loop is looked for twice a window, while the way is still
   * weighed over a whole one, so slow but sure convergence is not taken for a loop; a window after a slowing, the two
   * steps since it are weighed (see stepStalled), so a loop the slowing did not stop is found a window sooner
   * (docs/solver-notes.md, "A sliding loop window").
   */
  breakLoops(V: Uint32Array, count: number, topology: SkinTopology): void {
    const path = this.path;
    const stepPath = this.stepPath;
    const mark = this.looping;
    const share = this.share;
    let longest = 0;
    for (let k = 0; k < count; k++) {
      const way = path[V[k]] + stepPath[V[k]];
      if (way > longest) longest = way;
    }
    // Skin going less than STILL_MOVE a frame is about to come to rest.
    const least = LOOP_WINDOW * STILL_MOVE * topology.size;
    // Two whole windows must lie behind: the first look's way covers only a step.
    let stalled = this.motionFrames >= 2 * LOOP_WINDOW && longest > least && longest > STALL * this.longestWindowAgo;
    // A window after a slowing, both windows weighed above still hold moves from before it, so a loop the slowing did
    // not stop would be found only a window later: weigh the two steps since the slowing instead.
    if (this.motionFrames === this.slowedAt + LOOP_WINDOW && !stalled) stalled = this.stepStalled(V, count, least / 2);
    this.longestWindowAgo = this.longestStepAgo;
    this.longestStepAgo = longest;
    const far = Math.max(least, STALL_PART * longest);
    const start = topology.neighbourStart;
    const nb = topology.neighbours;
    let marked = 0;
    for (let k = 0; k < count; k++) {
      const v = V[k];
      if (stalled && path[v] + stepPath[v] > far) {
        mark[v] = 1;
        for (let j = start[v]; j < start[v + 1]; j++) mark[nb[j]] = 1;
        marked++;
      }
      stepPath[v] = path[v];
      path[v] = 0;
    }
    if (marked === 0) return;
    this.slowedAt = this.motionFrames;
    // Only the region's shares change: a marked neighbour outside it is at rest and joins, if ever, with a whole share.
    for (let k = 0; k < count; k++) {
      const v = V[k];
      if (mark[v] === 1 && share[v] > LOOP_LEAST_SHARE) share[v] *= LOOP_SLOWING;
    }
    mark.fill(0);
  }

  /** Whether the longest way of the last step is not clearly shorter than the step before's (STALL_STEP). */
  private stepStalled(V: Uint32Array, count: number, least: number): boolean {
    const path = this.path;
    const stepPath = this.stepPath;
    let last = 0;
    let before = 0;
    for (let k = 0; k < count; k++) {
      const v = V[k];
      if (path[v] > last) last = path[v];
      if (stepPath[v] > before) before = stepPath[v];
    }
    return last > least && last > STALL_STEP * before;
  }
}
