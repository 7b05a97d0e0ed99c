import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import { typingInto } from '../embed/face-editor';
import type { FaceChange, FaceHandle, GizmoMode } from '../embed/face-handle';
import { MusclePanel } from './muscle-panel';

/** The keys, as the panel's hint shows them. */
export const EDITOR_HINT =
  'E: editor on/off (with no muscle selected) · click a muscle to select it · W move, E turn, R scale · Esc: deselect · Ctrl+Z undo, Ctrl+Shift+Z redo';

/**
 * The Editor folder: the muscle editor's switch (also the key E, see the hint), the gizmo's mode, mirrored edits,
 * undo and redo (buttons and Ctrl+Z / Ctrl+Shift+Z while the editor is on), and the selected muscle's Muscle folder.
 */
export class EditorPanel {
  readonly folder: GUI;
  readonly muscle: MusclePanel;
  private readonly state: { editor: boolean; mode: GizmoMode; mirror: boolean; undo: () => void; redo: () => void };
  private readonly controllers: Controller[] = [];
  private readonly unsubscribe: () => void;
  private readonly undoButton: Controller;
  private readonly redoButton: Controller;

  constructor(parent: GUI, private readonly face: FaceHandle) {
    const editor = face.describeEditor();
    this.state = {
      editor: editor.on,
      mode: editor.mode,
      mirror: editor.mirror,
      undo: () => face.undo(),
      redo: () => face.redo(),
    };
    this.folder = parent.addFolder('Editor');
    const s = this.state;
    this.add(this.folder.add(s, 'editor').name('muscle editor').onChange((v: boolean) => face.setEditor(v)), 'editor');
    const hint = document.createElement('div');
    hint.dataset.control = 'editor-hint';
    hint.textContent = EDITOR_HINT;
    Object.assign(hint.style, { padding: '2px 8px 6px', opacity: '0.75', fontSize: '11px', lineHeight: '1.35' });
    this.folder.$children.append(hint);
    this.add(this.folder.add(s, 'mode', ['translate', 'rotate', 'scale']).name('gizmo').onChange((v: GizmoMode) => face.setGizmoMode(v)), 'gizmo-mode');
    this.add(this.folder.add(s, 'mirror').name('mirror edits').onChange((v: boolean) => face.setMirrorEdits(v)), 'mirror-edits');
    this.undoButton = this.folder.add(s, 'undo');
    this.add(this.undoButton, 'undo');
    this.redoButton = this.folder.add(s, 'redo');
    this.add(this.redoButton, 'redo');
    this.muscle = new MusclePanel(this.folder, face);
    this.refresh();
    this.unsubscribe = face.onChange((change) => this.changed(change));
    window.addEventListener('keydown', this.onKey);
  }

  dispose(): void {
    window.removeEventListener('keydown', this.onKey);
    this.unsubscribe();
    this.muscle.dispose();
    this.folder.destroy();
  }

  private changed(change: FaceChange): void {
    if (change === 'editor' || change === 'rig') this.refresh();
  }

  private refresh(): void {
    const e = this.face.describeEditor();
    // Switched on: the folder opens, so the selected muscle's fields are in view.
    if (e.on && !this.state.editor) this.folder.open();
    Object.assign(this.state, { editor: e.on, mode: e.mode, mirror: e.mirror });
    this.undoButton.name(`undo (${e.history.undo})`).enable(e.history.undo > 0);
    this.redoButton.name(`redo (${e.history.redo})`).enable(e.history.redo > 0);
    for (const c of this.controllers) c.updateDisplay();
  }

  private add(controller: Controller, name: string): void {
    controller.domElement.dataset.control = name;
    this.controllers.push(controller);
  }

  /**
   * E switches the editor on, and off again while no muscle is selected (with one selected, E turns the gizmo to
   * rotate); Ctrl+Z and Ctrl+Shift+Z (or Ctrl+Y) undo and redo while the editor is on. Keys typed into a field are left alone.
   */
  private readonly onKey = (event: KeyboardEvent): void => {
    if (typingInto(event) || event.altKey) return;
    const key = event.key.toLowerCase();
    const on = this.face.getEditor();
    if ((event.ctrlKey || event.metaKey) && on && (key === 'z' || key === 'y')) {
      event.preventDefault();
      if (key === 'y' || event.shiftKey) this.face.redo();
      else this.face.undo();
      return;
    }
    if (event.ctrlKey || event.metaKey || key !== 'e') return;
    if (!on) this.face.setEditor(true);
    else if (this.face.getSelectedMuscle() === null) this.face.setEditor(false);
  };
}
