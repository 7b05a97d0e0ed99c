import { Box3, Mesh, Object3D, Vector3, type Material } from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { createCorneaMaterial, createSkinMaterial, createTeethMaterial } from './materials';

/** What the model file's scene extras say about it (written by scripts/build-head-model.ts). */
export interface HeadModelInfo {
  format: string;
  version: number;
  level: { name: string; skinVertices: number; renderVertices: number; triangles: number };
  eyeRadius: number;
  pivots: Record<string, [number, number, number]>;
}

/** A loaded head: the three.js objects by role, and the model's pivots. */
export interface HeadModel {
  root: Object3D;
  skin: Mesh;
  eyes: Object3D[];
  teeth: Object3D[];
  tongue: Object3D | undefined;
  jaw: Object3D | undefined;
  info: HeadModelInfo;
  /** Bounds of the skin at rest. */
  bounds: Box3;
}

/** Loads a softface head GLB and gives its parts the app's materials. */
export async function loadHeadModel(url: string): Promise<HeadModel> {
  const gltf = await new GLTFLoader().loadAsync(url);
  const info = gltf.scene.userData.softface as HeadModelInfo | undefined;
  if (!info || info.format !== 'softface-head') throw new Error(`${url} is not a softface head model (its scene has no softface extras)`);
  const root = gltf.scene;
  root.traverse((o) => {
    const t = [...o.position.toArray(), ...o.quaternion.toArray(), ...o.scale.toArray()];
    if (!t.every(Number.isFinite)) throw new Error(`${url}: node "${o.name}" has a non-finite transform`);
  });
  const skin = root.getObjectByName('skin');
  if (!(skin instanceof Mesh)) throw new Error(`${url} has no mesh named "skin"`);
  skin.material = createSkinMaterial();

  const teethMaterial = createTeethMaterial();
  const teeth = ['teeth-upper', 'teeth-lower'].map((n) => root.getObjectByName(n)).filter((o): o is Object3D => !!o);
  for (const t of teeth) forEachMesh(t, (m) => replaceMaterial(m, teethMaterial));

  const eyes = ['eye-l', 'eye-r'].map((n) => root.getObjectByName(n)).filter((o): o is Object3D => !!o);
  const cornea = createCorneaMaterial();
  for (const eye of eyes) {
    forEachMesh(eye, (m) => {
      if ((m.material as Material).name === 'cornea') replaceMaterial(m, cornea);
      m.renderOrder = (m.material as Material).transparent ? 2 : 0;
    });
  }
  skin.geometry.computeBoundingBox();
  return {
    root,
    skin,
    eyes,
    teeth,
    tongue: root.getObjectByName('tongue'),
    jaw: root.getObjectByName('jaw'),
    info,
    bounds: skin.geometry.boundingBox!.clone(),
  };
}

/** Centre of a box, as a new vector (for framing). */
export const boxCentre = (b: Box3): Vector3 => b.getCenter(new Vector3());

function forEachMesh(o: Object3D, fn: (m: Mesh) => void): void {
  o.traverse((c) => {
    if (c instanceof Mesh) fn(c);
  });
}

function replaceMaterial(mesh: Mesh, material: Material): void {
  const old = mesh.material as Material;
  mesh.material = material;
  if (old !== material) old.dispose();
}
