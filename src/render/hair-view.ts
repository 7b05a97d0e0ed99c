import { BufferAttribute, BufferGeometry, Color, DoubleSide, DynamicDrawUsage, Mesh, MeshStandardMaterial } from 'three';
import { FrontCaster } from '../core/hair/front-caster';
import { poseHair, type HairStrands } from '../core/hair/hair';
import { placeBrows, placeLashes, type HairEye, type HairLandmarks } from '../core/hair/hair-placement';
import { SkinContact } from '../core/hair/skin-contact';
import { APPEARANCE_DEFAULTS, type AppearanceOptions } from './view-options';

/** Names of the hair meshes (children of the skin mesh), as a glTF export shows them. */
const HAIR_NODES = Object.freeze({ brows: 'eyebrows', lashes: 'eyelashes' });

/** A skin's shape: positions and normals, xyz per render vertex. */
export interface SkinShape {
  positions: Float32Array;
  normals: Float32Array;
}

/** One kind of hair as drawn now (`face.getHair()`): vertices as shown, and where each hair is anchored. */
export interface HairPartSnapshot {
  /** Hairs drawn (0 when switched off). */
  count: number;
  /** Vertices in one hair's ribbon: two per point along the hair, the root's pair first. */
  verticesPerHair: number;
  /** The drawn hairs' ribbon vertices as shown, xyz in the skin's model space; a hair's first two are its root. */
  positions: Float32Array;
  /** Per hair, its anchor triangle's three skin vertices (simulation order, as `getSkin` gives them). */
  corners: Uint32Array;
  /** Per hair, the anchor point's barycentric weights in that triangle. */
  weights: Float32Array;
}

/** The face's brows and lashes as drawn now. */
export interface HairSnapshot {
  /** The eyebrows: no hairs while `brows` is off (see `setAppearance`), fewer at a lower `browDensity`. */
  brows: HairPartSnapshot;
  /** The eyelashes: no hairs while `lashes` is off (see `setAppearance`). */
  lashes: HairPartSnapshot;
}

/** One kind of hair: its strands, mesh and the attributes posed at each skin frame. */
interface HairPart {
  strands: HairStrands;
  mesh: Mesh<BufferGeometry, MeshStandardMaterial>;
  positions: BufferAttribute;
  normals: BufferAttribute;
  /** Hairs drawn (a prefix of the shuffled strands: the density). */
  drawn: number;
}

/**
 * Eyebrows and eyelashes on a skin mesh: strands placed once from the skin at rest and the eye corners, drawn as
 * thin ribbons that are posed on the skin's current positions and normals whenever the skin shows a new frame (see
 * core/hair.ts). The meshes are children of the skin mesh, so they share its transform and leave with its head.
 */
export class HairView {
  readonly brows: HairPart;
  readonly lashes: HairPart;
  private appearance: Required<AppearanceOptions> = { ...APPEARANCE_DEFAULTS };
  /** The skin's render positions at rest, xyz (the anchors' corners are render vertices). */
  private readonly rest: Float32Array;
  /** Keeps the lashes out of the lids, which close over each other's margins; none without eyes to find them by. */
  private readonly contact: SkinContact | undefined;

  /** Places the hair on `skin` as it is now (at rest), from the eye corners and eyeballs in the skin's own frame. */
  constructor(
    private readonly skin: Mesh,
    landmarks: HairLandmarks,
    eyes: readonly HairEye[] = [],
  ) {
    const geometry = skin.geometry;
    const positions = geometry.getAttribute('position');
    const normals = geometry.getAttribute('normal');
    const surface = {
      positions: Float32Array.from({ length: 3 * positions.count }, (_, i) => positions.getComponent(Math.floor(i / 3), i % 3)),
      normals: Float32Array.from({ length: 3 * normals.count }, (_, i) => normals.getComponent(Math.floor(i / 3), i % 3)),
      triangles: geometry.index!.array,
    };
    this.rest = surface.positions;
    const caster = new FrontCaster(surface.positions, surface.triangles);
    this.brows = part(placeBrows(surface, landmarks, caster), HAIR_NODES.brows);
    this.lashes = part(placeLashes(surface, landmarks, eyes, caster), HAIR_NODES.lashes);
    for (const p of [this.brows, this.lashes]) skin.add(p.mesh);
    if (eyes.length > 0) this.contact = new SkinContact(lidVertices(surface.positions, eyes));
    this.setAppearance(APPEARANCE_DEFAULTS);
    this.skinChanged();
  }

  /** Applies checked appearance options (colours, density, which hair shows). */
  setAppearance(options: Partial<AppearanceOptions>): void {
    const a = Object.assign(this.appearance, options);
    this.brows.mesh.visible = a.brows;
    this.lashes.mesh.visible = a.lashes;
    this.brows.mesh.material.color.set(a.browColor);
    this.lashes.mesh.material.color.set(a.lashColor);
    const drawn = Math.round(a.browDensity * this.brows.strands.count);
    if (drawn !== this.brows.drawn) {
      this.brows.drawn = drawn;
      this.brows.mesh.geometry.setDrawRange(0, (drawn * this.brows.strands.indices.length) / this.brows.strands.count);
      // Hairs that were hidden have not followed the skin.
      this.pose(this.brows);
    }
  }

  /** Poses the hair on the skin mesh's current positions and normals (call after the skin took a new frame). */
  skinChanged(): void {
    this.pose(this.brows);
    this.pose(this.lashes);
  }

  /**
   * The hair as drawn now; `vertexAt` gives the simulation vertex at a rest position (render vertices on a seam are
   * copies of one simulation vertex).
   */
  snapshot(vertexAt: (x: number, y: number, z: number) => number): HairSnapshot {
    const one = (p: HairPart): HairPartSnapshot => {
      const count = p.mesh.visible ? p.drawn : 0;
      const corners = new Uint32Array(3 * count);
      for (let i = 0; i < corners.length; i++) {
        const r = 3 * p.strands.corners[i];
        corners[i] = vertexAt(this.rest[r], this.rest[r + 1], this.rest[r + 2]);
      }
      return {
        count,
        verticesPerHair: p.strands.verticesPerHair,
        positions: (p.positions.array as Float32Array).slice(0, 3 * count * p.strands.verticesPerHair),
        corners,
        weights: p.strands.weights.slice(0, 3 * count),
      };
    };
    return { brows: one(this.brows), lashes: one(this.lashes) };
  }

  /** The hair meshes, each with whether it is shown now (hidden hair stays out of exports). */
  meshes(): { mesh: Mesh; shown: boolean }[] {
    return [this.brows, this.lashes].map((p) => ({ mesh: p.mesh, shown: p.mesh.visible && p.drawn > 0 }));
  }

  /**
   * A copy of `mesh`'s geometry (one of `meshes()`) for an export: the hairs drawn now, posed on the skin at rest,
   * with a morph target per skin shape (named after it, relative, positions and normals), so that a file's morph
   * weights move the hair with the skin.
   */
  bakedGeometry(mesh: Mesh, rest: SkinShape, shapes: readonly (SkinShape & { name: string })[]): BufferGeometry {
    const p = mesh === this.brows.mesh ? this.brows : this.lashes;
    const vertices = p.drawn * p.strands.verticesPerHair;
    const posed = (s: SkinShape): { positions: Float32Array; normals: Float32Array } => {
      const positions = new Float32Array(3 * vertices);
      const normals = new Float32Array(3 * vertices);
      poseHair(p.strands, s.positions, s.normals, positions, normals, p.drawn);
      return { positions, normals };
    };
    const base = posed(rest);
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(base.positions, 3));
    geometry.setAttribute('normal', new BufferAttribute(base.normals, 3));
    geometry.setAttribute(
      'color',
      new BufferAttribute((p.mesh.geometry.getAttribute('color').array as Float32Array).slice(0, 3 * vertices), 3),
    );
    geometry.setIndex(new BufferAttribute(p.strands.indices.slice(0, (p.drawn * p.strands.indices.length) / p.strands.count), 1));
    const targets = shapes.map((s) => ({ name: s.name, ...posed(s) }));
    const relative = (name: string, a: Float32Array, b: Float32Array): BufferAttribute => {
      for (let i = 0; i < a.length; i++) a[i] -= b[i];
      const attribute = new BufferAttribute(a, 3);
      attribute.name = name;
      return attribute;
    };
    geometry.morphTargetsRelative = true;
    geometry.morphAttributes.position = targets.map((t) => relative(t.name, t.positions, base.positions));
    geometry.morphAttributes.normal = targets.map((t) => relative(t.name, t.normals, base.normals));
    return geometry;
  }

  /** Frees the meshes' geometry and materials and takes them off the skin. */
  dispose(): void {
    for (const p of [this.brows, this.lashes]) {
      p.mesh.removeFromParent();
      p.mesh.geometry.dispose();
      p.mesh.material.dispose();
    }
  }

  private pose(p: HairPart): void {
    if (!p.mesh.visible || p.drawn === 0) return;
    const g = this.skin.geometry;
    const positions = g.getAttribute('position').array;
    const normals = g.getAttribute('normal').array;
    const out = p.positions.array as Float32Array;
    poseHair(p.strands, positions, normals, out, p.normals.array as Float32Array, p.drawn);
    if (p === this.lashes && this.contact) {
      this.contact.bin(positions);
      // Past each lash's root pair: the root is on the skin by construction.
      const pairs = p.strands.verticesPerHair / 2;
      for (let h = 0; h < p.drawn; h++) this.contact.resolve(out, h * pairs + 1, (h + 1) * pairs, positions, normals);
    }
    p.positions.needsUpdate = true;
    p.normals.needsUpdate = true;
  }
}

/**
 * The skin vertices that lashes may come near: the lids, within 8 mm of an eyeball's surface and in front of its
 * centre (not the socket behind it), the lids' inner sides among them: a closing lid brings them forward.
 */
function lidVertices(positions: Float32Array, eyes: readonly HairEye[]): Uint32Array {
  const out: number[] = [];
  for (let v = 0; v < positions.length / 3; v++) {
    const x = positions[3 * v],
      y = positions[3 * v + 1],
      z = positions[3 * v + 2];
    const near = (e: HairEye): boolean =>
      z > e.centre[2] && Math.hypot(x - e.centre[0], y - e.centre[1], z - e.centre[2]) < e.radius + 0.008;
    if (eyes.some(near)) out.push(v);
  }
  return Uint32Array.from(out);
}

/** A mesh for strands: dynamic positions and normals, a grey per vertex (the shade) that the colour multiplies. */
function part(strands: HairStrands, name: string): HairPart {
  const geometry = new BufferGeometry();
  const vertices = strands.count * strands.verticesPerHair;
  const positions = new BufferAttribute(new Float32Array(3 * vertices), 3).setUsage(DynamicDrawUsage);
  const normals = new BufferAttribute(new Float32Array(3 * vertices), 3).setUsage(DynamicDrawUsage);
  const shade = new Float32Array(3 * vertices);
  for (let v = 0; v < vertices; v++) shade.fill(strands.shade[v], 3 * v, 3 * v + 3);
  geometry.setAttribute('position', positions);
  geometry.setAttribute('normal', normals);
  geometry.setAttribute('color', new BufferAttribute(shade, 3));
  geometry.setIndex(new BufferAttribute(strands.indices, 1));
  // Hair is a little glossy (a cuticle's sheen), seen from both sides of its ribbons. Its ribbons take the skin's
  // normal, which at a lid's margin faces the room's bright lights: a full reflection there turned dark lashes grey.
  const material = new MeshStandardMaterial({
    name,
    color: new Color(),
    roughness: 0.7,
    metalness: 0,
    envMapIntensity: 0.25,
    side: DoubleSide,
    vertexColors: true,
  });
  const mesh = new Mesh(geometry, material);
  mesh.name = name;
  // The hair moves with the skin, whose bounds the view does not pass on: never culled (it is always in the face).
  mesh.frustumCulled = false;
  return { strands, mesh, positions, normals, drawn: strands.count };
}
