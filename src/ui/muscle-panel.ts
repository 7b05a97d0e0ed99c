import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import { ACTION_UNITS } from '../core/expression/facs';
import { type FieldRange, MUSCLE_RANGES } from '../core/rig/muscle-ranges';
import type { Muscle } from '../core/rig/rig-types';
import { gizmoParts, type FaceChange, type FaceHandle } from '../face/face-handle';
import { BRUSH_RULES } from '../face/editor-session';

/**
 * Number fields by muscle type, in the panel's order, with their labels; their bounds and steps are the rig's
 * (MUSCLE_RANGES). Vectors get one field per axis.
 */
const SCALARS: Record<Muscle['type'], [string, string][]> = {
  linear: [
    ['strength', 'strength'],
    ['normalWeight', 'normal weight'],
    ['angle', 'cone angle °'],
    ['falloffStart', 'falloff start'],
    ['falloffEnd', 'falloff end'],
  ],
  sphincter: [
    ['strength', 'strength'],
    ['normalWeight', 'normal weight'],
  ],
  lid: [
    ['maxAngle', 'max angle °'],
    ['innerFraction', 'inner fraction'],
  ],
  jaw: [
    ['maxAngle', 'max angle °'],
    ['curve', 'curve'],
    ['fade', 'fade (m)'],
  ],
};

const VECTORS: Record<Muscle['type'], [string, string][]> = {
  linear: [
    ['insertion', 'insertion'],
    ['origin', 'bone end'],
  ],
  sphincter: [
    ['center', 'centre'],
    ['rotation', 'rotation °'],
    ['radii', 'radii'],
    ['innerRadii', 'inner radii'],
    ['scale', 'scale'],
  ],
  lid: [
    ['center', 'centre'],
    ['rotation', 'rotation °'],
    ['radii', 'radii'],
  ],
  jaw: [
    ['center', 'centre'],
    ['rotation', 'rotation °'],
    ['size', 'size'],
  ],
};

/** The table's entry for field `key` of muscle type `type`. */
function rangeOf(type: Muscle['type'], key: string): FieldRange {
  return (MUSCLE_RANGES[type] as Record<string, FieldRange>)[key];
}

const NO_UNIT = '(none)';

/**
 * The Muscle folder: the selected muscle's fields (name, type, side, Action Unit and weight, the gizmo's part, a
 * preview contraction, then its numbers). A field applies as soon as it changes; a slider's whole drag is one undo
 * step; a value the rig refuses is shown under the fields and the field goes back. Rebuilt when the selection
 * changes, refreshed when the rig does.
 */
export class MusclePanel {
  readonly folder: GUI;
  private controllers: Controller[] = [];
  private state: Record<string, unknown> = {};
  private shown: string | null = null;
  private editing = false;
  private readonly message: HTMLDivElement;
  private readonly unsubscribe: () => void;

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
  ) {
    this.folder = parent.addFolder('Muscle');
    this.folder.domElement.dataset.control = 'muscle-folder';
    this.message = document.createElement('div');
    this.message.className = 'softface-editor-message';
    this.message.dataset.control = 'muscle-message';
    Object.assign(this.message.style, { padding: '4px 8px', color: '#ff8a80', whiteSpace: 'pre-wrap', fontSize: '11px' });
    this.folder.domElement.append(this.message);
    this.unsubscribe = face.onChange((change) => this.changed(change));
    this.rebuild();
  }

  dispose(): void {
    this.unsubscribe();
    if (this.editing) this.face.endEdit();
    this.folder.destroy();
  }

  private changed(change: FaceChange): void {
    if (change !== 'rig' && change !== 'editor') return;
    const selected = this.face.getSelectedMuscle();
    const rig = this.face.getRig();
    const muscle = rig.muscles.find((m) => m.name === selected);
    // A new selection, or a muscle whose type changed, needs other fields; otherwise the values are refreshed.
    if (selected !== this.shown || (muscle && muscle.type !== this.state.type)) this.rebuild();
    else if (muscle) {
      // A field being typed into keeps what is typed: a change elsewhere (the autosave's status a moment after an
      // edit) must not put the old value back under the user's cursor, nor into what Enter then applies.
      const typing = this.controllers.find((c) => c.domElement.contains(document.activeElement));
      const typed: unknown = typing?.getValue();
      this.fill(muscle);
      if (typing) (typing.object as Record<string, unknown>)[typing.property] = typed;
      for (const c of this.controllers) if (c !== typing) c.updateDisplay();
    }
  }

  /** The fields of the selected muscle, or a hidden folder when none is. */
  private rebuild(): void {
    for (const c of this.controllers) c.destroy();
    this.controllers = [];
    const name = this.face.getSelectedMuscle();
    this.shown = name;
    this.message.textContent = '';
    const muscle = name === null ? undefined : this.face.getRig().muscles.find((m) => m.name === name);
    this.folder.show(!!muscle);
    if (!muscle) return;
    this.state = {};
    this.fill(muscle);
    const s = this.state;
    const f = this.folder;
    this.add(
      f.add(s, 'name').onFinishChange((v: string) => this.apply(() => this.face.renameMuscle(this.shown!, v))),
      'muscle-name',
    );
    this.add(f.add(s, 'type').disable(), 'muscle-type');
    this.add(
      f
        .add(s, 'side', ['left', 'right', 'mid'])
        .onChange((v: string) => this.apply(() => this.face.updateMuscle(this.shown!, { side: v } as Partial<Muscle>))),
      'muscle-side',
    );
    const units = [NO_UNIT, ...ACTION_UNITS.map((a) => a.id)];
    this.add(
      f
        .add(s, 'actionUnit', units)
        .name('Action Unit')
        .onChange(() => this.assign()),
      'muscle-action-unit',
    );
    this.add(
      f
        .add(s, 'weight', 0.05, 2, 0.05)
        .name('AU weight')
        .onFinishChange(() => this.assign()),
      'muscle-weight',
    );
    this.add(
      f
        .add(s, 'part', gizmoParts(muscle))
        .name('gizmo on')
        .onChange((v: string) => this.face.setGizmoPart(v as never)),
      'muscle-part',
    );
    s.duplicate = () => this.apply(() => this.face.selectMuscle(this.face.duplicateMuscle(this.shown!)));
    s.remove = () => this.apply(() => this.face.removeMuscle(this.shown!));
    s.mirror = () => this.apply(() => this.face.mirrorMuscle(this.shown!));
    this.add(f.add(s, 'duplicate'), 'muscle-duplicate');
    this.add(f.add(s, 'remove').name('delete'), 'muscle-delete');
    if (/-[lr]$/.test(muscle.name)) this.add(f.add(s, 'mirror').name('mirror to twin'), 'muscle-mirror');
    s.clearBrush = () => this.apply(() => this.face.updateMuscle(this.shown!, { brush: undefined }));
    this.add(
      f
        .add(s, 'brushMode', BRUSH_RULES.choices.mode)
        .name('vertex brush')
        .onChange((v: 'off' | 'add' | 'remove') => this.face.setBrush({ mode: v })),
      'brush-mode',
    );
    this.add(
      f
        .add(s, 'brushRadius', BRUSH_RULES.ranges.radius[0] * 1000, BRUSH_RULES.ranges.radius[1] * 1000, 0.5)
        .name('brush radius mm')
        .onChange((v: number) => this.face.setBrush({ radius: v / 1000 })),
      'brush-radius',
    );
    this.add(f.add(s, 'clearBrush').name('clear brush'), 'brush-clear');
    this.add(
      f
        .add(s, 'preview', 0, 1, 0.01)
        .name('preview contraction')
        .onChange((v: number) => this.face.setPreviewContraction(v)),
      'muscle-preview',
    );
    for (const [key, label] of SCALARS[muscle.type]) {
      if (!(key in s)) continue;
      const { range, slider = range, step } = rangeOf(muscle.type, key);
      this.add(
        f
          .add(s, key, slider[0], slider[1], step)
          .name(label)
          .onChange(() => this.drag(key))
          .onFinishChange(() => this.finish()),
        `muscle-${key}`,
      );
    }
    for (const [key, label] of VECTORS[muscle.type]) {
      const { step } = rangeOf(muscle.type, key);
      ['x', 'y', 'z'].forEach((axis) => {
        const field = `${key}.${axis}`;
        this.add(
          f
            .add(s, field)
            .step(step)
            .name(`${label} ${axis}`)
            .onChange(() => this.drag(key))
            .onFinishChange(() => this.finish()),
          `muscle-${key}-${axis}`,
        );
      });
    }
    // The message stays last, under the fields.
    f.$children.after(this.message);
  }

  /** Copies the muscle into the panel's state: scalars by key, vectors as `key.x`, `key.y`, `key.z`. */
  private fill(muscle: Muscle): void {
    const s = this.state;
    const editor = this.face.describeEditor();
    const link = this.face
      .getRig()
      .actionUnits.flatMap((a) => a.muscles.filter((l) => l.muscle === muscle.name).map((l) => ({ id: a.id, weight: l.weight })))[0];
    Object.assign(s, {
      name: muscle.name,
      type: muscle.type,
      side: muscle.side,
      actionUnit: link?.id ?? NO_UNIT,
      weight: link?.weight ?? 1,
    });
    s.part = editor.part ?? gizmoParts(muscle)[0];
    s.brushMode = editor.brush.mode;
    s.brushRadius = editor.brush.radius * 1000;
    s.preview = editor.preview;
    for (const [key, value] of Object.entries(muscle)) {
      if (typeof value === 'number') s[key] = value;
      else if (Array.isArray(value)) ['x', 'y', 'z'].forEach((axis, i) => (s[`${key}.${axis}`] = value[i]));
    }
  }

  /** Applies the field `key` from the panel's state; the first change of a drag opens its undo step. */
  private drag(key: string): void {
    if (!this.editing) {
      this.face.beginEdit();
      this.editing = true;
    }
    const s = this.state;
    const value = `${key}.x` in s ? [s[`${key}.x`], s[`${key}.y`], s[`${key}.z`]] : s[key];
    this.apply(() => this.face.updateMuscle(this.shown!, { [key]: value } as Partial<Muscle>, { mirror: this.face.getMirrorEdits() }));
  }

  private finish(): void {
    if (!this.editing) return;
    this.editing = false;
    this.face.endEdit();
  }

  private assign(): void {
    const unit = this.state.actionUnit as string;
    this.apply(() => this.face.assignMuscle(this.shown!, unit === NO_UNIT ? null : unit, this.state.weight as number));
  }

  /** Runs an edit; a refusal is shown under the fields and the fields show the rig as it is. */
  private apply(edit: () => void): void {
    try {
      edit();
      this.message.textContent = '';
    } catch (error) {
      this.message.textContent = (error as Error).message;
      const muscle = this.face.getRig().muscles.find((m) => m.name === this.shown);
      if (muscle) this.fill(muscle);
      for (const c of this.controllers) c.updateDisplay();
    }
  }

  private add(controller: Controller, name: string): void {
    controller.domElement.dataset.control = name;
    this.controllers.push(controller);
  }
}
