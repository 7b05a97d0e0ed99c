/**
 * Action Unit intensities from a face tracker's landmarks (MediaPipe Face Mesh's 468 points, or 478 with its refined
 * eyes and lips, image-normalised): a few distances in the face's own frame (across the face and up it, in eye
 * distances, so that the face's size, place and tilt in the picture drop out), taken relative to the viewer's neutral
 * face (their mean over a calibration
 * time at the start), each scaled by how far it moves when the unit is at its E grade, clamped and smoothed. The
 * distances: each brow's inner and outer part above the eye, each lid's opening (at three places), each mouth corner's height over the
 * lips' gap, the lips' inner gap and the nose-to-chin distance. Pure: no DOM, no three.js.
 */

/** A tracker's landmark: `x` and `y` as fractions of the picture's width and height (MediaPipe's NormalizedLandmark). */
export interface Landmark {
  x: number;
  y: number;
}

/** MediaPipe Face Mesh's points used (its canonical mesh's indices; right and left are the subject's). */
const P = Object.freeze({
  rightEyeOuter: 33,
  rightEyeInner: 133,
  rightUpperLid: 159,
  rightLowerLid: 145,
  rightUpperLidInner: 158,
  rightLowerLidInner: 153,
  rightUpperLidOuter: 160,
  rightLowerLidOuter: 144,
  leftEyeOuter: 263,
  leftEyeInner: 362,
  leftUpperLid: 386,
  leftLowerLid: 374,
  leftUpperLidInner: 385,
  leftLowerLidInner: 380,
  leftUpperLidOuter: 387,
  leftLowerLidOuter: 373,
  rightBrowInnerTop: 107,
  rightBrowInnerBottom: 55,
  rightBrowOuterTop: 70,
  rightBrowOuterBottom: 46,
  leftBrowInnerTop: 336,
  leftBrowInnerBottom: 285,
  leftBrowOuterTop: 300,
  leftBrowOuterBottom: 276,
  rightMouthCorner: 61,
  leftMouthCorner: 291,
  upperLipInner: 13,
  lowerLipInner: 14,
  noseTip: 1,
  foreheadTop: 10,
  chin: 152,
  rightFaceSide: 234,
  leftFaceSide: 454,
});

/**
 * How far the mouth corners follow the lower lip's inner edge when the jaw drops: a third (the default head's AU26
 * seen by the face mesh: the corners 0.09 to 0.11 eye distances down, the lower lip 0.28 to 0.31, the upper lip 0.02).
 */
const CORNER_GAP_SHARE = 1 / 3;

/** The most landmark index read: a tracker must give at least this many points plus one. */
const LANDMARKS_NEEDED = 454 + 1;

// The measures, in eye distances.
const BROW_INNER_L = 0;
const BROW_INNER_R = 1;
const BROW_OUTER_L = 2;
const BROW_OUTER_R = 3;
const LID_L = 4;
const LID_R = 5;
const CORNER_L = 6;
const CORNER_R = 7;
const LIP_GAP = 8;
const JAW = 9;
const MEASURES = 10;

/** The Action Unit sides the tracker sets, in the order `LandmarkUnits.values` has them. */
export const TRACKED_UNIT_IDS: readonly string[] = Object.freeze([
  'AU1L',
  'AU1R',
  'AU2L',
  'AU2R',
  'AU4L',
  'AU4R',
  'AU5L',
  'AU5R',
  'AU12L',
  'AU12R',
  'AU15L',
  'AU15R',
  'AU25',
  'AU26',
  'AU43L',
  'AU43R',
]);

/**
 * How far each measure moves (eye distances, about 62 mm on an adult) when its unit is at E: the FACS amounts of
 * docs/features.md's table over that distance (brows 5 to 10 mm, the upper lid 2 to 4, a lip corner's rise 6, the
 * jaw's drop 15 to 25).
 */
const AT_E = Object.freeze({ brow: 0.11, lidRaise: 0.05, cornerUp: 0.1, cornerDown: 0.08, lipGap: 0.08, jaw: 0.3 });

function clamp(x: number): number {
  return x < 0 ? 0 : x > 1 ? 1 : x;
}

/**
 * Eye distances (eye centre to eye centre) in the face's width at its sides by the cheekbones (points 234 and 454):
 * 0.46 on the faces measured (about 63 mm in 137 mm on an adult). The frame is taken from the face's sides, not from
 * the eyes, because the refined face mesh moves the eye corners apart by up to 8 % when the lids close, which read
 * as a smile.
 */
const EYES_PER_FACE_WIDTH = 0.46;

/** How a tracker's landmarks become Action Units: the calibration time and the smoothing. */
export interface LandmarkUnitsOptions {
  /** Milliseconds of frames at the start averaged as the neutral face; default 1000. */
  calibrationMs?: number;
  /** Time constant of the exponential smoothing, milliseconds; default 50 (0 for none). */
  smoothingMs?: number;
}

const DEFAULTS: Readonly<Required<LandmarkUnitsOptions>> = { calibrationMs: 1000, smoothingMs: 50 };

/** Turns landmark frames into Action Unit intensities (see the module's summary). Allocates nothing per frame. */
export class LandmarkUnits {
  /** The smoothed intensities, in TRACKED_UNIT_IDS' order (0 until calibrated). */
  readonly values = new Float64Array(TRACKED_UNIT_IDS.length);
  private readonly o: Required<LandmarkUnitsOptions>;
  private readonly measures = new Float64Array(MEASURES);
  private readonly neutral = new Float64Array(MEASURES);
  private readonly raw = new Float64Array(TRACKED_UNIT_IDS.length);
  private frames = 0;
  private startedAt = Number.NaN;
  private lastAt = Number.NaN;
  private done = false;
  private width = 1;
  private height = 1;
  /** The frame measured last: its eye distance (pixels) and the face's up direction in the picture. */
  private eyes = 1;
  private upX = 0;
  private upY = -1;

  constructor(options: LandmarkUnitsOptions = {}) {
    this.o = { ...DEFAULTS, ...options };
  }

  /** Whether the neutral face is known (the calibration time has passed with a face in view). */
  get calibrated(): boolean {
    return this.done;
  }

  /** Forgets the neutral face and the intensities: the next frames calibrate again. */
  reset(): void {
    this.values.fill(0);
    this.neutral.fill(0);
    this.frames = 0;
    this.startedAt = Number.NaN;
    this.lastAt = Number.NaN;
    this.done = false;
  }

  /**
   * Takes one frame's landmarks (a picture `width` x `height` pixels, at `timeMs`); returns whether the intensities
   * are up to date (false while calibrating).
   */
  update(landmarks: ArrayLike<Landmark>, width: number, height: number, timeMs: number): boolean {
    if (landmarks.length < LANDMARKS_NEEDED) return false;
    this.width = width;
    this.height = height;
    this.measure(landmarks);
    if (!this.done) {
      if (Number.isNaN(this.startedAt)) this.startedAt = timeMs;
      for (let i = 0; i < MEASURES; i++) this.neutral[i] += this.measures[i];
      this.frames++;
      if (timeMs - this.startedAt < this.o.calibrationMs) return false;
      for (let i = 0; i < MEASURES; i++) this.neutral[i] /= this.frames;
      this.done = true;
      this.lastAt = timeMs;
    }
    this.intensities();
    const dt = Number.isNaN(this.lastAt) ? 0 : Math.max(0, timeMs - this.lastAt);
    this.lastAt = timeMs;
    const share = this.o.smoothingMs > 0 ? 1 - Math.exp(-dt / this.o.smoothingMs) : 1;
    for (let i = 0; i < this.values.length; i++) this.values[i] += share * (this.raw[i] - this.values[i]);
    return true;
  }

  /** The measures of one frame, into `measures`. */
  private measure(l: ArrayLike<Landmark>): void {
    const w = this.width;
    const h = this.height;
    // The face's frame: x from its right side to its left, up perpendicular (the picture's y runs down).
    const rx = l[P.rightFaceSide].x * w;
    const ry = l[P.rightFaceSide].y * h;
    const lx = l[P.leftFaceSide].x * w;
    const ly = l[P.leftFaceSide].y * h;
    const across = Math.hypot(lx - rx, ly - ry) || 1;
    this.eyes = across * EYES_PER_FACE_WIDTH;
    // "Up" in the face: the across axis turned a quarter, toward the top of the picture.
    this.upX = (ly - ry) / across;
    this.upY = -(lx - rx) / across;
    const m = this.measures;
    // The brows' height over the inner eye corner and the forehead's top together. The face mesh moves its whole fit
    // with what it sees, so no single point stands still: as the eyes close it drops the eye corners (on the default
    // head, with the brows still, the inner ones 0.055 to 0.075 eye distances, the brows 0.045 to 0.065, the forehead's
    // top 0.026), under a smile the nose tip (0.053, the eye corners 0.03, the brows 0.02, the forehead's top 0.017),
    // and as the brows rise it lifts the forehead's top by 0.021 and the eye corners by up to 0.015 (the brows 0.047).
    // Over the eye corners alone closed eyes read as AU1+AU2 0.4; over the corners and the nose tip a smile read as
    // 0.2 and a brow raise as 0.3; over the corners and the forehead's top each reads within 0.006 of still brows.
    const left = this.up2(l, P.leftEyeInner, P.foreheadTop);
    const right = this.up2(l, P.rightEyeInner, P.foreheadTop);
    m[BROW_INNER_L] = this.up2(l, P.leftBrowInnerTop, P.leftBrowInnerBottom) - left;
    m[BROW_INNER_R] = this.up2(l, P.rightBrowInnerTop, P.rightBrowInnerBottom) - right;
    m[BROW_OUTER_L] = this.up2(l, P.leftBrowOuterTop, P.leftBrowOuterBottom) - left;
    m[BROW_OUTER_R] = this.up2(l, P.rightBrowOuterTop, P.rightBrowOuterBottom) - right;
    // Each lid's opening at three places across the eye, averaged: one pair of points is noisy.
    m[LID_L] =
      (this.gap(l, P.leftUpperLid, P.leftLowerLid) +
        this.gap(l, P.leftUpperLidInner, P.leftLowerLidInner) +
        this.gap(l, P.leftUpperLidOuter, P.leftLowerLidOuter)) /
      3;
    m[LID_R] =
      (this.gap(l, P.rightUpperLid, P.rightLowerLid) +
        this.gap(l, P.rightUpperLidInner, P.rightLowerLidInner) +
        this.gap(l, P.rightUpperLidOuter, P.rightLowerLidOuter)) /
      3;
    // Each corner over the lips' gap a third of the way down (CORNER_GAP_SHARE), not under the nose: a dropping jaw
    // takes the corners down too, which under the nose read as the corners pulled down (AU15 at E with AU26).
    const upper = this.up(l, P.upperLipInner);
    const mouth = upper + CORNER_GAP_SHARE * (this.up(l, P.lowerLipInner) - upper);
    m[CORNER_L] = this.up(l, P.leftMouthCorner) - mouth;
    m[CORNER_R] = this.up(l, P.rightMouthCorner) - mouth;
    m[LIP_GAP] = this.gap(l, P.upperLipInner, P.lowerLipInner);
    m[JAW] = this.up(l, P.noseTip) - this.up(l, P.chin);
  }

  /** How high point `i` is in the face's frame, in eye distances. */
  private up(l: ArrayLike<Landmark>, i: number): number {
    return (l[i].x * this.width * this.upX + l[i].y * this.height * this.upY) / this.eyes;
  }

  private up2(l: ArrayLike<Landmark>, i: number, j: number): number {
    return (this.up(l, i) + this.up(l, j)) * 0.5;
  }

  /** The distance of points `i` and `j`, in eye distances. */
  private gap(l: ArrayLike<Landmark>, i: number, j: number): number {
    return Math.hypot((l[i].x - l[j].x) * this.width, (l[i].y - l[j].y) * this.height) / this.eyes;
  }

  /** The unsmoothed intensities of the frame measured last, into `raw` (TRACKED_UNIT_IDS' order). */
  private intensities(): void {
    const m = this.measures;
    const n = this.neutral;
    const r = this.raw;
    r[0] = clamp((m[BROW_INNER_L] - n[BROW_INNER_L]) / AT_E.brow);
    r[1] = clamp((m[BROW_INNER_R] - n[BROW_INNER_R]) / AT_E.brow);
    r[2] = clamp((m[BROW_OUTER_L] - n[BROW_OUTER_L]) / AT_E.brow);
    r[3] = clamp((m[BROW_OUTER_R] - n[BROW_OUTER_R]) / AT_E.brow);
    r[4] = clamp((n[BROW_INNER_L] - m[BROW_INNER_L]) / AT_E.brow);
    r[5] = clamp((n[BROW_INNER_R] - m[BROW_INNER_R]) / AT_E.brow);
    r[6] = clamp((m[LID_L] - n[LID_L]) / AT_E.lidRaise);
    r[7] = clamp((m[LID_R] - n[LID_R]) / AT_E.lidRaise);
    r[8] = clamp((m[CORNER_L] - n[CORNER_L]) / AT_E.cornerUp);
    r[9] = clamp((m[CORNER_R] - n[CORNER_R]) / AT_E.cornerUp);
    r[10] = clamp((n[CORNER_L] - m[CORNER_L]) / AT_E.cornerDown);
    r[11] = clamp((n[CORNER_R] - m[CORNER_R]) / AT_E.cornerDown);
    r[12] = clamp((m[LIP_GAP] - n[LIP_GAP]) / AT_E.lipGap);
    r[13] = clamp((m[JAW] - n[JAW]) / AT_E.jaw);
    // Closed: the opening gone, as a share of the neutral opening.
    r[14] = n[LID_L] > 0 ? clamp(1 - m[LID_L] / n[LID_L]) : 0;
    r[15] = n[LID_R] > 0 ? clamp(1 - m[LID_R] / n[LID_R]) : 0;
  }
}
