import {
  AnimationClip,
  BufferAttribute,
  BufferGeometry,
  Matrix3,
  Matrix4,
  Mesh,
  NumberKeyframeTrack,
  Quaternion,
  Source,
  Texture,
  Vector3,
  type Material,
  type Object3D,
} from 'three';
import type { HeadModel } from './head-model';

/** The jaw node's local turn and place, as `quaternion.toArray()` and `position.toArray()` give them. */
export interface JawPose {
  quaternion: [number, number, number, number];
  position: [number, number, number];
}

/** One morph target's shape: the settled skin (absolute, xyz per render vertex) and where the jaw was. */
export interface MorphShape {
  name: string;
  positions: Float32Array;
  normals: Float32Array;
  /** The jaw node's pose with this expression (null: the head has no jaw node). */
  jaw: JawPose | null;
}

/** Morph weights over time for an animation clip: `weights[i * shapes + k]` is shape k's weight at `times[i]`. */
export interface MorphClip {
  name: string;
  times: Float32Array;
  weights: Float32Array;
  duration: number;
}

/** Options of `HeadExporter.write`. */
export interface HeadWriteOptions {
  /** A GLB (true) or a glTF JSON document with its buffers and images inline (false). */
  binary?: boolean;
}

const HEAD_WRITE_DEFAULTS: Required<HeadWriteOptions> = { binary: true };

/** What the export scene is made of (for tests): the scene, its clips, and the meshes that carry morph targets. */
export interface ExportScene {
  scene: Object3D;
  animations: AnimationClip[];
  skin: Mesh;
  /** Meshes under the jaw node that carry the jaw's turn as morph targets (none if no shape turns it). */
  jawMeshes: Mesh[];
  /** The brows and lashes shown, with the skin's morph targets. */
  hairMeshes: Mesh[];
  /** Frees the geometries made for the export (the materials are the shown head's). */
  dispose(): void;
}

/** A node's local transform, kept as it was when the head was shown. */
interface RestTransform {
  position: Vector3;
  quaternion: Quaternion;
  scale: Vector3;
}

/**
 * Writes a shown head as glTF with morph targets: the skin at rest with each shape's displacement (positions and
 * normals, relative, named after the shape), the eyes and teeth as they are, and the jaw's turn baked into the lower
 * teeth's and tongue's morph targets under the same names, so that a target's weight at 1 is that expression whole.
 * The head's nodes are taken at the poses they had when the exporter was made (the head at rest).
 */
export class HeadExporter {
  private readonly rest = new Map<Object3D, RestTransform>();

  /** `restPositions` and `restNormals` are the skin at rest, xyz per render vertex (the mesh's own vertex order). */
  constructor(
    private readonly head: HeadModel,
    private readonly restPositions: Float32Array,
    private readonly restNormals: Float32Array,
  ) {
    head.root.traverse((o) => this.rest.set(o, { position: o.position.clone(), quaternion: o.quaternion.clone(), scale: o.scale.clone() }));
  }

  /** Render vertices of the skin. */
  get vertexCount(): number {
    return this.restPositions.length / 3;
  }

  /** The jaw node's pose now (null without a jaw node). */
  jawPose(): JawPose | null {
    const jaw = this.head.jaw;
    if (!jaw) return null;
    return { quaternion: jaw.quaternion.toArray() as JawPose['quaternion'], position: jaw.position.toArray() as JawPose['position'] };
  }

  /** The scene to export: a copy of the head at rest with the morph targets of `shapes` and the clip's animation. */
  buildScene(shapes: readonly MorphShape[], clip: MorphClip | null): ExportScene {
    const n = this.vertexCount;
    for (const s of shapes) {
      if (s.positions.length !== 3 * n || s.normals.length !== 3 * n)
        throw new Error(`the shape ${s.name} has ${s.positions.length / 3} vertices, the skin ${n}`);
    }
    const scene = this.head.root.clone(true);
    const copies = new Map<Object3D, Object3D>();
    pairUp(this.head.root, scene, copies);
    for (const [original, copy] of copies) {
      const r = this.rest.get(original);
      if (r) {
        copy.position.copy(r.position);
        copy.quaternion.copy(r.quaternion);
        copy.scale.copy(r.scale);
      }
      // The view's switches (eyes, teeth) do not decide what the file holds.
      copy.visible = true;
    }
    // The model's own extras describe a softface head model, which this file is not.
    delete scene.userData.softface;
    const made: BufferGeometry[] = [];

    const skin = copies.get(this.head.skin) as Mesh;
    const geometry = plainGeometry(this.head.skin.geometry, { position: this.restPositions, normal: this.restNormals });
    geometry.morphTargetsRelative = true;
    geometry.morphAttributes.position = shapes.map((s) => named(difference(s.positions, this.restPositions), s.name));
    geometry.morphAttributes.normal = shapes.map((s) => named(difference(s.normals, this.restNormals), s.name));
    skin.geometry = geometry;
    skin.updateMorphTargets();
    made.push(geometry);

    const jawMeshes = this.bakeJaw(scene, copies, shapes, made);
    // The brows and lashes as shown (hidden ones left out), at rest, with the skin's targets.
    const hairMeshes: Mesh[] = [];
    for (const { mesh, shown } of this.head.hair?.meshes() ?? []) {
      const copy = copies.get(mesh) as Mesh;
      if (!shown) {
        copy.removeFromParent();
        continue;
      }
      copy.geometry = this.head.hair!.bakedGeometry(mesh, { positions: this.restPositions, normals: this.restNormals }, shapes);
      copy.updateMorphTargets();
      made.push(copy.geometry);
      hairMeshes.push(copy);
    }
    const animations: AnimationClip[] = [];
    if (clip) {
      const count = clip.times.length;
      if (clip.weights.length !== count * shapes.length)
        throw new Error(`the clip ${clip.name} has ${clip.weights.length} weights for ${count} times of ${shapes.length} targets`);
      // By uuid: node names of a loaded head need not be unique.
      const tracks = [skin, ...jawMeshes, ...hairMeshes].map(
        (m) => new NumberKeyframeTrack(`${m.uuid}.morphTargetInfluences`, clip.times, clip.weights),
      );
      animations.push(new AnimationClip(clip.name, clip.duration, tracks));
    }
    return { scene, animations, skin, jawMeshes, hairMeshes, dispose: () => made.forEach((g) => g.dispose()) };
  }

  /** Exports the scene `buildScene` makes, through three.js's GLTFExporter: a GLB, or a glTF JSON document. */
  async write(
    shapes: readonly MorphShape[],
    clip: MorphClip | null,
    options: HeadWriteOptions = {},
  ): Promise<ArrayBuffer | Record<string, unknown>> {
    const o = { ...HEAD_WRITE_DEFAULTS, ...options };
    // Loaded when first used: most pages never export.
    const { GLTFExporter } = await import('three/addons/exporters/GLTFExporter.js');
    const built = this.buildScene(shapes, clip);
    const drawable = withDrawableTextures(built.scene);
    try {
      const result = await new GLTFExporter().parseAsync(built.scene, {
        binary: o.binary,
        animations: built.animations,
        onlyVisible: false,
      });
      return result as ArrayBuffer | Record<string, unknown>;
    } finally {
      drawable.dispose();
      built.dispose();
    }
  }

  /**
   * Gives each mesh under the jaw node the jaw's turn of each shape as a morph target (relative to the head at rest,
   * in the mesh's own frame): glTF morph targets cannot turn a node. Returns those meshes (none if no shape turns it).
   */
  private bakeJaw(scene: Object3D, copies: Map<Object3D, Object3D>, shapes: readonly MorphShape[], made: BufferGeometry[]): Mesh[] {
    const jaw = this.head.jaw ? copies.get(this.head.jaw) : undefined;
    if (!jaw) return [];
    const rest = { position: jaw.position.clone(), quaternion: jaw.quaternion.clone() };
    const turned = shapes.some((s) => s.jaw && !samePose(s.jaw, rest.position, rest.quaternion));
    if (!turned) return [];
    const meshes: Mesh[] = [];
    jaw.traverse((o) => {
      if (o instanceof Mesh) meshes.push(o);
    });
    scene.updateMatrixWorld(true);
    const restWorld = meshes.map((m) => m.matrixWorld.clone());
    const restInverse = restWorld.map((m) => m.clone().invert());
    // Per shape, per mesh: the move in the mesh's frame at rest, restWorld⁻¹ · turnedWorld.
    const moves = shapes.map((s) => {
      if (s.jaw) {
        jaw.position.fromArray(s.jaw.position);
        jaw.quaternion.fromArray(s.jaw.quaternion);
      }
      scene.updateMatrixWorld(true);
      const m = meshes.map((mesh, i) => new Matrix4().multiplyMatrices(restInverse[i], mesh.matrixWorld));
      jaw.position.copy(rest.position);
      jaw.quaternion.copy(rest.quaternion);
      return m;
    });
    scene.updateMatrixWorld(true);
    const p = new Vector3();
    const q = new Vector3();
    const normalMatrix = new Matrix3();
    meshes.forEach((mesh, i) => {
      const geometry = plainGeometry(mesh.geometry, {});
      const position = geometry.getAttribute('position');
      const normal = geometry.getAttribute('normal') as BufferAttribute | undefined;
      const positionTargets: BufferAttribute[] = [];
      const normalTargets: BufferAttribute[] = [];
      shapes.forEach((s, k) => {
        const move = moves[k][i];
        const dp = new Float32Array(3 * position.count);
        for (let v = 0; v < position.count; v++) {
          p.fromBufferAttribute(position, v);
          q.copy(p).applyMatrix4(move).sub(p);
          q.toArray(dp, 3 * v);
        }
        positionTargets.push(named(dp, s.name));
        if (normal) {
          normalMatrix.getNormalMatrix(move);
          const dn = new Float32Array(3 * normal.count);
          for (let v = 0; v < normal.count; v++) {
            p.fromBufferAttribute(normal, v);
            q.copy(p).applyMatrix3(normalMatrix).normalize().sub(p);
            q.toArray(dn, 3 * v);
          }
          normalTargets.push(named(dn, s.name));
        }
      });
      geometry.morphTargetsRelative = true;
      geometry.morphAttributes.position = positionTargets;
      if (normal) geometry.morphAttributes.normal = normalTargets;
      mesh.geometry = geometry;
      mesh.updateMorphTargets();
      made.push(geometry);
    });
    return meshes;
  }
}

/**
 * Gives the scene's meshes copies of their materials whose data textures (the pore and eye maps, made in code) are
 * canvases: GLTFExporter redraws a normal map through a canvas (to flip its green channel for meshes without
 * tangents), which takes an image, not raw pixels. Returns what frees the copies; the shown head keeps its own.
 */
function withDrawableTextures(scene: Object3D): { dispose(): void } {
  const textures = new Map<Texture, Texture>();
  const materials = new Map<Material, Material>();
  const drawable = (t: Texture): Texture => {
    let copy = textures.get(t);
    if (!copy) {
      const { data, width, height } = t.image as { data: Uint8Array; width: number; height: number };
      const canvas = document.createElement('canvas');
      canvas.width = width;
      canvas.height = height;
      canvas.getContext('2d')!.putImageData(new ImageData(Uint8ClampedArray.from(data), width, height), 0, 0);
      copy = t.clone();
      copy.source = new Source(canvas);
      textures.set(t, copy);
    }
    return copy;
  };
  scene.traverse((o) => {
    if (!(o instanceof Mesh)) return;
    const swap = (m: Material): Material => {
      const entries = Object.entries(m).filter(
        ([, v]) => v instanceof Texture && (v.image as { data?: unknown } | null)?.data instanceof Uint8Array,
      );
      if (entries.length === 0) return m;
      let copy = materials.get(m);
      if (!copy) {
        copy = m.clone();
        for (const [key, t] of entries) (copy as unknown as Record<string, Texture>)[key] = drawable(t as Texture);
        materials.set(m, copy);
      }
      return copy;
    };
    o.material = Array.isArray(o.material) ? o.material.map(swap) : swap(o.material);
  });
  return {
    dispose: () => {
      for (const t of textures.values()) t.dispose();
      for (const m of materials.values()) m.dispose();
    },
  };
}

/** Walks two copies of a tree side by side, pairing each original node with its copy. */
function pairUp(original: Object3D, copy: Object3D, into: Map<Object3D, Object3D>): void {
  into.set(original, copy);
  for (let i = 0; i < original.children.length; i++) pairUp(original.children[i], copy.children[i], into);
}

/**
 * A geometry with plain float attributes (the model's may be interleaved) copied from `source`: position, normal, uv
 * and colour where it has them, `replace` taking the place of some, and its triangles.
 */
function plainGeometry(source: BufferGeometry, replace: Partial<Record<'position' | 'normal', Float32Array>>): BufferGeometry {
  const geometry = new BufferGeometry();
  for (const name of ['position', 'normal', 'uv', 'color'] as const) {
    const given = name === 'position' || name === 'normal' ? replace[name] : undefined;
    if (given) {
      geometry.setAttribute(name, new BufferAttribute(given.slice(), 3));
      continue;
    }
    const a = source.getAttribute(name);
    if (!a) continue;
    const array = new Float32Array(a.count * a.itemSize);
    for (let i = 0; i < a.count; i++) for (let k = 0; k < a.itemSize; k++) array[i * a.itemSize + k] = a.getComponent(i, k);
    geometry.setAttribute(name, new BufferAttribute(array, a.itemSize));
  }
  if (source.index) geometry.setIndex(new BufferAttribute(source.index.array.slice(), 1));
  for (const group of source.groups) geometry.addGroup(group.start, group.count, group.materialIndex);
  return geometry;
}

/** `a - b`, element by element. */
function difference(a: Float32Array, b: Float32Array): Float32Array {
  const out = new Float32Array(a.length);
  for (let i = 0; i < a.length; i++) out[i] = a[i] - b[i];
  return out;
}

/** A morph attribute named after its target (three.js builds `morphTargetDictionary` from the names). */
function named(array: Float32Array, name: string): BufferAttribute {
  const attribute = new BufferAttribute(array, 3);
  attribute.name = name;
  return attribute;
}

function samePose(pose: JawPose, position: Vector3, quaternion: Quaternion): boolean {
  return (
    new Vector3().fromArray(pose.position).distanceTo(position) < 1e-9 &&
    Math.abs(new Quaternion().fromArray(pose.quaternion).dot(quaternion)) > 1 - 1e-12
  );
}
