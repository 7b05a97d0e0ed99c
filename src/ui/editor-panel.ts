import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import { typingInto } from '../face/face-editor';
import type { EditorState, FaceChange, FaceHandle, GizmoMode } from '../face/face-handle';
import { downloadBlob } from './download';
import { FileImport } from './file-import';
import { isHeadDrop } from './head-panel';
import { MusclePanel } from './muscle-panel';
import { note } from './note';

/** The keys, as the panel's hint shows them. */
const EDITOR_HINT =
  'E: editor on/off (with no muscle selected) · click a muscle to select it ' +
  '· W move, E turn, R scale · Esc: deselect · Ctrl+Z undo, Ctrl+Shift+Z redo';

/** What the rig status line says about an edited rig, by autosave status. */
const STATUS: Record<EditorState['autosave'], string> = {
  off: 'edited rig (not kept on reload: export it)',
  clean: 'edited rig',
  pending: 'edited rig · saving…',
  saved: 'edited rig · saved in this browser',
  failed: 'edited rig · could not be saved: export it',
};

/**
 * The Editor folder: the muscle editor's switch (also the key E, see the hint), the gizmo's mode, mirrored edits,
 * undo and redo (buttons and Ctrl+Z / Ctrl+Shift+Z while the editor is on), the rig's status with "revert to
 * default", export and import of rig files (also by dropping a file on the face), and the selected muscle's Muscle
 * folder. A refused import shows the schema's message here and changes nothing.
 */
export class EditorPanel {
  readonly folder: GUI;
  readonly muscle: MusclePanel;
  private readonly state: {
    editor: boolean;
    mode: GizmoMode;
    mirror: boolean;
    undo: () => void;
    redo: () => void;
    revert: () => void;
    exportRig: () => void;
    importRig: () => void;
    newType: 'linear' | 'sphincter' | 'lid' | 'jaw';
    add: () => void;
    mirrorLeft: () => void;
    mirrorRight: () => void;
  };
  private readonly controllers: Controller[] = [];
  private readonly unsubscribe: () => void;
  private readonly undoButton: Controller;
  private readonly redoButton: Controller;
  private readonly revertButton: Controller;
  private readonly status: HTMLDivElement;
  /** Rig files picked or dropped, and the message line. */
  private readonly files: FileImport;

  /** `dropTarget` takes rig files dropped on it (the face's element). */
  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
    dropTarget?: HTMLElement,
  ) {
    const editor = face.describeEditor();
    this.state = {
      editor: editor.on,
      mode: editor.mode,
      mirror: editor.mirror,
      undo: () => face.undo(),
      redo: () => face.redo(),
      revert: () => this.files.attempt(() => face.revertRig()),
      exportRig: () => this.exportRig(),
      importRig: () => this.files.pick(),
      newType: 'linear',
      add: () => this.files.attempt(() => face.createMuscle(this.state.newType)),
      mirrorLeft: () => this.files.attempt(() => face.mirrorSide('left')),
      mirrorRight: () => this.files.attempt(() => face.mirrorSide('right')),
    };
    this.folder = parent.addFolder('Editor');
    const s = this.state;
    this.add(
      this.folder
        .add(s, 'editor')
        .name('muscle editor')
        .onChange((v: boolean) => face.setEditor(v)),
      'editor',
    );
    const hint = note('editor-hint', { opacity: '0.75' });
    hint.textContent = EDITOR_HINT;
    this.folder.$children.append(hint);
    this.add(
      this.folder
        .add(s, 'mode', ['translate', 'rotate', 'scale'])
        .name('gizmo')
        .onChange((v: GizmoMode) => face.setGizmoMode(v)),
      'gizmo-mode',
    );
    this.add(
      this.folder
        .add(s, 'mirror')
        .name('mirror edits')
        .onChange((v: boolean) => face.setMirrorEdits(v)),
      'mirror-edits',
    );
    this.add(this.folder.add(s, 'newType', ['linear', 'sphincter', 'lid', 'jaw']).name('new muscle type'), 'new-type');
    this.add(this.folder.add(s, 'add').name('add muscle (in front of the view)'), 'add-muscle');
    this.add(this.folder.add(s, 'mirrorLeft').name('mirror left side → right'), 'mirror-left');
    this.add(this.folder.add(s, 'mirrorRight').name('mirror right side → left'), 'mirror-right');
    this.undoButton = this.folder.add(s, 'undo');
    this.add(this.undoButton, 'undo');
    this.redoButton = this.folder.add(s, 'redo');
    this.add(this.redoButton, 'redo');
    this.status = note('rig-status', { opacity: '0.85' });
    this.folder.$children.append(this.status);
    this.revertButton = this.folder.add(s, 'revert').name('revert to default');
    this.add(this.revertButton, 'revert-rig');
    this.add(this.folder.add(s, 'exportRig').name('export rig'), 'export-rig');
    this.add(this.folder.add(s, 'importRig').name('import rig (or drop a .json file)'), 'import-rig');
    // A head (.glb, .gltf, .obj) dropped on the face is the Head folder's to load.
    this.files = new FileImport(this.folder, 'import-file', 'editor-message', { color: '#ff8a80' })
      .accept('.json,application/json')
      .onText(
        (text, file) => face.setRig(text, file.name),
        (file) => `imported ${file.name}`,
      )
      .dropOn(dropTarget, (files) => files.length > 0 && !isHeadDrop(files));
    this.muscle = new MusclePanel(this.folder, face);
    this.refresh();
    this.unsubscribe = face.onChange((change) => this.changed(change));
    window.addEventListener('keydown', this.onKey);
  }

  dispose(): void {
    window.removeEventListener('keydown', this.onKey);
    this.files.dispose();
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
    this.status.textContent = e.edited ? STATUS[e.autosave] : `${e.rigName} rig`;
    this.revertButton.show(e.edited);
    for (const c of this.controllers) c.updateDisplay();
  }

  /** Downloads the rig as `<name>.rig.json`. */
  private exportRig(): void {
    const e = this.face.describeEditor();
    downloadBlob(new Blob([this.face.exportRig()], { type: 'application/json' }), `${e.rigName}.rig.json`);
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
