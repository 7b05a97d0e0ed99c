import { Matrix4, Quaternion, Vector3, type Mesh, type Object3D } from 'three';
import { POSE_TRANSFORM_SIZE, isRestingPose, poseTransform, type HeadPose } from '../core/expression/head-pose';
import type { Vec3 } from '../core/rig/rig-types';

/**
 * Turns the shown head by a head pose (AU51 to AU58, see head-pose.ts): the head's root, and with it the skin, eyes,
 * teeth, tongue and hair, turns about the neck's pivot in the skin's own frame (where the pose and the solver's neck
 * carry are), so the neck's base, which the solver turned the other way, comes back to where the body holds it.
 * Anything else drawn in the skin's frame (the muscle glyphs) takes the same frame through `follow`. Allocates nothing
 * per call.
 */
export class HeadTurner {
  private readonly rootRest: Matrix4;
  private readonly skinRest: Matrix4;
  private readonly skinRestInverse: Matrix4;
  private readonly pose = new Float64Array(POSE_TRANSFORM_SIZE);
  private readonly turn = new Matrix4();
  private readonly frame = new Matrix4();
  private readonly position = new Vector3();
  private readonly quaternion = new Quaternion();
  private readonly scale = new Vector3();
  private readonly followers: ((skinFrame: Matrix4) => void)[] = [];
  private shown = { yaw: 0, pitch: 0, roll: 0, forward: 0 };

  private readonly pivot: Vec3;

  /**
   * `pivot` (the skin's frame) is where the head turns; without one (a skin with no neck cut), the middle of its
   * bounds' lower half. The root and skin are taken at rest, as they are now.
   */
  constructor(
    private readonly root: Object3D,
    skin: Mesh,
    pivot: Vec3 | null,
  ) {
    if (pivot) this.pivot = pivot;
    else {
      skin.geometry.computeBoundingBox();
      const b = skin.geometry.boundingBox!;
      this.pivot = [(b.min.x + b.max.x) / 2, b.min.y + (b.max.y - b.min.y) / 4, (b.min.z + b.max.z) / 2];
    }
    root.updateMatrix();
    skin.updateWorldMatrix(true, false);
    this.rootRest = root.matrix.clone();
    this.skinRest = skin.matrixWorld.clone();
    this.skinRestInverse = this.skinRest.clone().invert();
  }

  /** Calls `then` with the skin's world matrix whenever the head turns (a glyph group drawn in the skin's frame). */
  follow(then: (skinFrame: Matrix4) => void): void {
    this.followers.push(then);
  }

  /** Shows the head turned by `pose`; returns whether anything moved. */
  set(pose: HeadPose): boolean {
    const s = this.shown;
    if (pose.yaw === s.yaw && pose.pitch === s.pitch && pose.roll === s.roll && pose.forward === s.forward) return false;
    s.yaw = pose.yaw;
    s.pitch = pose.pitch;
    s.roll = pose.roll;
    s.forward = pose.forward;
    const m = this.pose;
    poseTransform(pose, isRestingPose(pose) ? 0 : 1, this.pivot, m);
    // Row-major rotation and translation into three's column-major setter (which takes rows).
    this.turn.set(m[0], m[1], m[2], m[9], m[3], m[4], m[5], m[10], m[6], m[7], m[8], m[11], 0, 0, 0, 1);
    // In the scene: the skin's frame, the turn in it, back to the scene, then the root's own rest placement.
    this.frame.multiplyMatrices(this.skinRest, this.turn).multiply(this.skinRestInverse).multiply(this.rootRest);
    this.frame.decompose(this.position, this.quaternion, this.scale);
    this.root.position.copy(this.position);
    this.root.quaternion.copy(this.quaternion);
    this.root.scale.copy(this.scale);
    this.root.updateMatrixWorld(true);
    this.frame.multiplyMatrices(this.skinRest, this.turn);
    for (const f of this.followers) f(this.frame);
    return true;
  }
}
