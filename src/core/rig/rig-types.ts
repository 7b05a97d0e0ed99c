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
  /** Spheres that paint skin into the muscle's influence (at most 4096). */
  add: BrushSphere[];
  /** Spheres that paint skin out of the muscle's influence (at most 4096); they win where they overlap `add`. */
  remove: BrushSphere[];
}

interface MuscleCommon {
  /** Unique within the rig, e.g. `zygomaticus-major-l`. */
  name: string;
  /**
   * Which side of the face the muscle is on: a bilateral Action Unit links it on this side, and mirroring swaps left
   * and right.
   */
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
  /** Tells a linear muscle apart among the `Muscle` types. */
  type: 'linear';
  /** Where the muscle is anchored to bone, metres in the head model's frame: the skin is pulled toward it. */
  origin: Vec3;
  /**
   * Where the muscle inserts into the skin, metres in the head model's frame (apart from `origin`): with the origin it
   * sets the cone's axis and the muscle's length.
   */
  insertion: Vec3;
  /** Half-angle of the cone, degrees (0..90). */
  angle: number;
  /**
   * Where the pull is full, as a fraction of the muscle's length from the origin (above 0, below `falloffEnd`): it
   * rises (cosine) from none at the bone to full here.
   */
  falloffStart: number;
  /**
   * Where the pull has fallen (cosine) to none, as a fraction of the muscle's length from the origin (above
   * `falloffStart`, at most 100): skin farther from the origin is not pulled.
   */
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
  /** Tells a sphincter muscle apart among the `Muscle` types. */
  type: 'sphincter';
  /** Centre of the ellipsoids, metres in the head model's frame: the skin is pulled toward it. */
  center: Vec3;
  /** Turns the local frame the radii and `scale` are measured in (degrees, -360..360 each). */
  rotation: EulerDegrees;
  /** Semi-axes of the outer ellipsoid along the local x, y, z axes, metres (> 0): at its surface the pull is none. */
  radii: Vec3;
  /**
   * Semi-axes of the inner ellipsoid, metres (> 0, each at most the matching one of `radii`): the pull is full on its
   * surface and falls (cosine) to none at the centre, so the skin there is not over-compressed.
   */
  innerRadii: Vec3;
  /**
   * Pull along each local axis x, y, z, as a factor of the pull toward the centre (-10..10): 0 pulls not at all along
   * that axis, a negative factor pushes away from the centre.
   */
  scale: Vec3;
  /** Fraction of the way to the centre that fully pulled skin moves at contraction 1 (0..1), before `scale`. */
  strength: number;
  /** How much of the pull acts along the skin's normal, 0..1 (low: the skin slides and can fold). */
  normalWeight: number;
}

/**
 * Rotation muscle for a lid: skin inside the ellipsoid turns about a joint at the ellipsoid's back (center minus
 * radii.z along the local z axis), about the local x axis, by up to `maxAngle` degrees (|maxAngle| <= 90) at
 * contraction 1; the turn fades (cosine) to zero between `innerFraction` of the radii and the surface. A positive
 * angle turns right-handed about local +x (+y toward +z): skin in front of the joint moves down, closing an upper lid.
 */
export interface LidMuscle extends MuscleCommon {
  /** Tells a lid muscle apart among the `Muscle` types. */
  type: 'lid';
  /** Centre of the ellipsoid, metres in the head model's frame; the hinge lies `radii[2]` behind it along local z. */
  center: Vec3;
  /** Turns the ellipsoid's local frame (degrees, -360..360 each); the lid turns about the local x axis. */
  rotation: EulerDegrees;
  /** Semi-axes of the ellipsoid along the local x, y, z axes, metres (> 0). */
  radii: Vec3;
  /**
   * The turn at contraction 1, degrees (-90..90): positive moves skin in front of the hinge down (closing an upper
   * lid), negative moves it up.
   */
  maxAngle: number;
  /**
   * Normalised distance from the centre (0 to below 1, as a fraction of the radii) within which the skin turns fully;
   * from there the turn fades (cosine) to none at the surface.
   */
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
  /** Tells a jaw muscle apart among the `Muscle` types. */
  type: 'jaw';
  /** Centre of the box, metres in the head model's frame. */
  center: Vec3;
  /** Turns the box's local frame (degrees, -360..360 each); the lower face turns about the local x axis. */
  rotation: EulerDegrees;
  /** Full edge lengths of the box along its local x, y, z axes, metres (> 0). */
  size: Vec3;
  /**
   * The hinge the lower face turns about; defaults to the centre of the box's back face. A real jaw's condyle glides
   * forward as it turns, so the opening jaw turns about a centre well below it, near the ramus's middle: a hinge
   * placed there drops the chin instead of swinging it back into the neck (the default rig's is).
   */
  joint?: Vec3;
  /** The turn at contraction 1, degrees (-90..90), before `curve` adds to it: positive moves the chin down. */
  maxAngle: number;
  /**
   * Extra turn at the box's centre line, as a fraction of the angle (0..1), falling as a parabola to none at its sides:
   * the lower lip's middle opens further than its corners.
   */
  curve: number;
  /**
   * Depth inside the box's faces over which the turn fades (cosine) from none on a face to full, metres (> 0); the top
   * face uses `lipFade` when it is given.
   */
  fade: number;
  /**
   * The top face's fade (metres, > 0): short, so the lips part cleanly while the skin around the jaw stretches. Put the
   * top face between the lips and keep this under their gap, or the lower lip's top turns less than its body and is
   * pulled long as the jaw opens.
   */
  lipFade?: number;
  /**
   * How far the top face lies lower `lipHalfWidth` or more to either side of the box's centre line than on it, metres
   * (negative: higher; default 0, a flat face): a parabola across the mouth, so that the face follows a lip line that
   * falls (or rises) toward the mouth's corners instead of cutting through the upper lip's sides.
   */
  lipDrop?: number;
  /** Half the width (metres, > 0) over which the top face bends by `lipDrop`; defaults to half the box's width. */
  lipHalfWidth?: number;
}

/** A muscle of a rig, of any of the four kinds, told apart by its `type`. */
export type Muscle = LinearMuscle | SphincterMuscle | LidMuscle | JawMuscle;

/** One muscle an Action Unit drives, on which side of the AU, with what weight (contraction = intensity x weight). */
export interface ActionUnitMuscle {
  /** Name of the muscle driven, as in the rig's `muscles`. */
  muscle: string;
  /** For a bilateral AU, the side this muscle belongs to; `mid` for midline AUs. */
  side: MuscleSide;
  /**
   * How strongly the AU contracts the muscle (above 0, at most 10): contraction = intensity x weight, summed over the
   * AUs that drive the muscle and capped at 1.
   */
  weight: number;
}

/** A FACS Action Unit: `AU12`. Bilateral ones get ids `AU12L` and `AU12R` for their sides. */
export interface ActionUnitDefinition {
  /** The unit's FACS id, `AU` and its number (`AU12`); it must be one of the built-in catalogue's. */
  id: string;
  /** The unit's FACS name, e.g. `lip corner puller`. */
  name: string;
  /**
   * Whether each side of the face is set on its own (ids `AU12L` and `AU12R`, muscles linked on `left` and `right`),
   * rather than once for the midline; it must agree with the built-in catalogue.
   */
  bilateral: boolean;
  /** The muscles the unit contracts, with their sides and weights (at least one). */
  muscles: ActionUnitMuscle[];
}

/** A preset expression: Action Unit intensities (ids like `AU12`, `AU12L`, 0..1) scaled by the preset's weight. */
export interface PresetDefinition {
  /** The preset's name, unique within the rig, by which it is applied (`applyPreset`), e.g. `thesis-happiness`. */
  name: string;
  /** Where it comes from, e.g. "thesis 5.2" or "FACS prototype". */
  source: string;
  /**
   * The Action Unit intensities at full weight, by id (`AU12` sets both sides, `AU12L` or `AU12R` one), each 0..1; the
   * preset's weight (0..1) scales them.
   */
  actionUnits: Record<string, number>;
  /** Free-text remarks on how the preset was made; `listPresets` returns them with the `source`. */
  note?: string;
}

/** A whole rig document. */
export interface Rig {
  /** Marks the JSON document as a softface rig: always `softface-rig`. */
  format: 'softface-rig';
  /** 2 added the muscles' `brush`; version 1 documents are read as version 2. */
  version: 2;
  /** The muscles (at most 256), with unique names. */
  muscles: Muscle[];
  /** The Action Units the rig drives (at most 64), each with the muscles it contracts; ids are unique. */
  actionUnits: ActionUnitDefinition[];
  /** The preset expressions (at most 256), each a weighted mix of Action Unit intensities. */
  presets: PresetDefinition[];
}
