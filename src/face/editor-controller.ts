import { nextMuscleDisplay, shownMuscleNames, type MuscleDisplay } from '../core/rig/muscle-display';
import type { RigDocument } from '../core/rig/rig-document';
import type { Muscle, Rig } from '../core/rig/rig-types';
import { EditorSession, type AutosaveStatus, type BrushOptions, type EditorState, type GizmoMode, type GizmoPart } from './editor-session';
import type { FaceParts } from './face-parts';

/**
 * The muscle editor and the muscle glyphs: which muscles are shown, and the editor's selection, gizmo, preview,
 * mirroring and brush (kept by EditorSession, which this tells listeners about).
 */
export class EditorController {
  /** The editor's state and the rig document it edits. */
  readonly session: EditorSession;
  private display: MuscleDisplay = { all: false, actionUnits: [] };

  constructor(private readonly parts: FaceParts) {
    this.session = new EditorSession(() => parts.expression);
  }

  /**
   * Connects a head's rig document; its changes (from the handle, the panels or the gizmo) are told to listeners as
   * `'rig'`, after the glyphs show them.
   */
  attachRig(document: RigDocument, original: Rig, name: string): void {
    this.session.attachRig(document, original, name, () => {
      if (this.parts.disposed) return;
      this.showMuscles();
      this.parts.emit('rig');
    });
  }

  /** Connects the autosave, whose status `describeEditor` reports and whose writes are told as `'editor'`. */
  attachAutosave(status: () => AutosaveStatus): () => void {
    this.session.attachAutosave(status);
    return () => {
      if (!this.parts.disposed) this.parts.emit('editor');
    };
  }

  /**
   * Shows the rig's muscles over the skin: `all` of them, and/or those of some Action Units (`["AU12", "AU6"]`, ids
   * without a side: both sides are shown; the list replaces the previous one). Either key may be left out to keep it.
   * An unknown key, a non-boolean `all` or an unknown id throws naming it and changes nothing.
   */
  setMuscleDisplay(partial: Partial<MuscleDisplay>): void {
    this.parts.alive();
    this.display = nextMuscleDisplay(this.display, partial);
    this.showMuscles();
    this.parts.emit('muscles');
  }

  /** Which muscles are asked for (a copy): `{ all, actionUnits }`. */
  getMuscleDisplay(): MuscleDisplay {
    this.parts.alive();
    return { all: this.display.all, actionUnits: [...this.display.actionUnits] };
  }

  /** The names of the muscles the scene draws now, in rig order (read-only: what the glyphs show, for tests). */
  describeMuscleDisplay(): string[] {
    this.parts.alive();
    return this.parts.muscles?.shown() ?? [];
  }

  /**
   * Switches the muscle editor on or off: on, every muscle is drawn, a click on one selects it and a gizmo moves,
   * turns or scales the selected muscle's part; off, the display is as `setMuscleDisplay` asked.
   */
  setEditor(on: boolean): void {
    this.parts.alive();
    this.session.setEnabled(on);
    this.showMuscles();
    this.parts.emit('editor');
  }

  /** Whether the editor is on. */
  getEditor(): boolean {
    this.parts.alive();
    return this.session.enabled();
  }

  /** Selects a muscle by name for the gizmo and the Muscle panel, or `null` for none; an unknown name throws. */
  selectMuscle(name: string | null): void {
    this.edit(() => this.session.select(name));
  }

  /** The selected muscle's name, or null. */
  getSelectedMuscle(): string | null {
    this.parts.alive();
    return this.session.selection();
  }

  /** What the gizmo does: `translate`, `rotate` or `scale` (what a part cannot do, it ignores). */
  setGizmoMode(mode: GizmoMode): void {
    this.edit(() => this.session.setGizmoMode(mode));
  }

  /** Attaches the gizmo to a part of the selected muscle (see GizmoPart); a part it does not have throws. */
  setGizmoPart(part: GizmoPart): void {
    this.edit(() => this.session.setGizmoPart(part));
  }

  /**
   * Contracts the selected muscle by at least `value` (0..1) while it is edited, on top of the Action Units (0 ends
   * it); it follows the selection.
   */
  setPreviewContraction(value: number): void {
    this.edit(() => this.session.setPreviewContraction(value));
  }

  /** With `on`, the gizmo's and the Muscle panel's edits also reflect the muscle onto its left/right twin. */
  setMirrorEdits(on: boolean): void {
    this.edit(() => this.session.setMirrorEdits(on));
  }

  /** Whether edits are mirrored onto the twin. */
  getMirrorEdits(): boolean {
    this.parts.alive();
    return this.session.mirrorEdits();
  }

  /**
   * Sets the vertex brush (see BrushOptions; `radius` from 0.001 to 0.05 m): while it is on, dragging over the skin
   * paints the selected muscle's influence instead of turning the view. Bad input throws and changes nothing.
   */
  setBrush(partial: Partial<BrushOptions>): void {
    this.edit(() => this.session.setBrush(partial));
  }

  /** The vertex brush as last set. */
  getBrush(): BrushOptions {
    this.parts.alive();
    return this.session.getBrush();
  }

  /** The editor's state and where its gizmo is on the page (read-only: for tests and tools). */
  describeEditor(): EditorState {
    this.parts.alive();
    return this.session.describe();
  }

  /** Whether the rig differs from the one the face was made with (its `rig` option, or the package's). */
  isRigEdited(): boolean {
    this.parts.alive();
    return this.session.isRigEdited();
  }

  /** Brings back the rig the face was made with (one undoable step). */
  revertRig(): void {
    this.parts.alive();
    this.session.revertRig();
  }

  /** Where a shown muscle's glyph can be clicked on the page, in client pixels, or null (read-only: for tests). */
  locateMuscle(name: string): {
    /** Client pixels from the viewport's left edge, as `MouseEvent.clientX` counts them. */
    x: number;
    /** Client pixels from the viewport's top edge, as `MouseEvent.clientY` counts them. */
    y: number;
  } | null {
    this.parts.alive();
    return this.session.locateMuscle(name);
  }

  /**
   * Adds a new muscle of `type` (`linear`, `sphincter`, `lid`, `jaw`) where the view looks at the skin, linked to no
   * Action Unit, and selects it; returns its name (`new-sphincter`, `new-sphincter-2`, ... with `-l` / `-r` off the
   * midline).
   */
  createMuscle(type: Muscle['type']): string {
    this.parts.alive();
    const name = this.session.createMuscle(type);
    this.parts.emit('editor');
    return name;
  }

  /** Renames a muscle; its links and the selection follow. */
  renameMuscle(name: string, newName: string): void {
    this.parts.alive();
    const wasSelected = this.session.selection() === name;
    this.session.renameMuscle(name, newName);
    if (wasSelected) this.parts.emit('editor');
  }

  /** Runs a change of the editor's state and tells listeners (`'editor'`) once it is made. */
  private edit(change: () => void): void {
    this.parts.alive();
    change();
    this.parts.emit('editor');
  }

  /** Makes the glyphs show the muscles the display asks for (none until the glyphs and the expression are there). */
  showMuscles(): void {
    const muscles = this.parts.muscles;
    if (!muscles) return;
    const d = this.display;
    if (d.all || this.session.enabled()) muscles.setVisible('all');
    else if (!this.parts.expression || d.actionUnits.length === 0) muscles.setVisible('none');
    else muscles.setVisible(new Set(shownMuscleNames(this.parts.expression.rig, d)));
  }
}

/** The handle's methods that EditorController answers. */
export const EDITOR_METHODS = [
  'setMuscleDisplay',
  'getMuscleDisplay',
  'describeMuscleDisplay',
  'setEditor',
  'getEditor',
  'selectMuscle',
  'getSelectedMuscle',
  'setGizmoMode',
  'setGizmoPart',
  'setPreviewContraction',
  'setMirrorEdits',
  'getMirrorEdits',
  'setBrush',
  'getBrush',
  'describeEditor',
  'isRigEdited',
  'revertRig',
  'locateMuscle',
  'createMuscle',
  'renameMuscle',
] as const;
