import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { FaceChange, FaceHandle } from '../face/face-handle';

/** The Presets folder: a 0..1 weight slider per preset (they add up), and a button that zeroes everything. */
export class PresetsPanel {
  readonly folder: GUI;
  /** Preset weights by name, which the controllers read and write. */
  private readonly weights: Record<string, number> = {};
  private readonly controllers: Controller[] = [];
  private readonly unsubscribe: () => void;

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
    const actions = { reset: () => face.reset() };
    this.folder.add(actions, 'reset').name('reset (neutral face)').domElement.dataset.control = 'reset';
    this.unsubscribe = face.onChange((change) => this.changed(change));
  }

  /** Removes the folder and stops following the face. */
  dispose(): void {
    this.unsubscribe();
    this.folder.destroy();
  }

  private changed(change: FaceChange): void {
    if (change !== 'expression') return;
    for (const preset of this.face.listPresets()) this.weights[preset.name] = preset.weight;
    for (const c of this.controllers) c.updateDisplay();
  }
}
