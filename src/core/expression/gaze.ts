/**
 * The eye positions of FACS (AU61 eyes turn left, AU62 right, AU63 up, AU64 down, AU65 walleye, AU66 cross-eye) as a
 * gaze: both eyes turn about their centres, by an angle that grows with the unit's intensity up to its E grade, alike
 * for 61 to 64 and mirrored for 65 and 66. The E angles of 61 to 64 are the thesis's gaze range for the eye simulation
 * (5.3.3): 30 degrees to either side, 25 up, 20 down; each eye turns 15 degrees out (65) or in (66), a squint plain
 * in a picture. Left is the subject's left; a positive yaw turns that way, as in the eye simulation. Pure: no DOM, no
 * three.js.
 */

/** Degrees each eye position turns the eyes at intensity 1 (grade E). */
export const GAZE_AT_E = Object.freeze({ left: 30, right: 30, up: 25, down: 20, out: 15, in: 15 });

/** A gaze in degrees: `yaw` toward the subject's left, `pitch` up, and `vergence`, each eye toward the nose (negative: out). */
export interface Gaze {
  yaw: number;
  pitch: number;
  vergence: number;
}

/**
 * The gaze the eye positions ask for, from their effective intensities (0..1) as `read` gives them by id. Opposite
 * units cancel (AU61 and AU62 at 1 look ahead). Writes into `out` and returns it: a driver calls this every frame.
 */
export function actionUnitGaze(read: (id: string) => number, out: Gaze): Gaze {
  out.yaw = GAZE_AT_E.left * read('AU61') - GAZE_AT_E.right * read('AU62');
  out.pitch = GAZE_AT_E.up * read('AU63') - GAZE_AT_E.down * read('AU64');
  out.vergence = GAZE_AT_E.in * read('AU66') - GAZE_AT_E.out * read('AU65');
  return out;
}
