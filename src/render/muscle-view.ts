import { clamp01 } from '../core/math3';
import {
  BoxGeometry,
  BufferGeometry,
  Color,
  CylinderGeometry,
  EdgesGeometry,
  Euler,
  Float32BufferAttribute,
  Group,
  LineBasicMaterial,
  LineLoop,
  LineSegments,
  Line,
  Mesh,
  MeshBasicMaterial,
  Quaternion,
  type Raycaster,
  SphereGeometry,
  Vector3,
  type Matrix4,
  type Object3D,
} from 'three';
import { DEGREES } from '../core/math3';
import { MuscleField } from '../core/rig/muscle-fields';
import type { EulerDegrees, Muscle, Vec3 } from '../core/rig/rig-types';

/** Glyph colours by muscle type (sRGB), picked to stand apart from each other and from the skin. */
const MUSCLE_COLOURS: Readonly<Record<Muscle['type'], number>> = Object.freeze({
  linear: 0xff4f5e,
  sphincter: 0xffc83d,
  lid: 0x3fd6ff,
  jaw: 0xb58cff,
});

/** Drawn after the head's opaque and translucent parts (the cornea uses 2), over them, since depth is not tested. */
const RENDER_ORDER = 10;
/** Sizes in metres: linear muscle rod radius, bone-end and joint marker radius. */
const ROD_RADIUS = 0.0009;
const MARKER_RADIUS = 0.0025;
/** Colour at rest, as a share of the type's colour: dimmer, so that contracting muscles stand out brighter. */
const REST_LEVEL = 0.7;
/** How far (metres) from a glyph's lines a click still picks it. */
const PICK_THRESHOLD = 0.003;

type Shapes = Record<'sphere' | 'rod' | 'ring' | 'ellipsoid' | 'principal' | 'box', BufferGeometry>;

/** One muscle's glyphs and its own materials (its colour follows its own contraction). */
interface MuscleGlyph {
  name: string;
  object: Group;
  base: Color;
  materials: (MeshBasicMaterial | LineBasicMaterial)[];
  /** The contraction its colour shows, so that an unchanged one costs nothing. */
  level: number;
  /** Invisible shapes clicks are tested against: lines first, then volumes (a click inside an ellipsoid or box). */
  pickLines: Object3D[];
  pickVolumes: Object3D[];
  /** Its own geometries (the pick line), freed with it. */
  own: BufferGeometry[];
}

/**
 * The rig's muscles as simple glyphs over the head: a linear muscle as a rod from origin to insertion with a ball at
 * its bone end and a ring showing its cone at the insertion; a sphincter as a wireframe ellipsoid (its inner one
 * fainter); a lid as an ellipsoid with a ball at its joint; the jaw as a box with its hinge axis. Built once; showing
 * and highlighting only flip visibility and colours, so nothing is allocated per frame.
 */
export class MuscleView {
  /** Add this to the scene; hidden until some muscle is shown. */
  readonly group = new Group();
  private readonly glyphs: MuscleGlyph[] = [];
  private readonly geometries: BufferGeometry[] = [];
  private readonly white = new Color(1, 1, 1);
  private readonly shapes: Shapes;
  /** Not drawn: pick shapes are only raycast. */
  private readonly hidden = new MeshBasicMaterial({ visible: false });
  private readonly hiddenLine = new LineBasicMaterial({ visible: false });
  /** What `setVisible` was last given, so rebuilt glyphs show as before. */
  private visibleNames: ReadonlySet<string> | 'all' | 'none' = 'none';
  private highlighted: string | null = null;

  /** Moves the glyphs with the skin: `frame` maps the rig's frame to the scene's (the skin's world matrix). */
  setFrame(frame: Matrix4): void {
    this.group.matrix.copy(frame);
    this.group.matrixWorldNeedsUpdate = true;
  }

  /** `muscles` are positioned in the frame `frame` maps to the scene's (the skin's world matrix). */
  constructor(muscles: readonly Muscle[], frame?: Matrix4) {
    this.group.name = 'muscles';
    this.group.visible = false;
    // The frame changes only when the head turns (setFrame), so it is set then rather than recomputed per frame.
    this.group.matrixAutoUpdate = false;
    if (frame) this.group.matrix.copy(frame);
    this.shapes = {
      sphere: this.keep(new SphereGeometry(1, 10, 8)),
      rod: this.keep(new CylinderGeometry(1, 1, 1, 8, 1)),
      ring: this.keep(circle('y')),
      ellipsoid: this.keep(latLongLines(6, 5, 32)),
      principal: this.keep(mergeLines([circle('x'), circle('y'), circle('z')])),
      box: this.keep(new BoxGeometry(1, 1, 1)),
    };
    this.boxEdges = this.keep(new EdgesGeometry(this.shapes.box));
    this.setMuscles(muscles);
  }

  private readonly boxEdges: BufferGeometry;

  /** Rebuilds every glyph for a new muscle list (an edited rig); what is shown and highlighted stays, by name. */
  setMuscles(muscles: readonly Muscle[]): void {
    for (const g of this.glyphs) this.drop(g);
    this.glyphs.length = 0;
    for (const muscle of muscles) this.glyphs.push(this.build(muscle));
    this.setVisible(this.visibleNames);
    this.paintAll();
  }

  /** Rebuilds the glyph of muscle `index` (an edited muscle), keeping its visibility and colour. */
  updateMuscle(index: number, muscle: Muscle): void {
    const old = this.glyphs[index];
    if (!old) throw new Error(`MuscleView.updateMuscle: no muscle ${index}`);
    const glyph = this.build(muscle);
    glyph.object.visible = old.object.visible;
    glyph.level = old.level;
    this.drop(old);
    this.glyphs[index] = glyph;
    this.paint(glyph);
  }

  /** Draws the named muscle brighter and whiter than the others (null: none). */
  setHighlight(name: string | null): void {
    if (name === this.highlighted) return;
    this.highlighted = name;
    this.paintAll();
  }

  /**
   * The shown muscle whose glyph the ray hits first: its lines (rods, wireframes) within a few millimetres, else the
   * inside of an ellipsoid or box. Null if none.
   */
  pick(raycaster: Raycaster): string | null {
    if (!this.group.visible) return null;
    this.group.updateMatrixWorld(true);
    const shown = this.glyphs.filter((g) => g.object.visible);
    const threshold = raycaster.params.Line.threshold;
    raycaster.params.Line.threshold = PICK_THRESHOLD;
    try {
      for (const kind of ['pickLines', 'pickVolumes'] as const) {
        let best: { name: string; distance: number } | null = null;
        for (const g of shown) {
          for (const hit of raycaster.intersectObjects(g[kind], false)) {
            if (!best || hit.distance < best.distance) best = { name: g.name, distance: hit.distance };
          }
        }
        if (best) return best.name;
      }
      return null;
    } finally {
      raycaster.params.Line.threshold = threshold;
    }
  }

  /** Shows the named muscles (unknown names are ignored), every muscle, or none. */
  setVisible(names: ReadonlySet<string> | 'all' | 'none'): void {
    this.visibleNames = names;
    let any = false;
    for (const g of this.glyphs) {
      g.object.visible = names === 'all' || (names !== 'none' && names.has(g.name));
      any ||= g.object.visible;
    }
    // Hidden as a whole when empty, so the renderer does not even walk the glyphs.
    this.group.visible = any;
  }

  /** The names of the muscles drawn now, in rig order (read-only, for tests). */
  shown(): string[] {
    return this.group.visible ? this.glyphs.filter((g) => g.object.visible).map((g) => g.name) : [];
  }

  /** Brightens each muscle with its contraction (0..1, by rig index); allocation-free. */
  setContractions(contractions: ArrayLike<number>): void {
    for (let i = 0; i < this.glyphs.length; i++) {
      const g = this.glyphs[i];
      const c = clamp01(contractions[i] ?? 0);
      // Colour changes are cheap but not free; the eye simulation reports contractions every frame.
      if (Math.abs(c - g.level) < 0.01) continue;
      g.level = c;
      this.paint(g);
    }
  }

  private paintAll(): void {
    for (const g of this.glyphs) this.paint(g);
  }

  /** Colours a glyph for its contraction, and whitens the highlighted one. */
  private paint(g: MuscleGlyph): void {
    const c = g.level;
    const selected = g.name === this.highlighted;
    for (const m of g.materials) {
      m.color
        .copy(g.base)
        .multiplyScalar(REST_LEVEL + (1 - REST_LEVEL) * c)
        .lerp(this.white, selected ? 0.6 : 0.55 * c);
    }
  }

  /** Takes a glyph out of the group and frees what is its own. */
  private drop(g: MuscleGlyph): void {
    g.object.removeFromParent();
    for (const m of g.materials) m.dispose();
    for (const geometry of g.own) geometry.dispose();
  }

  /** Frees every geometry and material and detaches the group. */
  dispose(): void {
    this.group.removeFromParent();
    for (const g of this.glyphs) this.drop(g);
    for (const geometry of this.geometries) geometry.dispose();
    this.hidden.dispose();
    this.hiddenLine.dispose();
    this.glyphs.length = 0;
    this.geometries.length = 0;
  }

  private keep<T extends BufferGeometry>(geometry: T): T {
    this.geometries.push(geometry);
    return geometry;
  }

  private build(muscle: Muscle): MuscleGlyph {
    const shapes = this.shapes;
    const pickLines: Object3D[] = [];
    const pickVolumes: Object3D[] = [];
    const own: BufferGeometry[] = [];
    const base = new Color(MUSCLE_COLOURS[muscle.type]);
    const overlay = { transparent: true, depthTest: false, depthWrite: false, toneMapped: false };
    const solid = new MeshBasicMaterial({ ...overlay, opacity: 0.9 });
    const line = new LineBasicMaterial({ ...overlay, opacity: 0.85 });
    const faint = new LineBasicMaterial({ ...overlay, opacity: 0.35 });
    const materials = [solid, line, faint];
    const color = base.clone().multiplyScalar(REST_LEVEL);
    for (const m of materials) m.color.copy(color);
    const object = new Group();
    object.name = muscle.name;
    object.visible = false;
    const field = new MuscleField(muscle);
    if (muscle.type === 'linear') {
      const origin = new Vector3(...muscle.origin);
      const axis = new Vector3(...muscle.insertion).sub(origin);
      const length = axis.length();
      // A frame at the origin whose +y runs to the insertion: the rod, ball and ring are unit shapes in it.
      object.position.copy(origin);
      object.quaternion.setFromUnitVectors(new Vector3(0, 1, 0), axis.normalize());
      add(object, new Mesh(shapes.rod, solid), [0, length / 2, 0], [ROD_RADIUS, length, ROD_RADIUS]);
      add(object, new Mesh(shapes.sphere, solid), [0, 0, 0], [MARKER_RADIUS, MARKER_RADIUS, MARKER_RADIUS]);
      const cone = length * Math.tan(muscle.angle * DEGREES);
      add(object, new LineLoop(shapes.ring, faint), [0, length, 0], [cone, 1, cone]);
      const axisLine = new BufferGeometry().setAttribute('position', new Float32BufferAttribute([0, 0, 0, 0, length, 0], 3));
      own.push(axisLine);
      pickLines.push(add(object, new Line(axisLine, this.hiddenLine), [0, 0, 0], [1, 1, 1]));
    } else {
      const frame = new Group();
      frame.position.set(...muscle.center);
      frame.quaternion.copy(rotationOf(muscle.rotation));
      object.add(frame);
      if (muscle.type === 'sphincter') {
        pickLines.push(add(frame, new LineSegments(shapes.ellipsoid, line), [0, 0, 0], muscle.radii));
        add(frame, new LineSegments(shapes.principal, faint), [0, 0, 0], muscle.innerRadii);
        pickVolumes.push(add(frame, new Mesh(shapes.sphere, this.hidden), [0, 0, 0], muscle.radii));
      } else if (muscle.type === 'lid') {
        pickLines.push(add(frame, new LineSegments(shapes.ellipsoid, line), [0, 0, 0], muscle.radii));
        pickVolumes.push(add(frame, new Mesh(shapes.sphere, this.hidden), [0, 0, 0], muscle.radii));
      } else {
        pickLines.push(add(frame, new LineSegments(this.boxEdges, line), [0, 0, 0], muscle.size));
        pickVolumes.push(add(frame, new Mesh(shapes.box, this.hidden), [0, 0, 0], muscle.size));
      }
      const joint = field.joint();
      const turn = field.axis();
      if (joint && turn) {
        add(object, new Mesh(shapes.sphere, solid), joint, [MARKER_RADIUS, MARKER_RADIUS, MARKER_RADIUS]);
        if (muscle.type === 'jaw') {
          // The hinge axis, as wide as the box, so the turn's direction reads at a glance.
          const hinge = add(object, new Mesh(shapes.rod, solid), joint, [ROD_RADIUS, muscle.size[0], ROD_RADIUS]);
          hinge.quaternion.setFromUnitVectors(new Vector3(0, 1, 0), new Vector3(...turn));
        }
      }
    }
    object.traverse((o) => (o.renderOrder = RENDER_ORDER));
    this.group.add(object);
    return { name: muscle.name, object, base, materials, level: 0, pickLines, pickVolumes, own };
  }
}

/** Adds `child` to `parent` at `position` with `scale`; returns it. */
function add<T extends Object3D>(parent: Object3D, child: T, position: Vec3 | readonly number[], scale: Vec3 | readonly number[]): T {
  child.position.set(position[0], position[1], position[2]);
  child.scale.set(scale[0], scale[1], scale[2]);
  parent.add(child);
  return child;
}

/** The rig's Euler angles (R = Rz * Ry * Rx, degrees) as a quaternion: three.js's intrinsic 'ZYX' order. */
export function rotationOf(rotation: EulerDegrees): Quaternion {
  return new Quaternion().setFromEuler(new Euler(rotation[0] * DEGREES, rotation[1] * DEGREES, rotation[2] * DEGREES, 'ZYX'));
}

/** A unit circle of `segments` points around the axis `normal` (for a LineLoop, or as segments via mergeLines). */
function circle(normal: 'x' | 'y' | 'z', segments = 48): BufferGeometry {
  const p: number[] = [];
  for (let i = 0; i < segments; i++) {
    const a = (2 * Math.PI * i) / segments;
    const [u, v] = [Math.cos(a), Math.sin(a)];
    p.push(...(normal === 'x' ? [0, u, v] : normal === 'y' ? [u, 0, v] : [u, v, 0]));
  }
  return new BufferGeometry().setAttribute('position', new Float32BufferAttribute(p, 3));
}

/** Closed point loops (as `circle` makes) joined into one segment list for LineSegments; the inputs are disposed. */
function mergeLines(loops: BufferGeometry[]): BufferGeometry {
  const out: number[] = [];
  for (const loop of loops) {
    const p = loop.getAttribute('position');
    for (let i = 0; i < p.count; i++) {
      const j = (i + 1) % p.count;
      out.push(p.getX(i), p.getY(i), p.getZ(i), p.getX(j), p.getY(j), p.getZ(j));
    }
    loop.dispose();
  }
  return new BufferGeometry().setAttribute('position', new Float32BufferAttribute(out, 3));
}

/** A unit sphere's meridians and parallels as segments: reads as an ellipsoid once scaled, without triangle diagonals. */
function latLongLines(meridians: number, parallels: number, segments: number): BufferGeometry {
  const p: number[] = [];
  const point = (polar: number, azimuth: number): number[] => [
    Math.sin(polar) * Math.cos(azimuth),
    Math.cos(polar),
    Math.sin(polar) * Math.sin(azimuth),
  ];
  for (let m = 0; m < meridians; m++) {
    const az = (Math.PI * m) / meridians; // each meridian is a full great circle through the poles
    for (let i = 0; i < segments; i++) p.push(...point((2 * Math.PI * i) / segments, az), ...point((2 * Math.PI * (i + 1)) / segments, az));
  }
  for (let k = 1; k <= parallels; k++) {
    const polar = (Math.PI * k) / (parallels + 1);
    for (let i = 0; i < segments; i++)
      p.push(...point(polar, (2 * Math.PI * i) / segments), ...point(polar, (2 * Math.PI * (i + 1)) / segments));
  }
  return new BufferGeometry().setAttribute('position', new Float32BufferAttribute(p, 3));
}
