/**
 * The render loop's choice at an animation frame: skip it, or draw at the motion's lower resolution or at full. Pure:
 * no three.js, no DOM, so that the policy is tested on its own.
 */

/**
 * How long nothing new must come before a picture drawn at the motion's lower resolution is drawn again at full: the
 * motion has ended. An animation frame can come a few milliseconds after a slow one, before the solver's next frame
 * (one every 10 to 20 ms while the skin moves); going to full resolution there cost software WebGL a full draw and a
 * new canvas in the middle of the motion, 300 to 560 ms in which the page read nothing new.
 */
export const MOTION_END_MS = 100;

/** What the loop knows at an animation frame. */
export interface MotionDrawState {
  /** Whether the frame shows something new (new skin, turned eyes, a moved camera). */
  changed: boolean;
  /** Whether the canvas is at the motion's lower resolution now. */
  reduced: boolean;
  /** Milliseconds since the loop last saw something new. */
  sinceChangeMs: number;
  /** How long the last full-resolution draw held the next animation frame back (the page waits there for the GPU). */
  fullDrawMs: number;
  /** Share of the pixel ratio drawn at while the picture changes and draws are slow; 1 turns the lower one off. */
  motionResolution: number;
  /** A full draw slower than this (ms) is slow. */
  slowDrawMs: number;
}

/**
 * While the picture changes, slow draws go at the lower resolution: in software WebGL a full one costs two threads
 * about 180 ms, in which the solver shares the cores with it, and the answer to an input reaches the screen later.
 * The motion's first draw decides by the last full one, so a GPU that keeps up never draws lower. Nothing new: a
 * picture drawn lower is drawn again at full once the motion has ended (MOTION_END_MS); otherwise nothing is drawn.
 */
export function motionDraw(s: MotionDrawState): 'skip' | 'reduced' | 'full' {
  if (s.changed) return s.motionResolution < 1 && s.fullDrawMs > s.slowDrawMs ? 'reduced' : 'full';
  return s.reduced && s.sinceChangeMs >= MOTION_END_MS ? 'full' : 'skip';
}
