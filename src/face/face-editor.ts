import { Raycaster, Vector2, Vector3, type Camera, type Mesh } from 'three';
import type { BrushSphere } from '../core/rig/rig-types';
import type { RigDocument } from '../core/rig/rig-document';
import type { Muscle } from '../core/rig/rig-types';
import type { HeadView } from '../render/head-view';
import { MuscleGizmo, type GizmoMode, type GizmoPart } from '../render/muscle-gizmo';
import type { MuscleView } from '../render/muscle-view';
import { gizmoParts, type FaceEditorView, type FaceHandle } from './face-handle';

/** A pointer that moves less than this (px) between press and release clicks rather than drags. */
const CLICK_SLOP = 4;

/** Whether a key event comes from a text field, where keys are typing, not commands. */
export function typingInto(event: KeyboardEvent): boolean {
  const t = event.target as HTMLElement | null;
  return !!t && (t.isContentEditable || t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.tagName === 'SELECT');
}

/**
 * The muscle editor on a face's canvas: a click on a muscle's glyph selects it (a raycast against the glyphs), the
 * selected glyph is highlighted, and a TransformControls gizmo holds one of its parts; a drag is one undo step whose
 * every pointer move updates that muscle alone on the skin. While on, W / E / R switch the gizmo to move / turn /
 * scale (E only with a muscle selected: without one, E is the editor's own switch in the panels) and Escape clears
 * the selection. Orbiting pauses while the gizmo drags.
 */
export class FaceEditor implements FaceEditorView {
  private readonly gizmo: MuscleGizmo;
  private readonly raycaster = new Raycaster();
  private readonly pointer = new Vector2();
  private readonly scratch = new Vector3();
  private on = false;
  /** The part chosen for the selected muscle, kept while the gizmo is away (editor off, brush on). */
  private lastPart: GizmoPart | null = null;
  private selected: string | null = null;
  private down: { x: number; y: number; gizmo: boolean } | null = null;
  /** While the brush paints: the muscle painted and the last dab (to space them out). */
  private painting: { name: string; last: BrushSphere | null } | null = null;
  private readonly unsubscribe: () => void;
  private readonly canvas: HTMLCanvasElement;
  private readonly camera: Camera;

  constructor(
    private readonly handle: FaceHandle,
    private readonly view: HeadView,
    private readonly muscles: MuscleView,
    private readonly document: RigDocument,
    /** Whether edits are mirrored onto the twin (the panel's "mirror edits"). */
    private readonly mirror: () => boolean = () => false,
    /** The skin, where new muscles are placed (under the middle of the view) and the brush paints. */
    private readonly skin?: Mesh,
    /** The skin's rest positions in render-vertex order (the brush's dabs are stored at rest). */
    private readonly restRender?: Float32Array,
  ) {
    this.canvas = view.renderer.domElement;
    this.camera = view.camera;
    this.gizmo = new MuscleGizmo(this.camera, this.canvas, muscles.group, view.scene, {
      start: () => handle.beginEdit(),
      change: (partial) => {
        if (this.selected === null) return;
        try {
          document.updateMuscle(this.selected, partial, { mirror: this.mirror() });
        } catch (error) {
          // A drag that leaves the schema's ranges (a radius scaled to nothing) stops at the last valid shape.
          console.warn(`muscle editor: ${(error as Error).message}`);
        }
      },
      end: () => handle.endEdit(),
    });
    this.gizmo.controls.addEventListener('dragging-changed', (event) => {
      view.controls.enabled = !(event as unknown as { value: boolean }).value;
    });
    this.unsubscribe = document.onChange(() => this.follow());
    this.canvas.addEventListener('pointerdown', this.onPointerDown);
    this.canvas.addEventListener('pointerup', this.onPointerUp);
    // Capture: the brush must claim the press before the orbit controls start turning the view.
    this.canvas.addEventListener('pointerdown', this.onBrushDown, { capture: true });
    this.canvas.addEventListener('pointermove', this.onBrushMove);
    window.addEventListener('pointerup', this.onBrushUp);
    window.addEventListener('keydown', this.onKey);
  }

  setEnabled(on: boolean): void {
    this.on = on;
    this.follow();
  }

  select(name: string | null): void {
    const changed = name !== this.selected;
    this.selected = name;
    this.muscles.setHighlight(name);
    if (changed) {
      this.lastPart = null;
      this.attach(this.firstPart());
    }
  }

  setMode(mode: GizmoMode): void {
    this.gizmo.setMode(mode);
  }

  setPart(part: GizmoPart | null): void {
    this.lastPart = part;
    this.attach(part);
  }

  part(): GizmoPart | null {
    return this.on ? this.gizmo.part : null;
  }

  gizmoPoint(): { x: number; y: number } | null {
    if (!this.on) return null;
    const p = this.gizmo.worldPosition(this.scratch);
    return p ? this.toClient(p) : null;
  }

  musclePoint(name: string): { x: number; y: number } | null {
    const m = this.document.rig.muscles.find((x) => x.name === name);
    if (!m) return null;
    const p = m.type === 'linear' ? this.scratch.set(...m.origin).lerp(new Vector3(...m.insertion), 0.5) : this.scratch.set(...m.center);
    this.muscles.group.updateMatrixWorld(true);
    return this.toClient(p.applyMatrix4(this.muscles.group.matrixWorld));
  }

  brushChanged(): void {
    this.follow();
  }

  frontPoint(): [number, number, number] {
    this.camera.updateMatrixWorld();
    this.raycaster.setFromCamera(this.pointer.set(0, 0), this.camera);
    const hit = this.skin ? this.raycaster.intersectObject(this.skin, false)[0] : undefined;
    const world = hit ? hit.point : this.scratch.copy(this.view.controls.target);
    // Into the rig's frame (the glyphs' group), rounded to 0.1 mm.
    const p = world.clone().applyMatrix4(this.muscles.group.matrixWorld.clone().invert());
    return [p.x, p.y, p.z].map((x) => Math.round(x * 1e4) / 1e4) as [number, number, number];
  }

  dispose(): void {
    this.unsubscribe();
    this.canvas.removeEventListener('pointerdown', this.onPointerDown);
    this.canvas.removeEventListener('pointerup', this.onPointerUp);
    this.canvas.removeEventListener('pointerdown', this.onBrushDown, { capture: true });
    this.canvas.removeEventListener('pointermove', this.onBrushMove);
    window.removeEventListener('pointerup', this.onBrushUp);
    this.onBrushUp();
    window.removeEventListener('keydown', this.onKey);
    this.gizmo.dispose();
    this.view.controls.enabled = true;
  }

  /** Keeps the gizmo on the selected muscle's part as the rig changes (an undo, a panel edit). */
  private follow(): void {
    this.attach(this.lastPart ?? this.firstPart());
  }

  private firstPart(): GizmoPart | null {
    const m = this.selectedMuscle();
    return m ? gizmoParts(m)[0] : null;
  }

  private attach(part: GizmoPart | null): void {
    // While the brush is on, a press on the skin paints: the gizmo steps aside.
    const m = this.on && this.handle.getBrush().mode === 'off' ? this.selectedMuscle() : null;
    const valid = m && part && gizmoParts(m).includes(part) ? part : m ? gizmoParts(m)[0] : null;
    this.gizmo.attach(m, valid);
  }

  private selectedMuscle(): Muscle | null {
    return this.selected === null ? null : (this.document.rig.muscles.find((m) => m.name === this.selected) ?? null);
  }

  private toClient(world: Vector3): { x: number; y: number } {
    // The camera's matrices are otherwise brought up to date only when a frame renders.
    this.camera.updateMatrixWorld();
    const p = world.clone().project(this.camera);
    const r = this.canvas.getBoundingClientRect();
    return { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
  }

  /** The rest point of the skin under a client position, in the rig's frame; null off the skin. */
  private restPointAt(clientX: number, clientY: number): Vector3 | null {
    if (!this.skin || !this.restRender) return null;
    const r = this.canvas.getBoundingClientRect();
    this.pointer.set(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1);
    this.camera.updateMatrixWorld();
    this.raycaster.setFromCamera(this.pointer, this.camera);
    const hit = this.raycaster.intersectObject(this.skin, false)[0];
    if (!hit?.face || !hit.barycoord) return null;
    // The same spot of the skin at rest: the hit's barycentric weights over the triangle's rest corners.
    const R = this.restRender;
    const { a, b, c } = hit.face;
    const w = hit.barycoord;
    return new Vector3(
      w.x * R[3 * a] + w.y * R[3 * b] + w.z * R[3 * c],
      w.x * R[3 * a + 1] + w.y * R[3 * b + 1] + w.z * R[3 * c + 1],
      w.x * R[3 * a + 2] + w.y * R[3 * b + 2] + w.z * R[3 * c + 2],
    );
  }

  /** Adds a dab at the rest point under the pointer to the painted muscle's brush (spaced a third of a radius apart). */
  private dab(clientX: number, clientY: number): void {
    const p = this.painting;
    if (!p) return;
    const at = this.restPointAt(clientX, clientY);
    if (!at) return;
    const { mode, radius } = this.handle.getBrush();
    const sphere: BrushSphere = [round(at.x), round(at.y), round(at.z), radius];
    if (p.last && Math.hypot(sphere[0] - p.last[0], sphere[1] - p.last[1], sphere[2] - p.last[2]) < radius / 3) return;
    p.last = sphere;
    const muscle = this.document.rig.muscles.find((m) => m.name === p.name);
    if (!muscle) return;
    const brush = { add: [...(muscle.brush?.add ?? [])], remove: [...(muscle.brush?.remove ?? [])] };
    brush[mode === 'add' ? 'add' : 'remove'].push(sphere);
    try {
      this.document.updateMuscle(p.name, { brush });
    } catch (error) {
      console.warn(`muscle brush: ${(error as Error).message}`);
    }
  }

  private readonly onBrushDown = (event: PointerEvent): void => {
    // Before the gizmo's own handler (this one captures): its handles must be where they are drawn.
    if (this.on) this.gizmo.refresh(this.camera);
    if (!this.on || event.button !== 0 || this.selected === null || this.handle.getBrush().mode === 'off') return;
    if (this.gizmo.hovered || !this.restPointAt(event.clientX, event.clientY)) return;
    this.view.controls.enabled = false;
    this.handle.beginEdit();
    this.painting = { name: this.selected, last: null };
    this.dab(event.clientX, event.clientY);
  };

  private readonly onBrushMove = (event: PointerEvent): void => {
    if (this.painting) this.dab(event.clientX, event.clientY);
  };

  private readonly onBrushUp = (): void => {
    if (!this.painting) return;
    this.painting = null;
    this.view.controls.enabled = true;
    this.handle.endEdit();
  };

  private readonly onPointerDown = (event: PointerEvent): void => {
    if (!this.on || event.button !== 0) return;
    // A brush stroke is not a click either.
    this.down = { x: event.clientX, y: event.clientY, gizmo: this.gizmo.dragging || this.gizmo.hovered || this.painting !== null };
  };

  /** A click (not a drag, not on the gizmo) selects the muscle under it; a click on nothing keeps the selection. */
  private readonly onPointerUp = (event: PointerEvent): void => {
    const down = this.down;
    this.down = null;
    if (!this.on || !down || down.gizmo) return;
    if (Math.hypot(event.clientX - down.x, event.clientY - down.y) > CLICK_SLOP) return;
    const r = this.canvas.getBoundingClientRect();
    this.pointer.set(((event.clientX - r.left) / r.width) * 2 - 1, -((event.clientY - r.top) / r.height) * 2 + 1);
    this.camera.updateMatrixWorld();
    this.raycaster.setFromCamera(this.pointer, this.camera);
    const name = this.muscles.pick(this.raycaster);
    if (name !== null && name !== this.selected) this.handle.selectMuscle(name);
  };

  private readonly onKey = (event: KeyboardEvent): void => {
    if (!this.on || typingInto(event) || event.ctrlKey || event.metaKey || event.altKey) return;
    const key = event.key.toLowerCase();
    if (key === 'escape' && this.selected !== null) this.handle.selectMuscle(null);
    else if (this.selected === null) return;
    else if (key === 'w') this.handle.setGizmoMode('translate');
    else if (key === 'e') this.handle.setGizmoMode('rotate');
    else if (key === 'r') this.handle.setGizmoMode('scale');
  };
}

/** Metres to 0.01 mm, so that saved brushes stay readable. */
function round(x: number): number {
  return Math.round(x * 1e5) / 1e5;
}
