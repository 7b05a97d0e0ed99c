import GUI from 'lil-gui';
import type { FaceHandle } from '../face/face-handle';
import { ActionUnitsPanel } from './action-units-panel';
import { EditorPanel } from './editor-panel';
import { ExportPanel } from './export-panel';
import { HeadPanel } from './head-panel';
import { IdentityPanel } from './identity-panel';
import { LightPanel } from './light-panel';
import { OutputsPanel, type FrameSource } from './outputs-panel';
import { PresetsPanel } from './presets-panel';
import { RenderingPanel } from './rendering-panel';
import { TimelinePanel } from './timeline-panel';
import { TrackingPanel } from './tracking-panel';
import { VideoPanel } from './video-panel';
import type { Resolution } from '../face/face-options';

export interface PanelsOptions {
  /** The element the column is placed over, at its top right corner (it needs a position other than static). */
  container: HTMLElement;
  /** Counts rendered frames for the fps output. */
  frames: FrameSource;
  /** The head resolution shown. */
  resolution: Resolution;
  /** What to do when the user picks another resolution; without it the resolution is not offered. */
  onResolution?: ((resolution: Resolution) => void) | null;
  /** Width of the panel column in px. */
  width?: number;
}

const PANELS_DEFAULTS: Required<Pick<PanelsOptions, 'width' | 'onResolution'>> = { width: 280, onResolution: null };

/** The class of the column's root element (pages and tests find the panels by it). */
const PANELS_CLASS = 'softface-panels';

/**
 * A face's lil-gui column on the right. The short, closed folders come first and the long Action Units list last,
 * so that every folder title and the outputs are on screen at 1024 x 768 without scrolling.
 */
export class Panels {
  readonly gui: GUI;
  readonly presets: PresetsPanel;
  readonly timeline: TimelinePanel;
  readonly tracking: TrackingPanel;
  readonly video: VideoPanel;
  readonly rendering: RenderingPanel;
  readonly light: LightPanel;
  readonly outputs: OutputsPanel;
  readonly actionUnits: ActionUnitsPanel;
  readonly editor: EditorPanel;
  readonly head: HeadPanel;
  readonly identity: IdentityPanel;
  readonly gltf: ExportPanel;

  constructor(face: FaceHandle, options: PanelsOptions) {
    const o = { ...PANELS_DEFAULTS, ...options };
    this.gui = new GUI({ title: 'softface', width: o.width, container: o.container });
    const style = this.gui.domElement.style;
    // Where lil-gui places a column of its own on the page, but over the face's corner: each face has its own.
    style.position = 'absolute';
    style.top = '0';
    style.right = '15px';
    style.maxHeight = '100%';
    style.zIndex = '1';
    this.gui.domElement.classList.add(PANELS_CLASS);
    this.presets = new PresetsPanel(this.gui, face);
    this.timeline = new TimelinePanel(this.gui, face);
    this.video = new VideoPanel(this.timeline.folder, face);
    this.tracking = new TrackingPanel(this.gui, face);
    this.rendering = new RenderingPanel(this.gui, face, { resolution: o.resolution, onResolution: o.onResolution });
    this.light = new LightPanel(this.gui, face);
    this.editor = new EditorPanel(this.gui, face, o.container);
    this.head = new HeadPanel(this.gui, face, o.container);
    this.identity = new IdentityPanel(this.gui, face);
    this.gltf = new ExportPanel(this.gui, face);
    this.outputs = new OutputsPanel(this.gui, face, o.frames);
    this.actionUnits = new ActionUnitsPanel(this.gui, face);
    this.presets.folder.close();
    this.timeline.folder.close();
    this.tracking.folder.close();
    this.rendering.folder.close();
    this.light.folder.close();
    this.editor.folder.close();
    this.head.folder.close();
    this.identity.folder.close();
    this.gltf.folder.close();
  }

  /** Removes every panel, with its listeners, timers and frame hooks. */
  dispose(): void {
    this.actionUnits.dispose();
    this.outputs.dispose();
    this.gltf.dispose();
    this.identity.dispose();
    this.head.dispose();
    this.editor.dispose();
    this.light.dispose();
    this.rendering.dispose();
    this.video.dispose();
    this.tracking.dispose();
    this.timeline.dispose();
    this.presets.dispose();
    this.gui.destroy();
  }
}
