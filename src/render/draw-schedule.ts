import { motionDraw, type MotionDrawState } from './motion-draw';

/**
 * How long, and at least how many frames, the view keeps drawing after it was told of a change: covers what lands a
 * frame or two later (the environment map, shader compiles, a panel's change applied in the next task), on a page
 * whose frames come slowly too.
 */
const DRAW_AFTER_CHANGE_MS = 250;
const DRAW_AFTER_CHANGE_FRAMES = 3;

/** What a view draws at an animation frame: nothing, a motion's frame (lower or full resolution), or a still. */
export type FrameDraw = 'skip' | 'reduced' | 'full' | 'still';

/**
 * When a view draws and how (see motionDraw): the frames after a change it was told of, a frame a hook held, a head's
 * first picture, the background alone, the motion's resolution and its end. Holds no three.js object.
 */
export class DrawSchedule {
  /** The view draws at animation frames until this time (ms, performance.now()) and for this many more frames. */
  private drawUntil = 0;
  private drawFrames = 0;
  /** How many times invalidate was called, and the count at the last draw of a scene without a head. */
  private changes = 0;
  private emptyDrawnAt = -1;
  /** Whether the head shown was drawn yet. */
  private headDrawn = false;
  /** A change waits to be drawn (a hook held the frame it came in). */
  private drawPending = false;
  /** The animation frame time at which the schedule last saw something new. */
  private changedAt = 0;
  /** What the schedule knows at an animation frame, for motionDraw; filled in place, the loop allocates nothing. */
  private readonly state: MotionDrawState;

  constructor(motionResolution: number, slowDrawMs: number) {
    this.state = {
      changed: false,
      reduced: false,
      sinceChangeMs: 0,
      moving: false,
      fullDrawMs: 0,
      motionResolution,
      slowDrawMs,
      empty: true,
      drawnSinceChange: false,
      fresh: false,
    };
  }

  /** Something changed outside the frame hooks: draw the next frames. */
  invalidate(): void {
    this.changes++;
    this.drawUntil = performance.now() + DRAW_AFTER_CHANGE_MS;
    this.drawFrames = DRAW_AFTER_CHANGE_FRAMES;
  }

  /** A new head is shown: its first picture is a still. */
  headSet(): void {
    this.headDrawn = false;
  }

  /**
   * The draw of the animation frame at `now`: `changed` whether a hook or the camera changed what it shows, `hold`
   * whether it must wait (a hook holds it, as the skin has not answered an input yet; or the GPU is still at the last
   * draw), `moving` whether a hook says more of the motion is coming, `reduced` whether the canvas shows a picture
   * drawn lower or without antialiasing, `head` whether the scene shows a head, `fullDrawMs` how long the last full
   * draw held the next frame back.
   */
  choose(now: number, changed: boolean, hold: boolean, moving: boolean, reduced: boolean, head: boolean, fullDrawMs: number): FrameDraw {
    const news = changed || this.drawPending || this.drawFrames > 0 || performance.now() < this.drawUntil;
    // An input's other changes (the jaw's turn, the glyphs) wait for the skin's answer, and are drawn with it: a
    // draw of the skin as it was costs as much as any (a third of a second in software WebGL, where it also slows
    // the solver) and shows the teeth ahead of the lips.
    this.drawPending = news && hold;
    if (hold) return 'skip';
    if (news) this.changedAt = now;
    const s = this.state;
    s.changed = news;
    s.reduced = reduced;
    s.sinceChangeMs = now - this.changedAt;
    s.moving = moving;
    s.fullDrawMs = fullDrawMs;
    s.empty = !head;
    s.drawnSinceChange = this.emptyDrawnAt === this.changes;
    s.fresh = !this.headDrawn;
    const draw = motionDraw(s);
    if (draw === 'skip') return draw;
    if (this.drawFrames > 0) this.drawFrames--;
    if (!head) {
      this.emptyDrawnAt = this.changes;
      return draw;
    }
    this.emptyDrawnAt = -1;
    this.headDrawn = true;
    if (draw === 'still') {
      // What the change's frames were to catch is in this picture: they need not be drawn again.
      this.drawUntil = 0;
      this.drawFrames = 0;
    }
    // Nothing new: the motion has ended, and this is its still.
    return draw === 'full' && !news ? 'still' : draw;
  }
}
