import { Euler, Object3D, type Vector3, type Camera } from 'three';
import { TransformControls } from 'three/addons/controls/TransformControls.js';
import { DEGREES } from '../core/math3';
import { MuscleField } from '../core/rig/muscle-fields';
import type { Muscle, Vec3 } from '../core/rig/rig-types';
import { rotationOf } from './muscle-view';

/** What the editor's gizmo does to the part it holds: move, turn or scale it (a point only moves). */
export type GizmoMode = 'translate' | 'rotate' | 'scale';
/**
 * The part of the selected muscle the editor's gizmo holds: a linear muscle's `insertion` or `origin` (its bone end),
 * a sphincter's or lid's `ellipsoid`, the jaw's `box` or `hinge` (its joint). Points only move; volumes also turn and
 * scale.
 */
export type GizmoPart = 'insertion' | 'origin' | 'ellipsoid' | 'box' | 'hinge';

/** Told while a drag runs: when it starts, each change of the part (as muscle fields), and when it ends. */
export interface GizmoDrag {
  start(): void;
  change(partial: Partial<Muscle>): void;
  end(): void;
}

/** Coordinates are written to 0.01 mm and angles to 0.01°, so that saved rigs stay readable. */
const round = (x: number, step: number): number =>
  Number((Math.round(x / step) * step).toFixed(Math.max(0, -Math.floor(Math.log10(step)))));
const point = (v: Vector3): Vec3 => [round(v.x, 1e-5), round(v.y, 1e-5), round(v.z, 1e-5)];

/**
 * three.js TransformControls on one part of one muscle, in the rig's frame: a point (a linear muscle's insertion or
 * bone end, the jaw's hinge) only moves; an ellipsoid or the jaw's box also turns (its Euler angles) and scales (its
 * radii or size; a sphincter's inner radii in proportion). Each pointer move of a drag reports the part's new fields.
 */
export class MuscleGizmo {
  readonly controls: TransformControls;
  /** The object the controls move: a stand-in for the part, in the rig's frame. */
  private readonly target = new Object3D();
  private muscle: Muscle | null = null;
  private partNow: GizmoPart | null = null;
  private modeNow: GizmoMode = 'translate';
  /** The muscle as the drag found it: scales apply to its radii or size. */
  private startMuscle: Muscle | null = null;
  private readonly euler = new Euler();

  /** `frame` is the rig's frame in the scene (the muscle glyphs' group); the helper is added to `scene`. */
  constructor(
    camera: Camera,
    domElement: HTMLElement,
    frame: Object3D,
    scene: Object3D,
    private readonly drag: GizmoDrag,
  ) {
    this.target.name = 'muscle-gizmo-target';
    frame.add(this.target);
    this.controls = new TransformControls(camera, domElement);
    this.controls.setSpace('local');
    this.controls.setSize(0.8);
    this.controls.enabled = false;
    scene.add(this.controls.getHelper());
    this.controls.addEventListener('mouseDown', () => {
      this.startMuscle = this.muscle;
      this.drag.start();
    });
    this.controls.addEventListener('objectChange', () => {
      const partial = this.read();
      if (partial) this.drag.change(partial);
    });
    this.controls.addEventListener('mouseUp', () => {
      this.startMuscle = null;
      this.drag.end();
      // Scales are read relative to the drag's start; the next drag starts from the new radii at scale 1.
      if (this.muscle && this.partNow) this.place(this.muscle, this.partNow);
    });
  }

  /**
   * Brings the camera's and the gizmo's matrices up to date: they are otherwise updated when a frame renders, and a
   * press that comes before the first frame after the gizmo moved (a slow software renderer) would miss its handles.
   */
  refresh(camera: Camera): void {
    camera.updateMatrixWorld();
    this.controls.getHelper().updateMatrixWorld(true);
  }

  /** Whether a drag runs. */
  get dragging(): boolean {
    return this.controls.dragging;
  }

  /** Whether the pointer is over one of the gizmo's handles. */
  get hovered(): boolean {
    return this.controls.axis !== null;
  }

  /** The part held now, or null. */
  get part(): GizmoPart | null {
    return this.partNow;
  }

  /** Holds `part` of `muscle` (or nothing with null); during a drag only the muscle is updated, not the stand-in. */
  attach(muscle: Muscle | null, part: GizmoPart | null): void {
    this.muscle = muscle;
    this.partNow = muscle ? part : null;
    if (this.dragging) return;
    if (!muscle || !part) {
      this.controls.detach();
      this.controls.enabled = false;
      return;
    }
    this.place(muscle, part);
    this.controls.attach(this.target);
    this.controls.enabled = true;
    this.applyMode();
  }

  setMode(mode: GizmoMode): void {
    this.modeNow = mode;
    this.applyMode();
  }

  /** The gizmo's centre in world space, or null when it holds nothing. */
  worldPosition(out: Vector3): Vector3 | null {
    if (!this.partNow) return null;
    return this.target.getWorldPosition(out);
  }

  dispose(): void {
    this.controls.detach();
    this.controls.getHelper().removeFromParent();
    this.controls.dispose();
    this.target.removeFromParent();
  }

  /** Points only move; volumes move, turn and scale. */
  private applyMode(): void {
    const isPoint = this.partNow === 'insertion' || this.partNow === 'origin' || this.partNow === 'hinge';
    this.controls.setMode(isPoint ? 'translate' : this.modeNow);
  }

  /** Puts the stand-in on the part: its point, and for a volume its rotation, at scale 1. */
  private place(muscle: Muscle, part: GizmoPart): void {
    const t = this.target;
    t.scale.set(1, 1, 1);
    t.quaternion.identity();
    if (muscle.type === 'linear') t.position.set(...(part === 'origin' ? muscle.origin : muscle.insertion));
    else if (muscle.type === 'jaw' && part === 'hinge') {
      t.position.set(...(new MuscleField(muscle).joint() as Vec3));
      t.quaternion.copy(rotationOf(muscle.rotation));
    } else {
      t.position.set(...muscle.center);
      t.quaternion.copy(rotationOf(muscle.rotation));
    }
    t.updateMatrixWorld(true);
  }

  /** The part's fields as the stand-in now has them. */
  private read(): Partial<Muscle> | null {
    const m = this.startMuscle ?? this.muscle;
    const part = this.partNow;
    if (!m || !part) return null;
    const t = this.target;
    const at = point(t.position);
    if (m.type === 'linear') return part === 'origin' ? { origin: at } : { insertion: at };
    if (m.type === 'jaw' && part === 'hinge') return { joint: at } as Partial<Muscle>;
    this.euler.setFromQuaternion(t.quaternion, 'ZYX');
    const rotation: Vec3 = [round(this.euler.x / DEGREES, 0.01), round(this.euler.y / DEGREES, 0.01), round(this.euler.z / DEGREES, 0.01)];
    const s = [Math.abs(t.scale.x), Math.abs(t.scale.y), Math.abs(t.scale.z)].map((k) => Math.max(k, 1e-3));
    const scaled = (v: Vec3): Vec3 => [round(v[0] * s[0], 1e-5), round(v[1] * s[1], 1e-5), round(v[2] * s[2], 1e-5)];
    if (m.type === 'jaw') return { center: at, rotation, size: scaled(m.size) } as Partial<Muscle>;
    if (m.type === 'sphincter')
      return { center: at, rotation, radii: scaled(m.radii), innerRadii: scaled(m.innerRadii) } as Partial<Muscle>;
    return { center: at, rotation, radii: scaled(m.radii) } as Partial<Muscle>;
  }
}
