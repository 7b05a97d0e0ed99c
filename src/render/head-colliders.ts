import { Matrix4, Mesh, Vector3, type Object3D } from 'three';
import { archSlabs, type Collider } from '../core/solver/colliders';
import { HEAD_NODES } from '../core/head/head-nodes';
import type { HeadModel } from './head-model';

/**
 * The rigid shapes the skin may not sink into, in the skin's own frame (head space): each eyeball as a sphere, and
 * each row of teeth as a chain of thin slabs along its arch. The lower teeth hang under the `jaw` node, so vertices are taken through
 * their world transforms.
 */
export function headColliders(head: HeadModel): Collider[] {
  head.root.updateMatrixWorld(true);
  const toSkin = head.skin.matrixWorld.clone().invert();
  // Pivots are given in the model's frame.
  const modelToSkin = new Matrix4().multiplyMatrices(toSkin, head.root.matrixWorld);
  const colliders: Collider[] = [];
  for (const side of HEAD_NODES.eyes) {
    const pivot = head.info.pivots[side];
    if (!pivot) continue;
    const centre = new Vector3(...pivot).applyMatrix4(modelToSkin);
    colliders.push({ name: side, a: [centre.x, centre.y, centre.z], radius: head.info.eyeRadius });
  }
  for (const name of [HEAD_NODES.upperTeeth, HEAD_NODES.lowerTeeth]) {
    const teeth = head.root.getObjectByName(name);
    if (teeth) colliders.push(...archSlabs(name, verticesIn(teeth, toSkin)));
  }
  return colliders;
}

/** The vertex positions of every mesh under `object`, xyz, transformed into the frame `toFrame` maps world to. */
function verticesIn(object: Object3D, toFrame: Matrix4): Float32Array {
  const out: number[] = [];
  const v = new Vector3();
  const m = new Matrix4();
  object.traverse((o) => {
    if (!(o instanceof Mesh)) return;
    m.multiplyMatrices(toFrame, o.matrixWorld);
    const p = o.geometry.getAttribute('position');
    for (let i = 0; i < p.count; i++) {
      v.fromBufferAttribute(p, i).applyMatrix4(m);
      out.push(v.x, v.y, v.z);
    }
  });
  return Float32Array.from(out);
}
