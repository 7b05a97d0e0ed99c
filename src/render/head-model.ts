import { type Box3, BufferAttribute, LoaderUtils, Mesh, type Object3D, Texture, Vector3, type Material } from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { HEAD_NODES } from '../core/head/head-nodes';
import type { IdentityLook } from '../core/head/identity-look';
import { createHeadMaterials } from './materials';
import type { HairView } from './hair-view';
import { mouthLight, SKIN_TINT_DEFAULTS, skinTint } from './skin-tint';

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
  /** Eyebrows and eyelashes on the skin, once the face has placed them (see HairView). */
  hair?: HairView;
  /** The head's own brow and lash look (an identity's), shown where the appearance options are left at their defaults. */
  hairLook?: { browColor: string; lashColor: string; browDensity: number };
}

/** Loads a softface head GLB and gives its parts the app's materials. */
export async function loadHeadModel(url: string): Promise<HeadModel> {
  return parseHeadModel(await fetchModel(url), url);
}

/** A model file's bytes (see parseHeadModel): fetched apart from the parse, so that the download can start first. */
export async function fetchModel(url: string): Promise<ArrayBuffer> {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`HTTP ${response.status}`);
  return response.arrayBuffer();
}

/** A softface head from the bytes of a GLB (or glTF) fetched from `url`, with the app's materials. */
export async function parseHeadModel(bytes: ArrayBuffer, url: string): Promise<HeadModel> {
  const gltf = await new GLTFLoader().parseAsync(bytes, LoaderUtils.extractUrlBase(url));
  return headModelOf(gltf.scene, url);
}

/**
 * A head from a softface head scene (a loaded model file's, or one built in the page: see head-from-spec.ts): its parts
 * found by name and given the app's materials. `source` names the scene in messages.
 */
export function headModelOf(root: Object3D, source: string, look?: IdentityLook): HeadModel {
  const url = source;
  const info = root.userData.softface as HeadModelInfo | undefined;
  if (info?.format !== 'softface-head') throw new Error(`${url} is not a softface head model (its scene has no softface extras)`);
  root.traverse((o) => {
    const t = [...o.position.toArray(), ...o.quaternion.toArray(), ...o.scale.toArray()];
    if (!t.every(Number.isFinite)) throw new Error(`${url}: node "${o.name}" has a non-finite transform`);
  });
  const skin = root.getObjectByName(HEAD_NODES.skin);
  if (!(skin instanceof Mesh)) throw new Error(`${url} has no mesh named "${HEAD_NODES.skin}"`);
  // A person's own skin and irises (an identity's head); else the materials' defaults.
  const materials = look ? createHeadMaterials({ color: look.skin }, look.iris) : createHeadMaterials();
  replaceMaterial(skin, materials.skin);
  // Lips, inner mouth and cheeks: per-vertex albedo multipliers, computed once at rest.
  const uv = skin.geometry.getAttribute('uv');
  if (uv) {
    // Through the getters: the model's attributes are interleaved, so their arrays hold more than one attribute.
    const position = skin.geometry.getAttribute('position');
    const positions = Float32Array.from({ length: 3 * position.count }, (_, i) => position.getComponent(Math.floor(i / 3), i % 3));
    const uvs = Float32Array.from({ length: 2 * uv.count }, (_, i) => uv.getComponent(Math.floor(i / 2), i % 2));
    skin.geometry.setAttribute('color', new BufferAttribute(skinTint(positions, uvs), 3));
    materials.skin.vertexColors = true;
  }

  const teeth = [HEAD_NODES.upperTeeth, HEAD_NODES.lowerTeeth].map((n) => root.getObjectByName(n)).filter((o): o is Object3D => !!o);
  // The rows hold crowns and gums: the gums by their material's name, everything else as enamel. Their vertex
  // colours are baked occlusion (the mouth's inside is darker); a mesh without them gets white, as the materials
  // then multiply by the colour attribute.
  for (const t of teeth) {
    forEachMesh(t, (m) => {
      replaceMaterial(m, (m.material as Material).name === 'gums' ? materials.gums : materials.teeth);
      if (!m.geometry.getAttribute('color')) whiteVertexColors(m);
    });
  }
  materials.teeth.vertexColors = true;
  materials.gums.vertexColors = true;
  const tongue = root.getObjectByName(HEAD_NODES.tongue);
  if (tongue) {
    forEachMesh(tongue, (m) => {
      replaceMaterial(m, materials.tongue);
      // Darker toward the throat, as the inner mouth (its positions are in the head's frame, see HEAD_NODES).
      const position = m.geometry.getAttribute('position');
      const light = new Float32Array(3 * position.count);
      for (let i = 0; i < position.count; i++) light.fill(mouthLight(position.getZ(i), SKIN_TINT_DEFAULTS.mouth[2]), 3 * i, 3 * i + 3);
      m.geometry.setAttribute('color', new BufferAttribute(light, 3));
    });
  }
  materials.tongue.vertexColors = true;

  const eyes = HEAD_NODES.eyes.map((n) => root.getObjectByName(n)).filter((o): o is Object3D => !!o);
  const byName: Partial<Record<string, Material>> = { sclera: materials.sclera, iris: materials.iris, cornea: materials.cornea };
  for (const eye of eyes) {
    forEachMesh(eye, (m) => {
      const replacement = byName[(m.material as Material).name];
      if (replacement) replaceMaterial(m, replacement);
      // The cornea blends over the iris, so it is drawn after the opaque parts.
      m.renderOrder = (m.material as Material).transparent ? 2 : 0;
    });
  }
  skin.geometry.computeBoundingBox();
  return {
    root,
    skin,
    eyes,
    teeth,
    tongue,
    jaw: root.getObjectByName(HEAD_NODES.jaw),
    info,
    bounds: skin.geometry.boundingBox!.clone(),
    ...(look ? { hairLook: { browColor: look.browColor, lashColor: look.lashColor, browDensity: look.browDensity } } : {}),
  };
}

/** Frees the geometries, materials and textures of a head's objects, each once. */
export function disposeHead(head: HeadModel): void {
  const materials = new Set<Material>();
  head.root.traverse((o) => {
    if (!(o instanceof Mesh)) return;
    o.geometry.dispose();
    for (const m of Array.isArray(o.material) ? o.material : [o.material]) materials.add(m);
  });
  for (const material of materials) {
    for (const value of Object.values(material)) if (value instanceof Texture) value.dispose();
    material.dispose();
  }
}

/** Centre of a box, as a new vector (for framing). */
export const boxCentre = (b: Box3): Vector3 => b.getCenter(new Vector3());

function forEachMesh(o: Object3D, fn: (m: Mesh) => void): void {
  o.traverse((c) => {
    if (c instanceof Mesh) fn(c);
  });
}

/** Gives a mesh white vertex colours, for a material that multiplies by them. */
export function whiteVertexColors(mesh: Mesh): void {
  const count = mesh.geometry.getAttribute('position').count;
  mesh.geometry.setAttribute('color', new BufferAttribute(new Float32Array(3 * count).fill(1), 3));
}

function replaceMaterial(mesh: Mesh, material: Material): void {
  const old = mesh.material as Material;
  mesh.material = material;
  if (old !== material) old.dispose();
}
