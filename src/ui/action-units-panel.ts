import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import { gradeOf, type Grade } from '../core/expression/facs';
import { Throttle } from './throttle';
import type { FaceChange, FaceHandle } from '../face/face-handle';
import { note } from './note';

/** One slider of the panel: an Action Unit side (`AU12L`) or a midline unit (`AU17`). */
interface SideSlider {
  id: string;
  /** Its label without the grade. */
  label: string;
  controller: Controller;
  /** The grade its label shows (none before the first), so the label is rebuilt only when the grade changes. */
  grade: Grade | undefined;
}

/**
 * The Action Units folder: a FACS code field (the expression as coders write it, `1+2+5B+26`: typed in, it sets the
 * expression; it follows the sliders and presets), then a folder per unit titled with its number and name, a 0..1
 * slider per side whose label shows the FACS grade (A trace .. E maximum), for bilateral units a link checkbox (on by
 * default) that makes either side's slider drive both, and a "show muscles" checkbox that draws the unit's muscles
 * over the skin.
 */
export class ActionUnitsPanel {
  readonly folder: GUI;
  /** The slider values by side id, which the controllers read and write. */
  private readonly values: Record<string, number>;
  /** Link state by Action Unit id (bilateral units only). */
  private readonly links: Record<string, boolean> = {};
  private readonly sliders: SideSlider[] = [];
  /** Whether each unit's muscles are shown, by Action Unit id, as the handle's muscle display says. */
  private readonly showMuscles: Record<string, boolean> = {};
  private readonly muscleControllers: Controller[] = [];
  /** The FACS code field's value. */
  private readonly code: { facs: string };
  private readonly codeController: Controller;
  /** Why the code typed last was refused, under the field; empty once one is taken. */
  private readonly codeMessage: HTMLDivElement;
  private readonly unsubscribe: () => void;
  /** Redraws after expression changes, a few times a second while a timeline plays (each redraw reads the face). */
  private readonly refresh = new Throttle(
    () => this.showExpression(),
    () => this.face.timelineState().playing,
  );

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
  ) {
    this.folder = parent.addFolder('Action Units');
    this.values = face.getActionUnits();
    this.code = { facs: face.getFACS() };
    this.codeController = this.folder
      .add(this.code, 'facs')
      .name('FACS code')
      .onFinishChange((code: string) => this.setCode(code));
    this.codeController.domElement.dataset.control = 'facs';
    this.codeMessage = note('facs-message', { color: '#ff8a80' });
    this.codeController.domElement.after(this.codeMessage);
    for (const au of face.listActionUnits()) {
      const unit = this.folder.addFolder(`AU${au.number} ${au.name}`);
      unit.domElement.dataset.actionUnit = au.id;
      const bilateral = au.sides.length === 2;
      for (const side of au.sides) {
        const id = bilateral ? `${au.id}${side}` : au.id;
        const label = side === 'L' ? 'left' : side === 'R' ? 'right' : 'intensity';
        const controller = unit
          .add(this.values, id, 0, 1, 0.01)
          .onChange((v: number) => face.setActionUnit(bilateral && this.links[au.id] ? au.id : id, v));
        controller.domElement.dataset.control = id;
        const slider: SideSlider = { id, label, controller, grade: undefined };
        this.label(slider);
        this.sliders.push(slider);
      }
      if (bilateral) {
        this.links[au.id] = true;
        unit.add(this.links, au.id).name('link sides').domElement.dataset.control = `${au.id}-link`;
      }
      this.showMuscles[au.id] = face.getMuscleDisplay().actionUnits.includes(au.id);
      const muscles = unit
        .add(this.showMuscles, au.id)
        .name('show muscles')
        .onChange((on: boolean) => {
          // The whole list goes to the handle, which keeps it; the checkboxes only mirror it.
          const ids = face.getMuscleDisplay().actionUnits.filter((id) => id !== au.id);
          face.setMuscleDisplay({ actionUnits: on ? [...ids, au.id] : ids });
        });
      muscles.domElement.dataset.control = `${au.id}-muscles`;
      this.muscleControllers.push(muscles);
    }
    this.unsubscribe = face.onChange((change) => this.changed(change));
  }

  /** Whether a bilateral unit's sides move together. */
  linked(id: string): boolean {
    return this.links[id] ?? false;
  }

  /** Removes the folder and stops following the face. */
  dispose(): void {
    this.unsubscribe();
    this.refresh.dispose();
    this.folder.destroy();
  }

  private changed(change: FaceChange): void {
    if (change === 'muscles') {
      const shown = this.face.getMuscleDisplay().actionUnits;
      for (const id of Object.keys(this.showMuscles)) this.showMuscles[id] = shown.includes(id);
      for (const c of this.muscleControllers) c.updateDisplay();
      return;
    }
    if (change === 'expression') this.refresh.call();
  }

  /** Shows the expression: the code (unless it is being typed), the sliders and their grades. */
  private showExpression(): void {
    if (!this.codeController.domElement.contains(document.activeElement)) {
      this.code.facs = this.face.getFACS();
      this.codeController.updateDisplay();
    }
    this.codeMessage.textContent = '';
    Object.assign(this.values, this.face.getActionUnits());
    for (const slider of this.sliders) {
      slider.controller.updateDisplay();
      this.label(slider);
    }
  }

  /** Sets the expression by the code typed; a refused one stays in the field, with the reason under it. */
  private setCode(code: string): void {
    try {
      this.face.setFACS(code);
    } catch (error) {
      this.codeMessage.textContent = (error as Error).message;
    }
  }

  /** Shows the slider's grade in its label, rebuilding the label only when the grade changed. */
  private label(slider: SideSlider): void {
    const grade = gradeOf(this.values[slider.id]);
    if (grade === slider.grade) return;
    slider.grade = grade;
    slider.controller.name(`${slider.label} · ${grade || '–'}`);
  }
}
