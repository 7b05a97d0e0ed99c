import { BoxGeometry, Group, Mesh, MeshStandardMaterial, Object3D, Quaternion, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { HeadExporter, type MorphShape } from '../src/render/gltf-export';
import type { HeadModel } from '../src/render/head-model';

/** A small head: a box of skin, and a jaw node at a hinge carrying a box of lower teeth. */
function smallHead(): HeadModel {
  const root = new Group();
  root.userData.softface = { format: 'softface-head' };
  const skin = new Mesh(new BoxGeometry(0.2, 0.2, 0.2), new MeshStandardMaterial());
  skin.name = 'skin';
  const jaw = new Object3D();
  jaw.name = 'jaw';
  jaw.position.set(0, 0.1, 0.05);
  const teeth = new Mesh(new BoxGeometry(0.04, 0.01, 0.02), new MeshStandardMaterial());
  teeth.name = 'teeth-lower';
  teeth.position.set(0, -0.12, 0.02);
  jaw.add(teeth);
  root.add(skin, jaw);
  return { root, skin, eyes: [], teeth: [teeth], tongue: undefined, jaw, info: {} as HeadModel['info'], bounds: undefined as never };
}

function restOf(mesh: Mesh): { positions: Float32Array; normals: Float32Array } {
  return {
    positions: Float32Array.from(mesh.geometry.getAttribute('position').array),
    normals: Float32Array.from(mesh.geometry.getAttribute('normal').array),
  };
}

describe('HeadExporter.buildScene', () => {
  it("stores each shape's skin as a named, relative morph target and bakes the jaw's turn into the teeth under it", () => {
    const head = smallHead();
    const rest = restOf(head.skin);
    const exporter = new HeadExporter(head, rest.positions, rest.normals);
    const restJaw = exporter.jawPose()!;
    // A smile moves the skin and leaves the jaw; a jaw drop turns the jaw 20° about x.
    const smile = rest.positions.map((x, i) => x + (i % 3 === 1 ? 0.003 : 0));
    head.jaw!.quaternion.setFromAxisAngle(new Vector3(1, 0, 0), (20 * Math.PI) / 180);
    const dropJaw = exporter.jawPose()!;
    const drop = rest.positions.map((x, i) => x - (i % 3 === 1 ? 0.01 : 0));
    const shapes: MorphShape[] = [
      { name: 'AU12', positions: smile, normals: rest.normals, jaw: restJaw },
      { name: 'AU26', positions: drop, normals: rest.normals, jaw: dropJaw },
    ];
    const clip = { name: 'timeline', times: Float32Array.of(0, 1), weights: Float32Array.of(0, 0, 1, 0.5), duration: 1 };
    const built = exporter.buildScene(shapes, clip);

    // The export is at rest, whatever the shown head's jaw does now, and does not claim to be a head model.
    const jaw = built.scene.getObjectByName('jaw')!;
    expect(jaw.quaternion.equals(new Quaternion(...restJaw.quaternion))).toBe(true);
    expect(built.scene.userData.softface).toBeUndefined();

    const skin = built.skin;
    expect(skin.morphTargetDictionary).toEqual({ AU12: 0, AU26: 1 });
    expect(skin.geometry.morphTargetsRelative).toBe(true);
    const base = skin.geometry.getAttribute('position');
    const delta = skin.geometry.morphAttributes.position![0];
    for (let i = 0; i < base.count; i++) expect(base.getY(i) + delta.getY(i)).toBeCloseTo(smile[3 * i + 1], 7);
    // The shown head's geometry is untouched.
    expect(head.skin.geometry.morphAttributes.position).toBeUndefined();

    // The teeth at weight 1 of AU26 are where the turned jaw puts them; AU12 does not move them.
    expect(built.jawMeshes.map((m) => m.name)).toEqual(['teeth-lower']);
    const teeth = built.jawMeshes[0];
    expect(teeth.morphTargetDictionary).toEqual({ AU12: 0, AU26: 1 });
    const teethBase = teeth.geometry.getAttribute('position');
    const still = teeth.geometry.morphAttributes.position![0];
    const turned = teeth.geometry.morphAttributes.position![1];
    head.root.updateMatrixWorld(true);
    const original = head.teeth[0] as Mesh;
    let moved = 0;
    for (let i = 0; i < teethBase.count; i++) {
      expect(Math.hypot(still.getX(i), still.getY(i), still.getZ(i))).toBeLessThan(1e-9);
      const p = new Vector3().fromBufferAttribute(teethBase, i).add(new Vector3().fromBufferAttribute(turned, i));
      // The export's teeth node is at rest: its world place of p against the shown (turned) teeth's world vertex.
      const inExport = p.applyMatrix4(teeth.matrixWorld);
      const shown = new Vector3().fromBufferAttribute(original.geometry.getAttribute('position'), i).applyMatrix4(original.matrixWorld);
      expect(inExport.distanceTo(shown)).toBeLessThan(1e-6);
      moved = Math.max(moved, Math.hypot(turned.getX(i), turned.getY(i), turned.getZ(i)));
    }
    expect(moved).toBeGreaterThan(0.01);

    // One clip, the same weights on every mesh with targets.
    expect(built.animations).toHaveLength(1);
    expect(built.animations[0].duration).toBe(1);
    expect(built.animations[0].tracks.map((t) => t.name)).toEqual([
      `${skin.uuid}.morphTargetInfluences`,
      `${teeth.uuid}.morphTargetInfluences`,
    ]);
    expect(Array.from(built.animations[0].tracks[1].values)).toEqual([0, 0, 1, 0.5]);
    built.dispose();
  });

  it("refuses a shape whose vertex count is not the skin's", () => {
    const head = smallHead();
    const rest = restOf(head.skin);
    const exporter = new HeadExporter(head, rest.positions, rest.normals);
    expect(() =>
      exporter.buildScene([{ name: 'AU12', positions: new Float32Array(3), normals: new Float32Array(3), jaw: null }], null),
    ).toThrow(/the shape AU12 has 1 vertices/);
  });
});
