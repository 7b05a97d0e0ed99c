/**
 * The accepted values of every number field of a muscle, in one table: the rig schema (rig-schema.ts) builds its
 * number checks from it, `validateMuscle` checks muscles handed to the solver against it, and the muscle panel takes
 * its sliders' bounds and steps from it, so that the three cannot drift apart.
 */
import { numberIn, type Range } from '../check';
import type { Muscle, Vec3 } from './rig-types';

/**
 * Farthest a muscle point may lie from the model's origin, and largest radius or box edge, in metres. The head is
 * about 0.25 m across; a point kilometres away would make the solver's targets (and the skin) run off to infinity.
 */
const MAX_RIG_DISTANCE = 10;
/** Farthest a jaw's top face may bend down (or up) toward the mouth's corners, metres: a lip line, not a new box. */
const MAX_LIP_DROP = 0.02;

/** The accepted values of one number field (or of each number of an [x, y, z] field), and how the panel offers it. */
export interface FieldRange {
  /** Least and greatest accepted value. */
  readonly range: Range;
  /** A bound that is itself refused: a length must be above 0, a lid's innerFraction below 1. */
  readonly open?: 'least' | 'greatest';
  /** What messages call an accepted value, as in `expected a number from 0 to 1`. */
  readonly expected: string;
  /** The panel's step. */
  readonly step: number;
  /**
   * The panel slider's bounds where they are narrower than `range`: a slider cannot stop short of an open bound, and
   * one across a falloff's 0 to 100 could not be dragged finely over the values rigs use.
   */
  readonly slider?: Range;
  /** The field is [x, y, z], each number in the range. */
  readonly vector?: boolean;
  /** The field may be left out (a jaw's joint and lipFade). */
  readonly optional?: boolean;
}

/** Whether `x` is a finite number that `field` accepts (one number; an [x, y, z] field's numbers one by one). */
export function accepts(field: FieldRange, x: unknown): x is number {
  if (typeof x !== 'number' || !Number.isFinite(x)) return false;
  const [least, greatest] = field.range;
  const aboveLeast = field.open === 'least' ? x > least : x >= least;
  const belowGreatest = field.open === 'greatest' ? x < greatest : x <= greatest;
  return aboveLeast && belowGreatest;
}

const fraction: FieldRange = { range: [0, 1], expected: numberIn([0, 1]), step: 0.01 };
const coordinate: FieldRange = {
  range: [-MAX_RIG_DISTANCE, MAX_RIG_DISTANCE],
  expected: `a coordinate within ±${MAX_RIG_DISTANCE} m`,
  step: 0.0005,
  vector: true,
};
const rotation: FieldRange = { range: [-360, 360], expected: 'an angle from -360 to 360 degrees', step: 0.5, vector: true };
/** A radius, box edge or fade: positive and at most MAX_RIG_DISTANCE. */
const extent = (more: Partial<FieldRange> = {}): FieldRange => ({
  range: [0, MAX_RIG_DISTANCE],
  open: 'least',
  expected: `a positive length of at most ${MAX_RIG_DISTANCE} m`,
  step: 0.0005,
  ...more,
});
const angle = (least: number, greatest: number): FieldRange => ({
  range: [least, greatest],
  expected: `an angle from ${least} to ${greatest} degrees`,
  step: 0.5,
});
/** A falloff as a fraction of a linear muscle's length. */
const falloff: FieldRange = { range: [0, 100], open: 'least', expected: 'a positive number of at most 100', step: 0.01, slider: [0.01, 3] };

/** The fields of muscle type `T` that hold a number or an [x, y, z]. */
type NumberFields<T extends Muscle['type']> = {
  [K in keyof Extract<Muscle, { type: T }>]-?: Extract<Muscle, { type: T }>[K] extends number | Vec3 | undefined ? K : never;
}[keyof Extract<Muscle, { type: T }>];

/**
 * Every number field of every muscle type with its accepted values, in the order the schema checks them. The type
 * makes a field added to a muscle (rig-types.ts) without a range here fail to compile.
 */
export const MUSCLE_RANGES: { readonly [T in Muscle['type']]: Readonly<Record<NumberFields<T>, FieldRange>> } = {
  linear: {
    origin: coordinate,
    insertion: coordinate,
    angle: angle(0, 90),
    falloffStart: falloff,
    falloffEnd: falloff,
    strength: fraction,
    normalWeight: fraction,
  },
  sphincter: {
    center: coordinate,
    rotation,
    radii: extent({ vector: true }),
    // Positive: the pull inside the inner ellipsoid is scaled by the distance over these radii.
    innerRadii: extent({ vector: true }),
    // Negative pushes away from the center along that axis (a pucker thrusts the lips forward).
    scale: { range: [-10, 10], expected: numberIn([-10, 10]), step: 0.01, vector: true },
    strength: fraction,
    normalWeight: fraction,
  },
  lid: {
    center: coordinate,
    rotation,
    radii: extent({ vector: true }),
    maxAngle: angle(-90, 90),
    // Below 1: the fade runs from innerFraction to the surface, and must have a width.
    innerFraction: { range: [0, 1], open: 'greatest', expected: 'a number from 0 to below 1', step: 0.01, slider: [0, 0.99] },
  },
  jaw: {
    center: coordinate,
    rotation,
    size: extent({ vector: true }),
    joint: { ...coordinate, optional: true },
    maxAngle: angle(-90, 90),
    curve: fraction,
    // Positive: without a fade the turn would stop in a step at the box's faces.
    fade: extent({ slider: [0.001, 0.05] }),
    lipFade: extent({ optional: true }),
    lipDrop: {
      range: [-MAX_LIP_DROP, MAX_LIP_DROP],
      expected: `a length within ±${MAX_LIP_DROP} m`,
      step: 0.0001,
      optional: true,
    },
    lipHalfWidth: extent({ optional: true, slider: [0.005, 0.05] }),
  },
};

/** Largest brush sphere radius, in metres. */
const MAX_BRUSH_RADIUS = 0.1;

/** The numbers of a brush sphere [x, y, z, radius]: its centre's coordinates, and its radius. */
export const BRUSH_RANGES: { readonly coordinate: FieldRange; readonly radius: FieldRange } = {
  coordinate,
  radius: { range: [0, MAX_BRUSH_RADIUS], open: 'least', expected: `a positive radius of at most ${MAX_BRUSH_RADIUS} m`, step: 0.0005 },
};
