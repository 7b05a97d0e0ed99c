import { BufferAttribute, BufferGeometry, Group, Mesh, MeshStandardMaterial, type Object3D } from 'three';
import type { MaterialSpec, NodeSpec, PartSpec } from '../core/head/build/head-spec';

/**
 * The three.js scene of a head built in the page (an identity's head, see src/core/head/build/), shaped as
 * GLTFLoader shapes the same head read from its model file: a node with one part is a mesh of the node's name, one
 * with several a group of meshes; nodes that name the same mesh share its geometry; extras become `userData`. So
 * `headModelOf` reads both alike.
 */
export function headSceneFromSpec(root: NodeSpec, sceneExtras: Record<string, unknown>): Group {
  const geometries = new Map<string, BufferGeometry[]>();
  const materials = new Map<string, MeshStandardMaterial>();
  const material = (spec: MaterialSpec): MeshStandardMaterial => {
    let m = materials.get(spec.name);
    if (!m) {
      const [r, g, b, a] = spec.baseColor;
      m = new MeshStandardMaterial({ name: spec.name, roughness: spec.roughness, metalness: spec.metallic ?? 0 });
      m.color.setRGB(r, g, b);
      m.opacity = a;
      m.transparent = spec.blend ?? false;
      if (spec.doubleSided) m.side = 2;
      materials.set(spec.name, m);
    }
    return m;
  };
  const meshes = (spec: NodeSpec, parts: readonly PartSpec[]): Mesh[] => {
    const key = spec.meshName ?? spec.name;
    let shared = geometries.get(key);
    if (!shared) {
      shared = parts.map((p) => geometryOf(p));
      geometries.set(key, shared);
    }
    const list = shared;
    return parts.map((p, i) => new Mesh(list[i], material(p.material)));
  };
  const build = (spec: NodeSpec): Object3D => {
    let node: Object3D;
    if (spec.parts && spec.parts.length === 1) node = meshes(spec, spec.parts)[0];
    else {
      node = new Group();
      if (spec.parts) node.add(...meshes(spec, spec.parts));
    }
    node.name = spec.name;
    if (spec.translation) node.position.fromArray(spec.translation);
    if (spec.extras) node.userData = structuredClone(spec.extras);
    for (const child of spec.children ?? []) node.add(build(child));
    return node;
  };
  const scene = new Group();
  scene.name = 'softface-head';
  scene.userData = structuredClone(sceneExtras);
  scene.add(build(root));
  scene.updateMatrixWorld(true);
  return scene;
}

function geometryOf({ geometry: g }: PartSpec): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(g.positions, 3));
  geometry.setAttribute('normal', new BufferAttribute(g.normals, 3));
  geometry.setAttribute('uv', new BufferAttribute(g.uvs, 2));
  if (g.colors) geometry.setAttribute('color', new BufferAttribute(g.colors, 3));
  // As the model file stores them: 16-bit where every index fits.
  geometry.setIndex(new BufferAttribute(g.positions.length / 3 < 65536 ? Uint16Array.from(g.indices) : g.indices, 1));
  geometry.computeBoundingSphere();
  return geometry;
}
