/**
 * The solver's schedule within a motion (the frames since an input or parameter change): the momentum a frame
 * carries, when stalled or late skin is slowed, and how many orientation passes end a frame. The measurements behind
 * these numbers are in docs/solver-notes.md.
 */

/**
 * A motion's first frames, in which compressed skin chooses its fold pattern, carry at most this share of a move along
 * the normal; the frames after carry `foldMomentum` (0.85 by default). More while the folds form picks longer ones
 * than the skin's wavelength asks for; once formed, folds only rise, sink and slide, slowly, and the larger share
 * moves them there sooner (docs/solver-notes.md, "Fold momentum").
 */
export const FOLD_CHOICE_MOMENTUM = 0.75;
/** Frames after an input or parameter change during which FOLD_CHOICE_MOMENTUM caps the fold momentum. */
export const FOLD_CHOICE_FRAMES = 15;

/**
 * Frames after an input or parameter change that carry `startMomentum` along the surface instead of `momentum`. A
 * motion's first frames take the skin most of its way, and a larger carry there takes it in fewer frames; after them
 * the folds settle, slide and stop, where the larger share made patches circle and chatter (docs/solver-notes.md,
 * "Start momentum").
 */
export const START_MOMENTUM_FRAMES = 10;

/** Frames after an input after which still-moving skin is slowed down for good (see SkinSolver.relax). */
export const LATE_MOTION = 1000;
/** Per frame after LATE_MOTION, the cap on every vertex's share shrinks by this factor. */
export const LATE_SLOWING = 0.98;

/**
 * Frames over which the skin's ways are weighed against the window before (see Relaxation.breakLoops). A loop is
 * found two windows after it starts at the soonest; 24 let the rig's expressions sleep after the fewest frames of 16 to
 * 32 on both heads (docs/solver-notes.md, "Relaxation and loops"), and a shorter window takes slow convergence for a
 * loop ("A shorter loop window").
 */
export const LOOP_WINDOW = 24;
/**
 * Frames between two looks of breakLoops: half a window, so that a loop is found up to half a window sooner, weighed
 * over the whole one (docs/solver-notes.md, "A sliding loop window").
 */
export const LOOP_STEP = LOOP_WINDOW / 2;
/**
 * The stillness the solver was tuned at: no vertex moving more than this in a frame, relative to the mesh size (the
 * sleep tolerance before 1e-5). Two things keep it however loose `sleepTolerance` is (docs/solver-notes.md, "Sleep
 * tolerance"): breakLoops counts skin slower than this as coming to rest, not stalled, so that a looser sleep only
 * stops sooner and moves no skin differently on the way; and skin with a triangle turned over sleeps only this still,
 * as such a fold is often still untangling (at 1e-5 the old African woman's AU46 slept with four turned over, which
 * untangle some 270 frames later), and where it never does (the high head's densest fans) the solver stops where it did.
 */
export const STILL_MOVE = 2e-6;
/** Skin whose longest way in a window is more than this share of the window before's has stalled. */
export const STALL = 0.9;
/** The same over a step (LOOP_STEP), as weighed a window after a slowing: as large a share a frame as STALL's. */
export const STALL_STEP = 0.95;
/** In stalled skin, the vertices that went more than this share of the longest way are slowed, with their neighbours. */
export const STALL_PART = 0.25;
/**
 * The factor on a stalled vertex's share each window (see Relaxation.breakLoops): a quarter brings a loop below the
 * sleep tolerance in fewer windows than a half, without slowing the skin that converges (docs/solver-notes.md).
 */
export const LOOP_SLOWING = 0.25;
/** The least share breakLoops leaves a vertex (a thousandth: its moves are then far below the sleep tolerance). */
export const LOOP_LEAST_SHARE = 1 / 1024;

/**
 * At most this many orientation passes end a frame's iterations, before the relaxation (they stop once one corrects
 * nothing).
 */
export const ORIENTATION_PASSES = 12;
/** After the relaxation at most this many passes follow, at ORIENTATION_SHOWN_FLOOR of the bound. */
export const ORIENTATION_SHOWN_PASSES = 6;
/**
 * The share of the orientation bound the passes after the relaxation hold. A blend of two untangled shapes seldom
 * turns a triangle over but often leaves one a little under the bound; lifting it all the way back moved the fans'
 * skin by more than the relaxation let it, every frame. Half the bound lets the skin sleep sooner, with fewer
 * triangles turned over on the way (docs/solver-notes.md, "Orientation").
 */
export const ORIENTATION_SHOWN_FLOOR = 0.5;
/**
 * At most this many orientation passes untangle a sliver still skin has left turned over (see FramePasses.untangle): the
 * high head's AU20 fans needed about 110 from where the frames left them; with 100 it slept after 154 frames, with 200
 * or more after 97.
 */
export const UNTANGLE_PASSES = 200;
/**
 * The share of the orientation bound the untangling passes hold (see FramePasses.untangle): enough to turn a sliver
 * back, not to lift it to the bound. At ORIENTATION_SHOWN_FLOOR the high head's anger stood still with one sliver
 * turned over for 77 frames, 76 tries failing, and each lift moved the skin up to 0.19 mm; at a tenth each of the
 * high head's expressions measured untangles at its first try, moving the skin at most 0.045 mm (docs/solver-notes.md,
 * "Untangling to a tenth of the bound").
 */
export const UNTANGLE_FLOOR = 0.1;
