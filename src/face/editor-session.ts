import { clamp01 } from '../core/math3';
import { checkBoolean, checkChoice, checkNumber, checkOptions, type OptionRules } from '../core/check';
import { newMuscle, type RigDocument } from '../core/rig/rig-document';
import type { Muscle, Rig } from '../core/rig/rig-types';
import type { GizmoMode, GizmoPart } from '../render/muscle-gizmo';
import type { FaceExpression } from './face-expression';

/**
 * What the gizmo does (`translate`, `rotate`, `scale`), and which part of the selected muscle it holds: a linear
 * muscle's `insertion` or `origin` (its bone end), a sphincter's or lid's `ellipsoid`, the jaw's `box` or `hinge`.
 */
export type { GizmoMode, GizmoPart };

/**
 * The vertex brush: off, or painting skin into (`add`) or out of (`remove`) the selected muscle's influence with
 * spheres of `radius` metres, stored in the rig in rest space.
 */
export interface BrushOptions {
  /**
   * What a press or drag on the skin does while the editor is on and a muscle is selected: nothing (`off`, the
   * default; the gizmo shows), or dabs spheres that paint the skin into (`add`) or out of (`remove`) its influence.
   */
  mode: 'off' | 'add' | 'remove';
  /** Radius of each dab's sphere, in metres (0.001..0.05; default 0.006): full hold in its inner half. */
  radius: number;
}

const BRUSH_DEFAULTS: Readonly<BrushOptions> = Object.freeze({ mode: 'off', radius: 0.006 });

/** The brush's modes and its radius range in metres (the Muscle panel's slider shows it in mm). */
export const BRUSH_RULES = Object.freeze({
  choices: { mode: ['off', 'add', 'remove'] as const },
  ranges: { radius: [0.001, 0.05] as const },
}) satisfies OptionRules<BrushOptions>;

const GIZMO_MODES: readonly GizmoMode[] = ['translate', 'rotate', 'scale'];

/** The editor's state, as `describeEditor` reports it (read-only). */
export interface EditorState {
  /** Whether the muscle editor is on (`setEditor`). */
  on: boolean;
  /** The selected muscle's name, or null when none is. */
  selected: string | null;
  /** What the gizmo does to the part it holds: `translate`, `rotate` or `scale` (a point only moves). */
  mode: GizmoMode;
  /** The part of the selected muscle the gizmo holds; null when the editor is off or nothing is held. */
  part: GizmoPart | null;
  /** Contraction of the selected muscle while it is edited, 0..1 (on top of the Action Units). */
  preview: number;
  /** Where the gizmo is on the page (client pixels), if it shows. */
  gizmo: {
    /** Client pixels from the viewport's left edge, as `MouseEvent.clientX` counts them. */
    x: number;
    /** Client pixels from the viewport's top edge, as `MouseEvent.clientY` counts them. */
    y: number;
  } | null;
  /** Undo and redo steps available. */
  history: {
    /** Rig edits that can be undone now. */
    undo: number;
    /** Undone rig edits that can be redone now. */
    redo: number;
  };
  /** Whether edits are mirrored onto the twin. */
  mirror: boolean;
  /** Whether the rig differs from the one the face was made with. */
  edited: boolean;
  /** The autosave: `off`, or whether the edited rig is stored (`clean`: nothing to store). */
  autosave: 'off' | 'clean' | 'pending' | 'saved' | 'failed';
  /** The rig's name, for its exported file (`<name>.rig.json`). */
  rigName: string;
  /** The vertex brush's mode and radius, as `getBrush` gives them. */
  brush: BrushOptions;
}

/** The editor's view side the handle drives (FaceEditor): gizmo, picking, highlight. */
export interface FaceEditorView {
  setEnabled(on: boolean): void;
  select(name: string | null): void;
  setMode(mode: GizmoMode): void;
  setPart(part: GizmoPart | null): void;
  part(): GizmoPart | null;
  /** Where the gizmo is on the page, in client pixels; null when it does not show. */
  gizmoPoint(): { x: number; y: number } | null;
  /** Where a muscle's glyph can be clicked (the middle of a linear muscle's rod, an ellipsoid's or box's centre). */
  musclePoint(name: string): { x: number; y: number } | null;
  /** The brush was switched on or off: the gizmo makes way for it. */
  brushChanged(): void;
  /** The skin point at the middle of the view (or the orbit centre if the skin is not there), in the rig's frame. */
  frontPoint(): [number, number, number];
}

/** What the editor's autosave reports (see EditorState.autosave). */
export type AutosaveStatus = 'clean' | 'pending' | 'saved' | 'failed';

/** The parts of a muscle the gizmo can hold, the first being where it goes on selection. */
export function gizmoParts(muscle: Muscle): GizmoPart[] {
  switch (muscle.type) {
    case 'linear':
      return ['insertion', 'origin'];
    case 'jaw':
      return ['box', 'hinge'];
    default:
      return ['ellipsoid'];
  }
}

/**
 * The muscle editor's state behind the face's handle: on or off, the selected muscle, the gizmo's mode and part, the
 * preview contraction, mirrored edits and the vertex brush, with the rig document it edits and the view side it
 * drives (gizmo, picking). The handle checks that the face is alive and tells listeners; this keeps the state whole:
 * a bad value throws, naming the method, and changes nothing.
 */
export class EditorSession {
  private on = false;
  private selected: string | null = null;
  private mode: GizmoMode = 'translate';
  private preview = 0;
  private mirror = false;
  private brush: BrushOptions = { ...BRUSH_DEFAULTS };
  private view: FaceEditorView | undefined;
  private doc: RigDocument | undefined;
  private original: Rig | undefined;
  private fileName = 'rig';
  private autosave: (() => AutosaveStatus) | undefined;

  /** `expression` gives the face's expression once it runs (the preview contraction goes there). */
  constructor(private readonly expression: () => FaceExpression | undefined) {}

  /**
   * Takes the rig document to edit, the rig the face was made with and the rig's file name; `changed` is called after
   * each of the document's changes, once the selection and preview have followed it.
   */
  attachRig(document: RigDocument, original: Rig, name: string, changed: () => void): void {
    this.doc = document;
    this.original = original;
    this.fileName = name;
    document.onChange((_, rig) => {
      // A muscle that is gone (removed, renamed, undone) cannot stay selected.
      if (this.selected !== null && !rig.muscles.some((m) => m.name === this.selected)) this.setSelection(null);
      else this.applyPreview();
      changed();
    });
  }

  /** Takes the view side, and shows it the state so far. */
  attachView(view: FaceEditorView): void {
    this.view = view;
    view.setMode(this.mode);
    view.setEnabled(this.on);
    view.select(this.selected);
  }

  attachAutosave(status: () => AutosaveStatus): void {
    this.autosave = status;
  }

  /** The rig document; before the face runs, an error saying so. */
  document(): RigDocument {
    if (!this.doc) throw new Error('the face is not ready yet: await face.ready first');
    return this.doc;
  }

  setEnabled(on: boolean): void {
    checkBoolean('setEditor', '', on);
    this.document();
    this.on = on;
    this.view?.setEnabled(on);
  }

  enabled(): boolean {
    return this.on;
  }

  select(name: string | null): void {
    const doc = this.document();
    if (name !== null) doc.indexOf(name, 'selectMuscle');
    this.setSelection(name);
  }

  selection(): string | null {
    return this.selected;
  }

  setGizmoMode(mode: GizmoMode): void {
    checkChoice('setGizmoMode', '', mode, GIZMO_MODES);
    this.mode = mode;
    this.view?.setMode(mode);
  }

  setGizmoPart(part: GizmoPart): void {
    const doc = this.document();
    if (this.selected === null) throw new Error('setGizmoPart: no muscle is selected');
    const muscle = doc.muscle(this.selected);
    const parts = gizmoParts(muscle);
    checkChoice('setGizmoPart', '', part, parts);
    this.view?.setPart(part);
  }

  setPreviewContraction(value: number): void {
    checkNumber('setPreviewContraction', '', value);
    this.document();
    this.preview = clamp01(value);
    this.applyPreview();
  }

  setMirrorEdits(on: boolean): void {
    checkBoolean('setMirrorEdits', '', on);
    this.mirror = on;
  }

  mirrorEdits(): boolean {
    return this.mirror;
  }

  setBrush(partial: Partial<BrushOptions>): void {
    this.brush = { ...this.brush, ...checkOptions<BrushOptions>('setBrush', partial, BRUSH_DEFAULTS, BRUSH_RULES) };
    this.view?.brushChanged();
  }

  getBrush(): BrushOptions {
    return { ...this.brush };
  }

  describe(): EditorState {
    const doc = this.document();
    return {
      on: this.on,
      selected: this.selected,
      mode: this.mode,
      part: this.view?.part() ?? null,
      preview: this.preview,
      gizmo: this.view?.gizmoPoint() ?? null,
      history: doc.historySizes(),
      mirror: this.mirror,
      edited: this.isRigEdited(),
      autosave: this.autosave?.() ?? 'off',
      rigName: this.fileName,
      brush: { ...this.brush },
    };
  }

  isRigEdited(): boolean {
    return JSON.stringify(this.document().rig) !== JSON.stringify(this.original);
  }

  revertRig(): void {
    const doc = this.document();
    if (this.original) doc.replace(this.original, 'revertRig');
  }

  locateMuscle(name: string): { x: number; y: number } | null {
    this.document().indexOf(name, 'locateMuscle');
    return this.view?.musclePoint(name) ?? null;
  }

  /** Adds a new muscle of `type` where the view looks at the skin and selects it; returns its name. */
  createMuscle(type: Muscle['type']): string {
    const doc = this.document();
    const at = this.view?.frontPoint() ?? [0, 0.7, 0.1];
    const suffix = at[0] > 0.005 ? '-l' : at[0] < -0.005 ? '-r' : '';
    const taken = new Set(doc.rig.muscles.map((m) => m.name));
    let name = `new-${type}${suffix}`;
    for (let k = 2; taken.has(name); k++) name = `new-${type}-${k}${suffix}`;
    doc.addMuscle(newMuscle(type, name, at));
    this.select(name);
    return name;
  }

  /** Renames a muscle; the selection follows. */
  renameMuscle(name: string, newName: string): void {
    const wasSelected = this.selected === name;
    this.document().renameMuscle(name, newName);
    if (wasSelected) this.select(newName);
  }

  /** Gives the preview contraction to the selected muscle (or none). */
  applyPreview(): void {
    const expression = this.expression();
    if (!expression || !this.doc) return;
    const index = this.selected === null ? -1 : this.doc.rig.muscles.findIndex((m) => m.name === this.selected);
    expression.setPreview(index >= 0 && this.preview > 0 ? index : null, this.preview);
  }

  private setSelection(name: string | null): void {
    this.selected = name;
    this.view?.select(name);
    this.applyPreview();
  }
}
