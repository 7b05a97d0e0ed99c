/**
 * The render loop's choice at an animation frame: skip it, or draw at the motion's lower resolution or at full. Pure:
 * no three.js, no DOM, so that the policy is tested on its own.
 */

/**
 * How long nothing new must come before a picture drawn at the motion's lower resolution is drawn again at full: the
 * motion has ended. Longer than the gap between two solver frames, so that a full draw does not land in the middle of
 * the motion (docs/page-notes.md).
 */
export const MOTION_END_MS = 100;

/**
 * How long nothing new may come from a skin whose solver still works before its picture is drawn at full all the same
 * (a solver that stopped answering). A loaded machine's solver frames come seconds apart only when something is wrong.
 */
export const MOTION_STALL_MS = 1_000;

/** What the loop knows at an animation frame. */
export interface MotionDrawState {
  /** Whether the frame shows something new (new skin, turned eyes, a moved camera). */
  changed: boolean;
  /** Whether the canvas is at the motion's lower resolution now. */
  reduced: boolean;
  /** Milliseconds since the loop last saw something new. */
  sinceChangeMs: number;
  /** Whether nothing is new at this frame but more of the motion is coming (the solver of the skin shown still works). */
  moving: boolean;
  /** How long the last full-resolution draw held the next animation frame back (the page waits there for the GPU). */
  fullDrawMs: number;
  /** Share of the pixel ratio drawn at while the picture changes and draws are slow; 1 turns the lower one off. */
  motionResolution: number;
  /** A full draw slower than this (ms) is slow. */
  slowDrawMs: number;
  /** Whether the scene shows no head (the background alone). */
  empty: boolean;
  /** Whether the picture on the canvas shows the latest change already (kept only for a scene without a head). */
  drawnSinceChange: boolean;
  /** Whether the head shown was never drawn yet (just set). */
  fresh: boolean;
}

/**
 * While the picture changes, slow draws go at the lower resolution: a slow full draw shares the cores with the solver,
 * and the answer to an input reaches the screen later (docs/page-notes.md). The motion's first draw decides by the
 * last full one, so a GPU that keeps up never draws lower. Nothing new: a picture drawn lower is drawn again at full
 * once the motion has ended: nothing new for MOTION_END_MS and no hook saying more is coming (on a loaded machine the
 * solver's frames come further apart than MOTION_END_MS, and a full draw between two of them is a slow draw in the
 * middle of the motion); otherwise nothing is drawn. A head just set is drawn once, as the finished picture
 * (`still`), even where its skin already moves (the solver's first frames, or a head switched under an expression: one
 * still, then the motion); the background alone, once for each change, at full resolution. (At a page's start in
 * software WebGL the head used to come as four lower draws and a still, the background as two draws at two
 * resolutions: a second of the GPU's time, and each switch of resolution reallocates the canvas.)
 */
export function motionDraw(s: MotionDrawState): 'skip' | 'reduced' | 'full' | 'still' {
  if (s.empty) return s.changed && !s.drawnSinceChange ? 'full' : 'skip';
  if (s.fresh) return 'still';
  if (s.changed) return s.motionResolution < 1 && s.fullDrawMs > s.slowDrawMs ? 'reduced' : 'full';
  return s.reduced && s.sinceChangeMs >= (s.moving ? MOTION_STALL_MS : MOTION_END_MS) ? 'full' : 'skip';
}
