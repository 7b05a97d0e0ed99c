import GUI from 'lil-gui';
import type { FaceHandle } from '../embed/face-handle';
import { ActionUnitsPanel } from './action-units-panel';
import { LightPanel } from './light-panel';
import { OutputsPanel, type FrameSource } from './outputs-panel';
import { PresetsPanel } from './presets-panel';
import { RenderingPanel, type Resolution } from './rendering-panel';

export interface PanelsOptions {
  /** Counts rendered frames for the fps output. */
  frames: FrameSource;
  /** The head resolution shown, and what to do when the user picks another. */
  resolution: Resolution;
  onResolution: (resolution: Resolution) => void;
  /** Width of the panel column in px. */
  width?: number;
}

const PANELS_DEFAULTS: Required<Pick<PanelsOptions, 'width'>> = { width: 280 };

/**
 * The app's lil-gui column on the right. The short, closed folders come first and the long Action Units list last,
 * so that every folder title and the outputs are on screen at 1024 x 768 without scrolling.
 */
export class Panels {
  readonly gui: GUI;
  readonly presets: PresetsPanel;
  readonly rendering: RenderingPanel;
  readonly light: LightPanel;
  readonly outputs: OutputsPanel;
  readonly actionUnits: ActionUnitsPanel;

  constructor(face: FaceHandle, options: PanelsOptions) {
    const o = { ...PANELS_DEFAULTS, ...options };
    this.gui = new GUI({ title: 'softface', width: o.width });
    this.gui.domElement.id = 'panels';
    this.presets = new PresetsPanel(this.gui, face);
    this.rendering = new RenderingPanel(this.gui, face, { resolution: o.resolution, onResolution: o.onResolution });
    this.light = new LightPanel(this.gui, face);
    this.outputs = new OutputsPanel(this.gui, face, o.frames);
    this.actionUnits = new ActionUnitsPanel(this.gui, face);
    this.presets.folder.close();
    this.rendering.folder.close();
    this.light.folder.close();
  }

  /** Removes every panel, with its listeners, timers and frame hooks. */
  destroy(): void {
    this.actionUnits.destroy();
    this.outputs.destroy();
    this.light.destroy();
    this.rendering.destroy();
    this.presets.destroy();
    this.gui.destroy();
  }
}
