import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { FaceHandle } from '../face/face-handle';

/** Something that calls hooks once per drawn frame (HeadView). */
export interface FrameSource {
  onRender(hook: () => void): () => void;
}

export interface OutputsPanelOptions {
  /** How often the numbers are refreshed, in ms. */
  refreshMs?: number;
}

/** Frames, or else ms, that one fps reading spans at least (a reading ends at the first refresh that has either). */
export const FPS_MIN_FRAMES = 4;
export const FPS_MAX_WINDOW_MS = 3000;

const OUTPUTS_PANEL_DEFAULTS: Required<OutputsPanelOptions> = { refreshMs: 500 };

/** What the Outputs folder shows. */
interface Outputs {
  fps: number;
  solverMs: number;
  vertices: number;
  edges: number;
  position: number;
  length: number;
  muscle: number;
  bending: number;
  collision: number;
  mode: string;
  workers: number;
}

/**
 * The Outputs folder: frames per second (counted from drawn frames: 0 while nothing moves, as the view then draws
 * nothing), the solver's ms per frame, the skin's size,
 * its constraints by type, the solver mode and its threads. Read-only, refreshed on a timer: the per-frame hook only counts.
 */
export class OutputsPanel {
  readonly folder: GUI;
  private readonly outputs: Outputs = {
    fps: 0,
    solverMs: 0,
    vertices: 0,
    edges: 0,
    position: 0,
    length: 0,
    muscle: 0,
    bending: 0,
    collision: 0,
    mode: '',
    workers: 0,
  };
  private readonly controllers: Controller[] = [];
  private frames = 0;
  private since = performance.now();
  private readonly stopFrames: () => void;
  private readonly timer: ReturnType<typeof setInterval>;

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
    frames: FrameSource,
    options: OutputsPanelOptions = {},
  ) {
    const o = { ...OUTPUTS_PANEL_DEFAULTS, ...options };
    this.folder = parent.addFolder('Outputs');
    const show = (key: keyof Outputs, name: string, decimals?: number): void => {
      const c = this.folder.add(this.outputs, key).name(name).disable();
      if (decimals !== undefined) c.decimals(decimals);
      c.domElement.dataset.control = `output-${key}`;
      this.controllers.push(c);
    };
    show('fps', 'frames per second', 1);
    show('solverMs', 'solver ms per frame', 1);
    show('vertices', 'vertices', 0);
    show('edges', 'edges', 0);
    show('position', 'position constraints', 0);
    show('length', 'length constraints', 0);
    show('muscle', 'muscle constraints', 0);
    show('bending', 'bending constraints', 0);
    show('collision', 'collision constraints', 0);
    show('mode', 'worker mode');
    show('workers', 'solver workers', 0);
    this.stopFrames = frames.onRender(this.countFrame);
    this.timer = setInterval(() => this.refresh(), o.refreshMs);
    this.refresh();
  }

  /** Removes the folder, its frame hook and its timer. */
  dispose(): void {
    clearInterval(this.timer);
    this.stopFrames();
    this.folder.destroy();
  }

  /** The per-frame hook: one increment, no allocation. */
  private readonly countFrame = (): void => {
    this.frames++;
  };

  private refresh(): void {
    const now = performance.now();
    const elapsed = now - this.since;
    // A slow page (software WebGL draws a couple of frames a second) would read 0 or jump between 0 and 2 over one
    // refresh, so the count runs on until it has a few frames or a few seconds.
    if (this.frames >= FPS_MIN_FRAMES || elapsed >= FPS_MAX_WINDOW_MS) {
      this.outputs.fps = (1000 * this.frames) / elapsed;
      this.frames = 0;
      this.since = now;
    }
    const s = this.face.stats();
    const out = this.outputs;
    out.solverMs = s.solveMs;
    out.vertices = s.vertices;
    out.edges = s.edges;
    out.position = s.constraints.position;
    out.length = s.constraints.length;
    out.muscle = s.constraints.muscle;
    out.bending = s.constraints.bending;
    out.collision = s.constraints.collision;
    out.mode = s.mode;
    out.workers = s.workers;
    for (const c of this.controllers) c.updateDisplay();
  }
}
