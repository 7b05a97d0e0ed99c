import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { FaceChange, FaceHandle } from '../face/face-handle';
import { named } from './named';
import { Throttle } from './throttle';

/**
 * The Presets folder: a 0..1 weight slider per preset (they add up), a list of the EMFACS table's faces (an emotion's
 * prototypes and major variants, each set as its FACS code), and a button that zeroes everything.
 */
export class PresetsPanel {
  readonly folder: GUI;
  /** Preset weights by name, which the controllers read and write. */
  private readonly weights: Record<string, number> = {};
  private readonly controllers: Controller[] = [];
  /** The EMFACS face picked last (its name), '' once the expression is changed some other way. */
  private readonly emotion = { face: '' };
  private readonly emotionController: Controller;
  private picking = false;
  private readonly unsubscribe: () => void;
  /** Redraws after expression changes, a few times a second while a timeline plays. */
  private readonly refresh = new Throttle(
    () => this.showWeights(),
    () => this.face.timelineState().playing,
  );

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
  ) {
    this.folder = parent.addFolder('Presets');
    for (const preset of face.listPresets()) {
      this.weights[preset.name] = preset.weight;
      const controller = this.folder.add(this.weights, preset.name, 0, 1, 0.01).onChange((w: number) => face.applyPreset(preset.name, w));
      controller.domElement.dataset.control = `preset-${preset.name}`;
      controller.domElement.title = preset.note ? `${preset.source}: ${preset.note}` : preset.source;
      this.controllers.push(controller);
    }
    // Label -> name, e.g. "fear prototype 2: 1+2+4+5+20+26" -> "fear-prototype-2".
    const faces: Record<string, string> = { '–': '' };
    for (const v of face.listEmotionVariants()) faces[`${v.emotion} ${v.kind} ${v.name.split('-').pop()}: ${v.code}`] = v.name;
    this.emotionController = named(
      this.folder
        .add(this.emotion, 'face', faces)
        .name('EMFACS face')
        .onChange((name: string) => this.pick(name)),
      'emfacs',
    );
    this.emotionController.domElement.title = 'EMFACS (Friesen & Ekman 1983): each emotion’s prototypes and major variants';
    const actions = { reset: () => face.reset() };
    this.folder.add(actions, 'reset').name('reset (neutral face)').domElement.dataset.control = 'reset';
    this.unsubscribe = face.onChange((change) => this.changed(change));
  }

  /** Removes the folder and stops following the face. */
  dispose(): void {
    this.unsubscribe();
    this.refresh.dispose();
    this.folder.destroy();
  }

  private pick(name: string): void {
    if (!name) return;
    this.picking = true;
    try {
      this.face.setEmotion(name);
    } finally {
      this.picking = false;
    }
  }

  private changed(change: FaceChange): void {
    if (change !== 'expression') return;
    // Any other change of the expression leaves the face picked.
    if (!this.picking && this.emotion.face !== '') {
      this.emotion.face = '';
      this.emotionController.updateDisplay();
    }
    this.refresh.call();
  }

  private showWeights(): void {
    for (const preset of this.face.listPresets()) this.weights[preset.name] = preset.weight;
    for (const c of this.controllers) c.updateDisplay();
  }
}
