import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import { SKIN_RANGES } from '../core/solver/skin-parameters';
import type { FaceChange, FaceHandle } from '../face/face-handle';
import { RESOLUTIONS, type Resolution } from '../face/face-options';
import { APPEARANCE_RANGES } from '../render/view-options';
import { downloadBlob, fileTimestamp } from './download';

/** What the Rendering folder needs from the page. */
export interface RenderingPanelOptions {
  /** The head resolution shown. */
  resolution: Resolution;
  /** Called when the user picks another resolution (the app reloads with it); without it none is offered. */
  onResolution?: ((resolution: Resolution) => void) | null;
  /** Largest iteration count the sliders offer (the skin accepts up to SKIN_RANGES' greatest). */
  maxIterations?: number;
}

const RENDERING_PANEL_DEFAULTS: Required<Pick<RenderingPanelOptions, 'maxIterations' | 'onResolution'>> = {
  maxIterations: 20,
  onResolution: null,
};

/**
 * The Rendering folder: solid or wireframe, eyes, teeth, the brows and lashes (switches, colours, density), the head's resolution, the
 * solver's length and position
 * iteration counts, the eye simulation, every muscle shown over the skin, and a button that saves the picture as a PNG.
 */
export class RenderingPanel {
  readonly folder: GUI;
  private readonly state: {
    wireframe: boolean;
    showEyes: boolean;
    showTeeth: boolean;
    skinColor: string;
    brows: boolean;
    browColor: string;
    browDensity: number;
    lashes: boolean;
    lashColor: string;
    resolution: Resolution;
    lengthIterations: number;
    positionIterations: number;
    eyeSimulation: boolean;
    showAllMuscles: boolean;
    savePNG: () => void;
  };
  private readonly controllers: Controller[] = [];
  private readonly unsubscribe: () => void;

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
    options: RenderingPanelOptions,
  ) {
    const o = { ...RENDERING_PANEL_DEFAULTS, ...options };
    const skin = face.getSkinParameters();
    this.state = {
      ...face.getRenderOptions(),
      ...face.getAppearance(),
      resolution: o.resolution,
      lengthIterations: skin.lengthIterations,
      positionIterations: skin.positionIterations,
      eyeSimulation: face.getEyeSimulation(),
      showAllMuscles: face.getMuscleDisplay().all,
      savePNG: () => void this.savePNG(),
    };
    this.folder = parent.addFolder('Rendering');
    const s = this.state;
    this.add(
      this.folder.add(s, 'wireframe').onChange((v: boolean) => face.setRenderOptions({ wireframe: v })),
      'wireframe',
    );
    this.add(
      this.folder
        .add(s, 'showEyes')
        .name('show eyes')
        .onChange((v: boolean) => face.setRenderOptions({ showEyes: v })),
      'show-eyes',
    );
    this.add(
      this.folder
        .add(s, 'showTeeth')
        .name('show teeth')
        .onChange((v: boolean) => face.setRenderOptions({ showTeeth: v })),
      'show-teeth',
    );
    this.add(
      this.folder
        .addColor(s, 'skinColor')
        .name('skin colour')
        .onChange((v: string) => face.setAppearance({ skinColor: v })),
      'skin-color',
    );
    this.add(
      this.folder
        .add(s, 'brows')
        .name('eyebrows')
        .onChange((v: boolean) => face.setAppearance({ brows: v })),
      'brows',
    );
    this.add(
      this.folder
        .addColor(s, 'browColor')
        .name('brow colour')
        .onChange((v: string) => face.setAppearance({ browColor: v })),
      'brow-color',
    );
    this.add(
      this.folder
        .add(s, 'browDensity', ...APPEARANCE_RANGES.browDensity!, 0.05)
        .name('brow density')
        .onChange((v: number) => face.setAppearance({ browDensity: v })),
      'brow-density',
    );
    this.add(
      this.folder
        .add(s, 'lashes')
        .name('eyelashes')
        .onChange((v: boolean) => face.setAppearance({ lashes: v })),
      'lashes',
    );
    this.add(
      this.folder
        .addColor(s, 'lashColor')
        .name('lash colour')
        .onChange((v: string) => face.setAppearance({ lashColor: v })),
      'lash-color',
    );
    const onResolution = o.onResolution;
    if (onResolution)
      this.add(
        this.folder
          .add(s, 'resolution', [...RESOLUTIONS])
          .name('mesh resolution')
          .onChange((r: Resolution) => onResolution(r)),
        'resolution',
      );
    // The skin's ranges, from at least one pass (no length pass leaves the skin without its edges, which no one wants
    // from a slider) to maxIterations (a slider over all 64 passes could not be set finely).
    const iterations = (key: 'lengthIterations' | 'positionIterations'): [number, number] => {
      const [least, greatest] = SKIN_RANGES[key];
      return [Math.max(1, least), Math.min(o.maxIterations, greatest)];
    };
    this.add(
      this.folder
        .add(s, 'lengthIterations', ...iterations('lengthIterations'), 1)
        .name('length iterations')
        .onChange((n: number) => face.setSkinParameters({ lengthIterations: n })),
      'length-iterations',
    );
    this.add(
      this.folder
        .add(s, 'positionIterations', ...iterations('positionIterations'), 1)
        .name('position iterations')
        .onChange((n: number) => face.setSkinParameters({ positionIterations: n })),
      'position-iterations',
    );
    this.add(
      this.folder
        .add(s, 'eyeSimulation')
        .name('eye simulation')
        .onChange((v: boolean) => face.setEyeSimulation(v)),
      'eye-simulation',
    );
    this.add(
      this.folder
        .add(s, 'showAllMuscles')
        .name('show all muscles')
        .onChange((v: boolean) => face.setMuscleDisplay({ all: v })),
      'show-all-muscles',
    );
    this.add(this.folder.add(s, 'savePNG').name('save PNG'), 'save-png');
    this.unsubscribe = face.onChange((change) => this.changed(change));
  }

  /** Removes the folder and stops following the face. */
  dispose(): void {
    this.unsubscribe();
    this.folder.destroy();
  }

  private add(controller: Controller, name: string): void {
    controller.domElement.dataset.control = name;
    this.controllers.push(controller);
  }

  /** Downloads the canvas as `softface-<timestamp>.png`; a failure is reported on the console, not thrown. */
  private async savePNG(): Promise<void> {
    try {
      downloadBlob(await this.face.savePNG(), `softface-${fileTimestamp()}.png`);
    } catch (error) {
      console.warn(`save PNG: ${(error as Error).message}`);
    }
  }

  private changed(change: FaceChange): void {
    if (change === 'render') Object.assign(this.state, this.face.getRenderOptions());
    else if (change === 'appearance') Object.assign(this.state, this.face.getAppearance());
    else if (change === 'eyes') this.state.eyeSimulation = this.face.getEyeSimulation();
    else if (change === 'muscles') this.state.showAllMuscles = this.face.getMuscleDisplay().all;
    else if (change === 'skin') {
      const skin = this.face.getSkinParameters();
      this.state.lengthIterations = skin.lengthIterations;
      this.state.positionIterations = skin.positionIterations;
    } else return;
    for (const c of this.controllers) c.updateDisplay();
  }
}
