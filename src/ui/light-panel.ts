import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { FaceChange, FaceHandle } from '../face/face-handle';
import { LIGHT_RANGES, type LightOptions } from '../render/view-options';

/**
 * The Light folder: the hemisphere fill's intensity, and the key light's horizontal angle (once around the head),
 * vertical angle (from below to above), intensity and colour.
 */
export class LightPanel {
  readonly folder: GUI;
  private readonly state: LightOptions;
  private readonly controllers: Controller[] = [];
  private readonly unsubscribe: () => void;

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
  ) {
    this.state = face.getLight();
    this.folder = parent.addFolder('Light');
    const set = (key: keyof LightOptions) => (value: number | string) => face.setLight({ [key]: value });
    const slider = (key: keyof typeof LIGHT_RANGES, name: string, step: number): void => {
      const [min, max] = LIGHT_RANGES[key];
      this.add(this.folder.add(this.state, key, min, max, step).name(name).onChange(set(key)), key);
    };
    slider('ambientIntensity', 'ambient (hemisphere)', 0.01);
    slider('keyAzimuth', 'key horizontal °', 1);
    slider('keyElevation', 'key vertical °', 1);
    slider('keyIntensity', 'key intensity', 0.05);
    this.add(this.folder.addColor(this.state, 'keyColor').name('key colour').onChange(set('keyColor')), 'keyColor');
    this.unsubscribe = face.onChange((change) => this.changed(change));
  }

  /** Removes the folder and stops following the face. */
  dispose(): void {
    this.unsubscribe();
    this.folder.destroy();
  }

  private add(controller: Controller, name: string): void {
    controller.domElement.dataset.control = `light-${name}`;
    this.controllers.push(controller);
  }

  private changed(change: FaceChange): void {
    if (change !== 'light') return;
    Object.assign(this.state, this.face.getLight());
    for (const c of this.controllers) c.updateDisplay();
  }
}
