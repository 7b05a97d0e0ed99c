import { Quaternion, Vector3 } from 'three';
import { DEGREES, eulerMatrix } from '../core/math3';
import type { Rig } from '../core/rig/rig-types';
import type { HeadModel } from '../render/head-model';

/** The jaw node's rest pose and the hinge of the rig it was loaded with. */
export interface JawRest {
  quaternion: Quaternion;
  position: Vector3;
  hinge: Vector3 | undefined;
}

/** The rig's jaw hinge: its jaw muscle's joint, by default the centre of the box's back face (as the solver takes it). */
export function jawHinge(rig: Rig): Vector3 | undefined {
  const muscle = rig.muscles.find((m) => m.type === 'jaw');
  if (muscle?.type !== 'jaw') return undefined;
  if (muscle.joint) return new Vector3(...muscle.joint);
  const frame = new Array<number>(9);
  eulerMatrix(muscle.rotation, frame);
  const back = muscle.size[2] / 2;
  return new Vector3(muscle.center[0] - back * frame[2], muscle.center[1] - back * frame[5], muscle.center[2] - back * frame[8]);
}

/**
 * Turns the lower teeth and tongue (the model's jaw node, placed at the jaw hinge) with the rig's jaw muscle, about
 * the muscle's local x axis, by the angle its contraction asks for. A hinge moved in the editor moves the pivot by as
 * much (the models put the jaw node at the root, in the rig's frame). Allocates nothing per call.
 */
export function jawTurner(head: HeadModel, rig: Rig, rest: JawRest | undefined): ((contractions: Float32Array) => void) | undefined {
  const index = rig.muscles.findIndex((m) => m.type === 'jaw');
  const muscle = rig.muscles[index];
  if (!head.jaw || !rest || !muscle || muscle.type !== 'jaw') return undefined;
  const jaw = head.jaw;
  const frame = new Array<number>(9);
  eulerMatrix(muscle.rotation, frame);
  const axis = new Vector3(frame[0], frame[3], frame[6]).normalize();
  const hinge = jawHinge(rig);
  const pivot = rest.position.clone();
  if (hinge && rest.hinge) pivot.add(hinge).sub(rest.hinge);
  const turn = new Quaternion();
  return (contractions) => {
    turn.setFromAxisAngle(axis, contractions[index] * muscle.maxAngle * DEGREES);
    jaw.quaternion.multiplyQuaternions(turn, rest.quaternion);
    jaw.position.copy(rest.position).sub(pivot).applyQuaternion(turn).add(pivot);
  };
}
