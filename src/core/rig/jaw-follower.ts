import type { Collider } from '../solver/colliders';
import { HEAD_NODES } from '../head/head-nodes';
import { DEGREES, rotateAboutAxis } from '../math3';
import { MuscleField } from './muscle-fields';
import type { Muscle, Vec3 } from './rig-types';

/** The lower teeth's colliders as the model places them at rest. */
interface RestShape {
  collider: Collider;
  a: Vec3;
  b?: Vec3;
  /** The slab's top edge point a + up, so `up` can be turned as a point pair. */
  top?: Vec3;
}

/**
 * Turns the lower teeth's colliders with the rig's jaw muscle, about the same hinge and axis and by the same angle its
 * contraction gives the skin (without the lip-middle curve), so the lips keep sliding over teeth that moved.
 */
export class JawFollower {
  private readonly shapes: RestShape[];
  private readonly joint: Vec3;
  private readonly axis: Vec3;
  private readonly maxAngle: number;
  private readonly point = new Float64Array(3);

  /** Null when the rig has no jaw muscle or the model no colliders named `prefix`. */
  static create(muscles: readonly Muscle[], colliders: Collider[], prefix: string = HEAD_NODES.lowerTeeth): JawFollower | null {
    const index = muscles.findIndex((m) => m.type === 'jaw');
    const shapes = colliders.filter((c) => c.name.startsWith(prefix));
    if (index < 0 || shapes.length === 0) return null;
    return new JawFollower(index, muscles[index], shapes);
  }

  private constructor(
    /** The jaw muscle's index in the rig, i.e. in the contractions. */
    readonly muscleIndex: number,
    muscle: Muscle,
    colliders: Collider[],
  ) {
    const field = new MuscleField(muscle);
    this.joint = field.joint()!;
    this.axis = field.axis()!;
    this.maxAngle = muscle.type === 'jaw' ? muscle.maxAngle * DEGREES : 0;
    this.shapes = colliders.map((collider) => ({
      collider,
      a: [...collider.a],
      b: collider.b ? [...collider.b] : undefined,
      top: collider.up ? [collider.a[0] + collider.up[0], collider.a[1] + collider.up[1], collider.a[2] + collider.up[2]] : undefined,
    }));
  }

  /** Moves the colliders (in place) to where the jaw's contraction turns them. */
  update(contractions: ArrayLike<number>): void {
    const angle = contractions[this.muscleIndex] * this.maxAngle;
    for (const s of this.shapes) {
      this.turn(s.a, angle, s.collider.a);
      if (s.b && s.collider.b) this.turn(s.b, angle, s.collider.b);
      if (s.top && s.collider.up) {
        this.turn(s.top, angle, s.collider.up);
        for (let k = 0; k < 3; k++) s.collider.up[k] -= s.collider.a[k];
      }
    }
  }

  private turn(p: Vec3, angle: number, out: Vec3): void {
    const [jx, jy, jz] = this.joint;
    const [ux, uy, uz] = this.axis;
    rotateAboutAxis(p[0], p[1], p[2], jx, jy, jz, ux, uy, uz, angle, this.point);
    out[0] = this.point[0];
    out[1] = this.point[1];
    out[2] = this.point[2];
  }
}
