import { Box3, BufferAttribute, BufferGeometry, Group, LoadingManager, Matrix4, Mesh, type Object3D, Vector3, type Material } from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
import { HEAD_NODES } from '../core/head/head-nodes';
import type { HeadTransform, TriangleMesh } from '../core/head/head-mesh';
import type { Landmarks } from '../core/head/landmarks';
import { warpPoint, type ThinPlateWarp } from '../core/head/thin-plate';
import { whiteVertexColors, type HeadModel } from './head-model';
import { skinTint, SKIN_TINT_DEFAULTS } from './skin-tint';

/** A file given for a head: its name (with extension) and bytes. A `.gltf` comes with the files it refers to. */
export interface HeadFile {
  /**
   * The file's name with its extension (`head.glb`, `scene.bin`): the extension says the head's format, and a `.gltf`
   * finds the files it refers to by their names.
   */
  name: string;
  /** The file's whole contents. */
  bytes: ArrayBuffer;
}

/** The file formats a head may come in, by what they start with or their extension. */
export type HeadFormat = 'glb' | 'gltf' | 'obj';

/** Which of the files is the head, and in what format: a `.glb`, `.gltf` or `.obj`; throws naming the files otherwise. */
function mainHeadFile(files: readonly HeadFile[]): { file: HeadFile; format: HeadFormat } {
  for (const file of files) {
    const extension = file.name.toLowerCase().split('.').pop();
    if (extension === 'glb' || extension === 'gltf' || extension === 'obj') return { file, format: extension };
  }
  // No extension to go by (a URL without one): the bytes say.
  for (const file of files) {
    const head = new Uint8Array(file.bytes, 0, Math.min(64, file.bytes.byteLength));
    if (head.length >= 4 && String.fromCharCode(...head.subarray(0, 4)) === 'glTF') return { file, format: 'glb' };
    const text = new TextDecoder().decode(head).trimStart();
    if (text.startsWith('{')) return { file, format: 'gltf' };
    if (/^(#|v |o |g |mtllib )/m.test(text)) return { file, format: 'obj' };
  }
  throw new Error(`${files.map((f) => f.name).join(', ')}: not a head model: give a .glb, a .gltf (with its files) or an .obj`);
}

/** Reads a head file into a three.js scene; throws naming the file when it cannot be read (truncated, not that format). */
export async function readHeadScene(files: readonly HeadFile[]): Promise<{ scene: Object3D; file: HeadFile }> {
  const { file, format } = mainHeadFile(files);
  try {
    if (format === 'obj') {
      const text = new TextDecoder().decode(file.bytes);
      if (!/^\s*f\s/m.test(text)) throw new Error('it has no faces (f lines)');
      return { scene: new OBJLoader().parse(text), file };
    }
    // The side files of a .gltf (buffers, textures) come from the files given, by name, not from the network.
    const manager = new LoadingManager();
    const urls: string[] = [];
    manager.setURLModifier((url) => {
      const name = decodeURIComponent(url.split(/[\\/]/).pop() ?? url);
      const side = files.find((f) => f.name === name);
      if (!side) return url;
      const blobUrl = URL.createObjectURL(new Blob([side.bytes]));
      urls.push(blobUrl);
      return blobUrl;
    });
    try {
      const gltf = await new GLTFLoader(manager).parseAsync(format === 'glb' ? file.bytes : new TextDecoder().decode(file.bytes), '');
      return { scene: gltf.scene, file };
    } finally {
      for (const url of urls) URL.revokeObjectURL(url);
    }
  } catch (error) {
    throw new Error(`${file.name}: not a readable ${format === 'obj' ? 'OBJ' : 'glTF'} file (${(error as Error).message})`);
  }
}

/** Meshes that are parts of a head by their names (eyes, teeth), not candidates for its skin. */
const PART_NAMES = new Set<string>([...HEAD_NODES.eyes, HEAD_NODES.upperTeeth, HEAD_NODES.lowerTeeth, HEAD_NODES.tongue]);

/**
 * The skin: the mesh named `name`, or the largest mesh (by triangles) that is not a named part, with its positions
 * in the file's scene frame, indexed triangles and uvs if it has them. Throws naming the file when there is none.
 */
export function skinOf(scene: Object3D, source: string, name: string | null): { mesh: TriangleMesh; name: string } {
  scene.updateMatrixWorld(true);
  const meshes: Mesh[] = [];
  scene.traverse((o) => {
    if (o instanceof Mesh && o.geometry?.getAttribute('position') && !isPart(o)) meshes.push(o);
  });
  const triangles = (m: Mesh): number => (m.geometry.index ? m.geometry.index.count : m.geometry.getAttribute('position').count) / 3;
  let skin: Mesh | undefined;
  if (name !== null) {
    skin = meshes.find((m) => m.name === name || m.parent?.name === name);
    if (!skin)
      throw new Error(`${source}: has no mesh named "${name}" (its meshes: ${meshes.map((m) => `"${m.name}"`).join(', ') || 'none'})`);
  } else {
    for (const m of meshes) if (!skin || triangles(m) > triangles(skin)) skin = m;
  }
  if (!skin || triangles(skin) < 1) throw new Error(`${source}: has no triangle mesh in it`);
  const geometry = skin.geometry;
  const position = geometry.getAttribute('position');
  const positions = new Float32Array(3 * position.count);
  const v = new Vector3();
  for (let i = 0; i < position.count; i++) {
    v.fromBufferAttribute(position, i).applyMatrix4(skin.matrixWorld);
    positions[3 * i] = v.x;
    positions[3 * i + 1] = v.y;
    positions[3 * i + 2] = v.z;
  }
  const indices = geometry.index
    ? Uint32Array.from({ length: geometry.index.count }, (_, i) => geometry.index!.getX(i))
    : Uint32Array.from({ length: position.count }, (_, i) => i);
  const uv = geometry.getAttribute('uv');
  const uvs = uv ? Float32Array.from({ length: 2 * uv.count }, (_, i) => uv.getComponent(Math.floor(i / 2), i % 2)) : undefined;
  return { mesh: { positions, indices, uvs }, name: skin.name };
}

function isPart(o: Object3D): boolean {
  for (let p: Object3D | null = o; p; p = p.parent) if (PART_NAMES.has(p.name)) return true;
  return false;
}

/** What the new head's parts come from: the file's named nodes where it has them, the default head's otherwise. */
export interface HeadParts {
  /** The file's scene (its named nodes are looked for) and the frame that takes it into the app's. */
  scene: Object3D;
  transform: HeadTransform;
  /** The default head, whose eyes, teeth, tongue and jaw are carried over by the warp where the file has none. */
  defaults: HeadModel;
  warp: ThinPlateWarp;
}

/**
 * Builds the head the face shows from a loaded skin (already in the app's frame) and its parts: the skin mesh with
 * the skin material (lips tinted about the found mouth), eyes placed at the warped eye centres and scaled with the
 * warp, teeth and tongue warped vertex by vertex, the jaw node at the warped hinge, and the default head's pivots
 * warped. Named nodes of the file (`eye-l`, `eye-r`, `teeth-upper`, `teeth-lower`, `jaw`) take the place of the
 * default head's. The default head's model is taken apart: its skin is disposed.
 */
/** Where a loaded head's eyes, teeth and jaw pivot came from: its own file's named nodes, or the default head. */
export interface PartSources {
  /** `file` if the file has an `eye-l` or `eye-r` node (the other eye, if missing, is the default head's, warped). */
  eyes: 'file' | 'default';
  /** `file` if the file has a `teeth-upper` or `teeth-lower` node; teeth it lacks are the default head's, warped. */
  teeth: 'file' | 'default';
  /** `file` if the file has a `jaw` node (the hinge the lower teeth and tongue turn about), else the default head's. */
  jaw: 'file' | 'default';
}

export function buildLoadedHead(skin: TriangleMesh, landmarks: Landmarks, parts: HeadParts): { head: HeadModel; sources: PartSources } {
  const { defaults, warp, transform } = parts;
  const root = new Group();
  root.name = 'head';
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(skin.positions, 3));
  geometry.setIndex(new BufferAttribute(skin.indices, 1));
  // Once, at load: the solver gives normals every frame from then on.
  geometry.computeVertexNormals();
  const mouth = [0, 1, 2].map((k) => (landmarks['mouth-l'][k] + landmarks['mouth-r'][k]) / 2) as [number, number, number];
  const s = warp.scale;
  const tint = skinTint(skin.positions, new Float32Array((2 * skin.positions.length) / 3), {
    mouth,
    lipHalfWidth: Math.abs(landmarks['mouth-l'][0] - landmarks['mouth-r'][0]) / 2 + 0.002 * s,
    upperLip: SKIN_TINT_DEFAULTS.upperLip * s,
    lowerLip: SKIN_TINT_DEFAULTS.lowerLip * s,
    // The inner mouth's uv island is the default head's; a loaded head's uvs say nothing of it.
    innerMouthUv: [2, 2, -1],
  });
  geometry.setAttribute('color', new BufferAttribute(tint, 3));
  if (skin.uvs) geometry.setAttribute('uv', new BufferAttribute(skin.uvs, 2));
  const skinMesh = new Mesh(geometry, defaults.skin.material as Material);
  skinMesh.name = HEAD_NODES.skin;
  root.add(skinMesh);
  defaults.skin.geometry.dispose();

  const fileMatrix = new Matrix4().set(
    transform.scale * transform.rotation[0],
    transform.scale * transform.rotation[1],
    transform.scale * transform.rotation[2],
    transform.offset[0],
    transform.scale * transform.rotation[3],
    transform.scale * transform.rotation[4],
    transform.scale * transform.rotation[5],
    transform.offset[1],
    transform.scale * transform.rotation[6],
    transform.scale * transform.rotation[7],
    transform.scale * transform.rotation[8],
    transform.offset[2],
    0,
    0,
    0,
    1,
  );
  parts.scene.updateMatrixWorld(true);
  // The app's materials by name (sclera, iris, cornea, teeth, tongue): a file's parts named so take them.
  const materials = new Map<string, Material>();
  defaults.root.traverse((o) => {
    if (o instanceof Mesh && !Array.isArray(o.material) && o !== defaults.skin)
      materials.set((o.material as Material).name, o.material as Material);
  });
  const fromFile = (name: string): Object3D | undefined => {
    const o = parts.scene.getObjectByName(name);
    if (!o) return undefined;
    // Into the app's frame, keeping its place: its world matrix, then the file's frame.
    o.removeFromParent();
    o.matrixWorld.premultiply(fileMatrix).decompose(o.position, o.quaternion, o.scale);
    o.traverse((m) => {
      if (!(m instanceof Mesh) || Array.isArray(m.material)) return;
      const own = materials.get((m.material as Material).name);
      if (own) m.material = own;
      // The app's teeth and gums multiply by vertex colours (baked occlusion): a part without them gets white.
      if (own?.vertexColors && !m.geometry.getAttribute('color')) whiteVertexColors(m);
      // The cornea blends over the iris, so it is drawn after the opaque parts.
      m.renderOrder = (m.material as Material).transparent ? 2 : 0;
    });
    return o;
  };

  const pivots: Record<string, [number, number, number]> = {};
  for (const [name, at] of Object.entries(defaults.info.pivots)) pivots[name] = warpPoint(warp, at);
  let eyeRadius = defaults.info.eyeRadius * s;
  const eyes: Object3D[] = [];
  const sources: PartSources = { eyes: 'default', teeth: 'default', jaw: 'default' };
  HEAD_NODES.eyes.forEach((name, i) => {
    const own = fromFile(name);
    if (own) {
      // The file's eye: a pivot group at its centre, so that it turns about it.
      const box = new Box3().setFromObject(own);
      const centre = box.getCenter(new Vector3());
      eyeRadius = box.getSize(new Vector3()).x / 2;
      const pivot = new Group();
      pivot.name = name;
      pivot.position.copy(centre);
      own.position.sub(centre);
      own.name = `${name}-mesh`;
      pivot.add(own);
      pivots[name] = centre.toArray();
      root.add(pivot);
      eyes.push(pivot);
      sources.eyes = 'file';
      return;
    }
    const eye = defaults.eyes[i];
    eye.position.fromArray(pivots[name]);
    eye.scale.multiplyScalar(s);
    root.add(eye);
    eyes.push(eye);
  });

  const warpGeometry = (object: Object3D, parentOffset: Vector3): void => {
    object.traverse((o) => {
      if (!(o instanceof Mesh)) return;
      const position = o.geometry.getAttribute('position');
      const p = [0, 0, 0];
      for (let i = 0; i < position.count; i++) {
        // The default head's teeth and tongue hold head-space positions (their nodes undo the jaw's translation).
        p[0] = position.getX(i);
        p[1] = position.getY(i);
        p[2] = position.getZ(i);
        const q = warpPoint(warp, p);
        position.setXYZ(i, q[0] + parentOffset.x, q[1] + parentOffset.y, q[2] + parentOffset.z);
      }
      position.needsUpdate = true;
      o.geometry.computeVertexNormals();
      o.geometry.computeBoundingSphere();
    });
  };

  const teeth: Object3D[] = [];
  const ownUpper = fromFile(HEAD_NODES.upperTeeth);
  const upper = ownUpper ?? defaults.teeth.find((t) => t.name === HEAD_NODES.upperTeeth);
  if (upper) {
    if (!ownUpper) warpGeometry(upper, new Vector3());
    else sources.teeth = 'file';
    root.add(upper);
    teeth.push(upper);
  }
  const ownJaw = fromFile(HEAD_NODES.jaw);
  const jaw = ownJaw ?? defaults.jaw;
  let tongue: Object3D | undefined;
  if (jaw) {
    if (!ownJaw) {
      // The default jaw: its node moves to the warped hinge, its children's vertices through the warp.
      const hinge = new Vector3().fromArray(pivots['jaw-hinge']);
      jaw.position.copy(hinge);
      for (const child of [...jaw.children]) {
        child.position.set(0, 0, 0);
        warpGeometry(child, hinge.clone().negate());
      }
    } else {
      pivots['jaw-hinge'] = jaw.position.toArray();
      sources.jaw = 'file';
    }
    const ownLower = fromFile(HEAD_NODES.lowerTeeth);
    if (ownLower) {
      for (const child of [...jaw.children]) if (child.name === HEAD_NODES.lowerTeeth) child.removeFromParent();
      ownLower.position.sub(jaw.position);
      jaw.add(ownLower);
      sources.teeth = 'file';
    }
    root.add(jaw);
    const lower = jaw.getObjectByName(HEAD_NODES.lowerTeeth);
    if (lower) teeth.push(lower);
    tongue = jaw.getObjectByName(HEAD_NODES.tongue);
  }
  geometry.computeBoundingBox();
  const head: HeadModel = {
    root,
    skin: skinMesh,
    eyes,
    teeth,
    tongue,
    jaw,
    info: {
      format: 'softface-head',
      version: 1,
      level: { name: 'loaded', skinVertices: 0, renderVertices: skin.positions.length / 3, triangles: skin.indices.length / 3 },
      eyeRadius,
      pivots,
    },
    bounds: geometry.boundingBox!.clone(),
  };
  return { head, sources };
}
