/**
 * The rig's data model: muscles (thesis 3.2 and 4.4), FACS Action Units that drive them (thesis 3.3 and 4.5) and
 * emotion presets that combine Action Units (thesis 5.2). Plain data, as stored in a rig JSON document
 * (`public/rigs/default.json`); positions are in the head model's frame, in metres.
 */

export type Vec3 = [number, number, number];

/**
 * Euler angles in degrees that turn a muscle's local frame within the head: R = Rz * Ry * Rx (x applied first),
 * which is three.js `new Euler(x, y, z, 'ZYX')` in radians.
 */
export type EulerDegrees = [number, number, number];

/** Which side of the face a muscle sits on (the subject's left is +x). */
export type MuscleSide = 'left' | 'right' | 'mid';

/** A brush dab: a sphere at rest, centre xyz and radius, in metres in the head model's frame. */
export type BrushSphere = [x: number, y: number, z: number, radius: number];

/**
 * Skin painted into or out of a muscle's influence (thesis: assigning vertices to muscles), as spheres in rest space,
 * so that it holds at every mesh resolution. Skin in an `add` sphere is held at least as strongly as the sphere
 * gives (full in its inner half, fading to none at its surface), even outside the muscle's zone; skin in a `remove`
 * sphere loses as much of its hold. Removal wins where both overlap.
 */
export interface MuscleBrush {
  add: BrushSphere[];
  remove: BrushSphere[];
}

interface MuscleCommon {
  /** Unique within the rig, e.g. `zygomaticus-major-l`. */
  name: string;
  side: MuscleSide;
  /** Painted influence, on top of the muscle's own zone. */
  brush?: MuscleBrush;
}

/**
 * Waters' linear muscle: anchored to bone at `origin`, inserted in the skin at `insertion`. Skin inside the cone of
 * half-angle `angle` around origin->insertion, closer to the origin than `falloffEnd` x |insertion - origin|, moves
 * toward the origin. Its pull is zero at the bone, rises (cosine) to full at `falloffStart` x length, and falls
 * (cosine) to zero at `falloffEnd` x length; sideways it falls (cosine) to zero at the cone's edge.
 */
export interface LinearMuscle extends MuscleCommon {
  type: 'linear';
  origin: Vec3;
  insertion: Vec3;
  /** Half-angle of the cone, degrees (0..90). */
  angle: number;
  /** Where the radial falloff starts and ends, as fractions of the muscle's length (0 < start < end). */
  falloffStart: number;
  falloffEnd: number;
  /** Fraction of the way to the origin that fully pulled skin moves at contraction 1 (0..1). */
  strength: number;
  /** How much of the pull acts along the skin's normal, 0..1 (low: the skin slides and can fold). */
  normalWeight: number;
}

/**
 * Waters' sphincter muscle (eyes, mouth): an ellipsoid of `radii` around `center`, in the frame turned by
 * `rotation`. Skin inside it is pulled toward the center, scaled per local axis by `scale` (eyes close more
 * vertically, the mouth purses more horizontally); the pull is reduced inside the inner ellipsoid (`innerRadii`) and
 * falls (cosine) to zero at the outer surface. Membership uses squared normalised distances. Inner radii must not
 * exceed the outer ones; `scale` scales the pull's local components (0 on z: no pull in depth; negative: a push away
 * from the center along that axis, as the lips thrust forward while the mouth's ring tightens in a pucker).
 */
export interface SphincterMuscle extends MuscleCommon {
  type: 'sphincter';
  center: Vec3;
  rotation: EulerDegrees;
  radii: Vec3;
  innerRadii: Vec3;
  scale: Vec3;
  strength: number;
  normalWeight: number;
}

/**
 * Rotation muscle for a lid: skin inside the ellipsoid turns about a joint at the ellipsoid's back (center minus
 * radii.z along the local z axis), about the local x axis, by up to `maxAngle` degrees (|maxAngle| <= 90) at
 * contraction 1; the turn fades (cosine) to zero between `innerFraction` of the radii and the surface. A positive
 * angle turns right-handed about local +x (+y toward +z): skin in front of the joint moves down, closing an upper lid.
 */
export interface LidMuscle extends MuscleCommon {
  type: 'lid';
  center: Vec3;
  rotation: EulerDegrees;
  radii: Vec3;
  maxAngle: number;
  innerFraction: number;
}

/**
 * Rotation muscle for the jaw: skin inside the box (`size` = full edge lengths, local frame) turns about the local x
 * axis through `joint` (the jaw hinge; the thesis puts it at the box's back face centre, center minus size.z / 2 along
 * local z, which is the default), by up to `maxAngle` degrees. `curve` opens the lip's middle further than its corners (the thesis's extra
 * term), as a fraction of the
 * angle added at the centre line; the turn fades to zero within `fade` (metres, > 0) of the box's faces, and within
 * `lipFade` (default `fade`) of its top face, which follows the line where the lips part. A positive
 * angle moves the chin down (right-handed about local +x).
 */
export interface JawMuscle extends MuscleCommon {
  type: 'jaw';
  center: Vec3;
  rotation: EulerDegrees;
  size: Vec3;
  /** The hinge the lower face turns about; defaults to the centre of the box's back face. */
  joint?: Vec3;
  maxAngle: number;
  curve: number;
  fade: number;
  /** The top face's fade (metres, > 0): short, so the lips part cleanly while the skin around the jaw stretches. */
  lipFade?: number;
}

export type Muscle = LinearMuscle | SphincterMuscle | LidMuscle | JawMuscle;

/** One muscle an Action Unit drives, on which side of the AU, with what weight (contraction = intensity x weight). */
export interface ActionUnitMuscle {
  muscle: string;
  /** For a bilateral AU, the side this muscle belongs to; `mid` for midline AUs. */
  side: MuscleSide;
  weight: number;
}

/** A FACS Action Unit: `AU12`. Bilateral ones get ids `AU12L` and `AU12R` for their sides. */
export interface ActionUnitDefinition {
  id: string;
  name: string;
  bilateral: boolean;
  muscles: ActionUnitMuscle[];
}

/** A preset expression: Action Unit intensities (ids like `AU12`, `AU12L`, 0..1) scaled by the preset's weight. */
export interface PresetDefinition {
  name: string;
  /** Where it comes from, e.g. "thesis 5.2" or "FACS prototype". */
  source: string;
  actionUnits: Record<string, number>;
  note?: string;
}

/** A whole rig document. */
export interface Rig {
  format: 'softface-rig';
  /** 2 added the muscles' `brush`; version 1 documents are read as version 2. */
  version: 2;
  muscles: Muscle[];
  actionUnits: ActionUnitDefinition[];
  presets: PresetDefinition[];
}
