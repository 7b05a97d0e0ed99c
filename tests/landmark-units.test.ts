import { describe, expect, it } from 'vitest';
import { LandmarkUnits, TRACKED_UNIT_IDS, type Landmark } from '../src/core/expression/landmark-units';

/** A neutral face's landmarks in a 640 x 480 picture: eyes 60 px apart, the points the tracker reads where a face has them. */
function neutralFace(): Landmark[] {
  const points: [number, number][] = Array.from({ length: 478 }, () => [320, 240]);
  const set = (i: number, x: number, y: number) => (points[i] = [x, y]);
  // Subject's right on the picture's left (a camera, not a mirror).
  set(33, 275, 200); // right eye outer
  set(133, 305, 200); // right eye inner
  for (const [upper, lower, x] of [
    [160, 144, 284],
    [159, 145, 290],
    [158, 153, 296],
    [387, 373, 356],
    [386, 374, 350],
    [385, 380, 344],
  ]) {
    set(upper, x, 195); // upper lid
    set(lower, x, 205); // lower lid
  }
  set(263, 365, 200); // left eye outer
  set(362, 335, 200); // left eye inner
  set(107, 305, 180); // right brow inner (top, bottom)
  set(55, 305, 184);
  set(70, 272, 182); // right brow outer
  set(46, 272, 186);
  set(336, 335, 180);
  set(285, 335, 184);
  set(300, 368, 182);
  set(276, 368, 186);
  set(61, 298, 290); // mouth corners
  set(291, 342, 290);
  set(13, 320, 287); // inner lips
  set(14, 320, 289);
  set(1, 320, 250); // nose tip
  set(10, 320, 130); // the forehead's top
  set(152, 320, 330); // chin
  // The face's sides by the cheekbones, 60 / 0.46 px apart (the eye distance in face widths).
  set(234, 320 - 30 / 0.46, 215);
  set(454, 320 + 30 / 0.46, 215);
  return points.map(([x, y]) => ({ x: x / 640, y: y / 480 }));
}

/** `face` with points moved by (dx, dy) pixels. */
function moved(face: Landmark[], moves: Record<number, [number, number]>): Landmark[] {
  return face.map((p, i) => (moves[i] ? { x: p.x + moves[i][0] / 640, y: p.y + moves[i][1] / 480 } : p));
}

/** The face turned by `degrees` in the picture about its centre. */
function tilted(face: Landmark[], degrees: number): Landmark[] {
  const a = (degrees * Math.PI) / 180;
  return face.map((p) => {
    const x = p.x * 640 - 320;
    const y = p.y * 480 - 240;
    return { x: (320 + x * Math.cos(a) - y * Math.sin(a)) / 640, y: (240 + x * Math.sin(a) + y * Math.cos(a)) / 480 };
  });
}

const at = (u: LandmarkUnits, id: string) => u.values[TRACKED_UNIT_IDS.indexOf(id)];

/** Calibrates on the neutral face for a second (30 frames), then shows `face` for another second. */
function run(face: Landmark[], calibrateOn = neutralFace()): LandmarkUnits {
  const u = new LandmarkUnits({ smoothingMs: 0 });
  let t = 0;
  for (; t <= 1000; t += 33) expect(u.update(calibrateOn, 640, 480, t)).toBe(false);
  expect(u.update(calibrateOn, 640, 480, t)).toBe(true);
  expect(u.calibrated).toBe(true);
  u.update(face, 640, 480, t + 33);
  return u;
}

describe('Action Units from tracker landmarks', () => {
  it('read nothing on the neutral face they calibrated on', () => {
    const u = run(neutralFace());
    // (The neutral face is a mean of equal frames: equal to a rounding error.)
    expect(Math.max(...u.values)).toBeLessThan(1e-9);
  });

  it('raise AU1 and AU2 by side as the brows rise, AU4 as they fall, each at E for a rise of 0.11 eye distances', () => {
    // Eye distance 60 px: 6.6 px up is E.
    const left = run(moved(neutralFace(), { 336: [0, -6.6], 285: [0, -6.6], 300: [0, -3.3], 276: [0, -3.3] }));
    expect(at(left, 'AU1L')).toBeCloseTo(1, 6);
    expect(at(left, 'AU2L')).toBeCloseTo(0.5, 6);
    expect(at(left, 'AU1R')).toBeLessThan(1e-9);
    const down = run(moved(neutralFace(), { 107: [0, 3.3], 55: [0, 3.3] }));
    expect(at(down, 'AU4R')).toBeCloseTo(0.5, 6);
    expect(at(down, 'AU1R')).toBeLessThan(1e-9);
  });

  it('read the smile, the jaw, the lips and closed eyes', () => {
    // The lower lip 4.8 px down takes the corners' reference (a third of the way down the lips' gap) 1.6 px down.
    const u = run(
      moved(neutralFace(), { 291: [3, -4.4], 61: [-3, -1.4], 152: [0, 9], 14: [0, 4.8], 385: [0, 5], 386: [0, 5], 387: [0, 5] }),
    );
    expect(at(u, 'AU12L')).toBeCloseTo(1, 6);
    expect(at(u, 'AU12R')).toBeCloseTo(0.5, 6);
    expect(at(u, 'AU26')).toBeCloseTo(0.5, 6);
    expect(at(u, 'AU25')).toBeCloseTo(1, 6);
    expect(at(u, 'AU43L')).toBeCloseTo(0.5, 6);
    expect(at(u, 'AU43R')).toBeLessThan(1e-9);
  });

  it('read no brow movement when the eyes close and the face mesh drops the eye corners', () => {
    // As the face mesh saw the default head's closed eyes under still brows (in eye distances): the outer corners
    // 0.17 down, the inner 0.075, the nose tip 0.037, the forehead's top 0.026, the brows 0.05 to 0.07 (the whole fit
    // moves). Over the eye corners alone that read as AU1+AU2 0.4.
    const px = (d: number): [number, number] => [0, 60 * d];
    const u = run(
      moved(neutralFace(), {
        33: px(0.17),
        263: px(0.17),
        133: px(0.075),
        362: px(0.075),
        1: px(0.037),
        10: px(0.026),
        107: px(0.05),
        55: px(0.05),
        336: px(0.05),
        285: px(0.05),
        70: px(0.07),
        46: px(0.07),
        300: px(0.07),
        276: px(0.07),
      }),
    );
    for (const id of ['AU1L', 'AU1R', 'AU2L', 'AU2R']) expect(at(u, id), id).toBeLessThan(0.05);
    for (const id of ['AU4L', 'AU4R']) expect(at(u, id), id).toBeLessThan(0.25);
  });

  it('read no brow movement under a smile that takes the nose tip down', () => {
    // As the face mesh saw the default head's smile (AU12) under still brows (eye distances down): the nose tip
    // 0.053, the inner eye corners 0.03, the brows 0.02, the forehead's top 0.017. Over the eye corners and the nose
    // tip that read as AU1+AU2 0.2.
    const px = (d: number): [number, number] => [0, 60 * d];
    const u = run(
      moved(neutralFace(), {
        1: px(0.053),
        133: px(0.03),
        362: px(0.03),
        10: px(0.017),
        107: px(0.02),
        55: px(0.02),
        336: px(0.02),
        285: px(0.02),
        70: px(0.02),
        46: px(0.02),
        300: px(0.02),
        276: px(0.02),
      }),
    );
    for (const id of ['AU1L', 'AU1R', 'AU2L', 'AU2R', 'AU4L', 'AU4R']) expect(at(u, id), id).toBeLessThan(0.1);
  });

  it('read no lip corner pulled down when the jaw drops and the corners follow a third of the lower lip', () => {
    // The jaw at E (0.3 eye distances, 18 px): the lower lip and chin 18 px down, the corners 6. Under the nose, as the
    // corners were measured before, that read as AU15 at E.
    const u = run(moved(neutralFace(), { 152: [0, 18], 14: [0, 18], 61: [0, 6], 291: [0, 6] }));
    expect(at(u, 'AU26')).toBeCloseTo(1, 6);
    for (const id of ['AU15L', 'AU15R', 'AU12L', 'AU12R']) expect(at(u, id), id).toBeLessThan(1e-9);
  });

  it('read no smile when closed lids move the eye corners apart, as the refined face mesh does', () => {
    const closed = run(
      moved(neutralFace(), {
        33: [-4, 0],
        133: [2, 0],
        362: [-2, 0],
        263: [4, 0],
        ...Object.fromEntries([160, 159, 158, 387, 386, 385].map((i) => [i, [0, 9] as [number, number]])),
      }),
    );
    expect(at(closed, 'AU43L')).toBeCloseTo(0.9, 6);
    expect(at(closed, 'AU43R')).toBeCloseTo(0.9, 6);
    for (const id of ['AU12L', 'AU12R', 'AU15L', 'AU15R', 'AU1L', 'AU4L']) expect(at(closed, id), id).toBeLessThan(1e-9);
  });

  it('do not change with the face’s place, size or tilt in the picture', () => {
    const smile = moved(neutralFace(), { 291: [0, -3], 61: [0, -3] });
    const straight = run(smile);
    const turned = run(tilted(smile, 20), tilted(neutralFace(), 20));
    for (let i = 0; i < TRACKED_UNIT_IDS.length; i++) expect(turned.values[i], TRACKED_UNIT_IDS[i]).toBeCloseTo(straight.values[i], 6);
    expect(at(straight, 'AU12L')).toBeCloseTo(0.5, 6);
  });

  it('smooth toward a new value with the time constant, and calibrate again after a reset', () => {
    const u = new LandmarkUnits({ smoothingMs: 50, calibrationMs: 100 });
    const face = neutralFace();
    for (let t = 0; t <= 100; t += 20) u.update(face, 640, 480, t);
    const up = moved(face, { 336: [0, -6.6], 285: [0, -6.6] });
    u.update(up, 640, 480, 150);
    expect(at(u, 'AU1L')).toBeCloseTo(1 - Math.exp(-1), 6);
    u.reset();
    expect(u.calibrated).toBe(false);
    expect(u.update(up, 640, 480, 200)).toBe(false);
    // Too few landmarks: not read.
    expect(u.update(face.slice(0, 100), 640, 480, 400)).toBe(false);
  });
});
