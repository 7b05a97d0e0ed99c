import { Document, NodeIO, type Node } from '@gltf-transform/core';
import type { MaterialSpec, NodeSpec } from '../../src/core/head/build/head-spec';

/** Writes a scene of nodes to GLB bytes; the same input always gives the same bytes. */
export async function writeGlb(root: NodeSpec, sceneExtras: Record<string, unknown>): Promise<Uint8Array> {
  const doc = new Document();
  doc.getRoot().getAsset().generator = 'softface build-head-model';
  const buffer = doc.createBuffer();
  const materials = new Map<string, ReturnType<Document['createMaterial']>>();
  const meshes = new Map<string, ReturnType<Document['createMesh']>>();

  const material = (spec: MaterialSpec) => {
    let m = materials.get(spec.name);
    if (!m) {
      m = doc
        .createMaterial(spec.name)
        .setBaseColorFactor(spec.baseColor)
        .setRoughnessFactor(spec.roughness)
        .setMetallicFactor(spec.metallic ?? 0)
        .setAlphaMode(spec.blend ? 'BLEND' : 'OPAQUE')
        .setDoubleSided(spec.doubleSided ?? false);
      materials.set(spec.name, m);
    }
    return m;
  };

  const accessor = (type: 'VEC2' | 'VEC3' | 'SCALAR', array: Float32Array | Uint32Array | Uint16Array) =>
    doc
      .createAccessor()
      .setType(type)
      .setArray(array as Float32Array<ArrayBuffer>)
      .setBuffer(buffer);

  const build = (spec: NodeSpec): Node => {
    const node = doc.createNode(spec.name);
    if (spec.translation) node.setTranslation(spec.translation);
    if (spec.extras) node.setExtras(spec.extras);
    if (spec.parts) {
      const meshName = spec.meshName ?? spec.name;
      let mesh = meshes.get(meshName);
      if (!mesh) {
        mesh = doc.createMesh(meshName);
        for (const part of spec.parts) {
          const g = part.geometry;
          const vertexCount = g.positions.length / 3;
          const prim = doc
            .createPrimitive()
            .setAttribute('POSITION', accessor('VEC3', g.positions))
            .setAttribute('NORMAL', accessor('VEC3', g.normals))
            .setAttribute('TEXCOORD_0', accessor('VEC2', g.uvs))
            .setIndices(accessor('SCALAR', vertexCount < 65536 ? Uint16Array.from(g.indices) : g.indices))
            .setMaterial(material(part.material));
          if (g.colors) prim.setAttribute('COLOR_0', accessor('VEC3', g.colors));
          mesh.addPrimitive(prim);
        }
        meshes.set(meshName, mesh);
      }
      node.setMesh(mesh);
    }
    for (const child of spec.children ?? []) node.addChild(build(child));
    return node;
  };

  const scene = doc.createScene('softface-head').addChild(build(root)).setExtras(sceneExtras);
  doc.getRoot().setDefaultScene(scene);
  return new NodeIO().writeBinary(doc);
}
