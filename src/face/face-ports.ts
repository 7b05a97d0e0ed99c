/**
 * The ports of the face's handle: the shapes of the parts it drives (the view, the eyes, the heads, the face's element,
 * the timeline player, the glTF writer, the recorder, the muscle glyphs), which EmbeddedFace connects, and the plain
 * data it hands out. No behaviour here.
 */
import type { EyeSimulationOptions } from '../core/expression/eye-simulation';
import type { SkinParameters } from '../core/solver/skin-parameters';
import type { Timeline } from '../core/timeline/timeline';
import type { RenderTiming } from '../render/render-timing';
import type { MaterialDescription } from '../render/materials';
import type { HairSnapshot } from '../render/hair-view';
import type { FrameHook } from '../render/head-view';
import type { HeadWriteOptions, JawPose, MorphClip, MorphShape } from '../render/gltf-export';
import type { AppearanceOptions, CameraOptions, LightOptions, RenderOptions } from '../render/view-options';
import type { SkinSimulationStats } from '../sim/main/skin-simulation';
import type { HashExpression } from './expression-hash';
import type { HeadDescription, HeadSource, LoadHeadOptions } from './head-loader';
import type { LandmarkGuide } from './landmark-guide';
import type { VideoOptions } from './video-options';
import type { NamedIdentity } from '../core/head/identity';

/** The welded skin at one moment, in simulation vertex order. */
export interface SkinSnapshot {
  /** Rest positions, xyz per vertex. */
  rest: Float32Array;
  /** Current positions, xyz per vertex. */
  positions: Float32Array;
  /** Current unit normals, xyz per vertex. */
  normals: Float32Array;
  /** Triangles over the vertices, counter-clockwise from outside. */
  triangles: Uint32Array;
}

/** What `stats` reports: the skin solver's state as of its newest frame (see `SkinSimulationStats`). */
export type FaceStats = SkinSimulationStats;
export type { SkinSimulationStats };

/**
 * What a handle call changed: the Action Units or presets, the light, the render options, the skin parameters,
 * whether the eye simulation runs, which muscles are shown, the rig (an edit, undo or redo, a new rig), or the
 * editor (on or off, the selected muscle, its gizmo's mode or part, the preview contraction), the head (another
 * head loaded, or the default one back), the landmark guide (started, a landmark placed, ended), or the timeline
 * (loaded, played, paused, sought, and every frame it plays).
 */
export type FaceChange =
  | 'expression'
  | 'light'
  | 'camera'
  | 'render'
  | 'appearance'
  | 'skin'
  | 'eyes'
  | 'muscles'
  | 'rig'
  | 'editor'
  | 'head'
  | 'landmarks'
  | 'timeline';

/** The muscle glyphs the handle shows and hides (MuscleView). */
export interface FaceMuscles {
  setVisible(names: ReadonlySet<string> | 'all' | 'none'): void;
  /** The names of the muscles drawn now. */
  shown(): string[];
}

/** What the eye simulation has done since it was last switched on: counts, and the gaze now in degrees. */
export interface EyeStats {
  /** Whether it runs. */
  on: boolean;
  /** Blinks started. */
  blinks: number;
  /** Saccades (quick turns of the gaze to a new target) started. */
  saccades: number;
  /** Lid closure of the blink now, 0 open .. 1 closed. */
  blink: number;
  /** The simulation's clock: ms of rendered frames since it was switched on. */
  time: number;
  /** Positive yaw looks to the subject's left, positive pitch up. */
  gaze: {
    /** Degrees the eyes turn sideways, positive to the subject's left; saccades aim within `yawMin`..`yawMax`. */
    yaw: number;
    /** Degrees the eyes turn up (positive) or down; saccades aim within `pitchMin`..`pitchMax`. */
    pitch: number;
  };
}

/** The eye simulation the handle switches (EyeDriver). */
export interface FaceEyes {
  setEnabled(on: boolean, simulation?: Partial<EyeSimulationOptions>): void;
  enabled(): boolean;
  stats(): EyeStats;
  /** Turns the eyes to the gaze asked for now, for a picture drawn before the next frame. */
  showGaze(): void;
}

/** The head side the handle drives (EmbeddedFace): loading another head, going back to the default one. */
export interface FaceHeads {
  loadHead(source: HeadSource, options?: LoadHeadOptions): Promise<HeadDescription>;
  revertHead(): Promise<void>;
  describeHead(): HeadDescription;
  guideLandmarks(source: HeadSource, options?: LoadHeadOptions): Promise<HeadDescription>;
  landmarkGuide(): LandmarkGuide | undefined;
  showIdentity(named: NamedIdentity | null): Promise<HeadDescription>;
}

/** The face's element around its canvas: the panels and the background (EmbeddedFace). */
export interface FaceShell {
  setPanels(on: boolean): Promise<void>;
  hasPanels(): boolean;
  setBackground(background: string): void;
  getBackground(): string;
}

/** What carries over from one head to the next: the expression, the eye simulation, the skin parameters. */
export interface CarriedState {
  expression: HashExpression;
  eyes: boolean;
  skin: SkinParameters;
}

/** Where the timeline is: whether one is loaded, whether it plays, its clock and duration in seconds, and its loop flag. */
export interface TimelineState {
  /** Whether a timeline is loaded (`setTimeline`). */
  loaded: boolean;
  /** Whether it plays; false when paused, after a timeline without loop has reached its end, or with none loaded. */
  playing: boolean;
  /** The timeline's clock in seconds, 0..`duration`. */
  time: number;
  /** How long the timeline runs, in seconds: its `duration`, else the end of its last key or action; 0 without one. */
  duration: number;
  /** Whether the timeline starts again at its end (its `loop`); false without one. */
  loop: boolean;
}

/** The timeline player the handle drives (TimelinePlayer). */
export interface FaceTimeline {
  set(timeline: Timeline | null): void;
  timeline(): Timeline | null;
  play(): void;
  pause(): void;
  seek(seconds: number): void;
  state(): TimelineState;
}

/** The writer `exportGLTF` hands the solved shapes to (HeadExporter). */
export interface FaceGLTFWriter {
  /** Render vertices of the skin. */
  readonly vertexCount: number;
  jawPose(): JawPose | null;
  write(shapes: readonly MorphShape[], clip: MorphClip | null, options: HeadWriteOptions): Promise<ArrayBuffer | Record<string, unknown>>;
}

/** The recorder the handle drives (VideoRecorder). */
export interface FaceRecorder {
  /** Records `seconds` with checked options. */
  record(options: Required<VideoOptions>, seconds: number): Promise<Blob>;
  recording(): boolean;
}

/** Told after every successful change made through the handle (panels refresh their sliders with it). */
export type FaceChangeListener = (change: FaceChange) => void;

/** The view the handle drives lights and render options through (HeadView). */
export interface FaceView {
  setLight(partial: Partial<LightOptions>): void;
  lightOptions(): LightOptions;
  setRenderOptions(partial: Partial<RenderOptions>): void;
  renderOptions(): RenderOptions;
  setAppearance(partial: Partial<AppearanceOptions>): void;
  appearanceOptions(): AppearanceOptions;
  describeHair(vertexAt: (x: number, y: number, z: number) => number): HairSnapshot | null;
  setCamera(partial: Partial<CameraOptions>): void;
  cameraOptions(): CameraOptions;
  locate(point: readonly [number, number, number]): { x: number; y: number } | null;
  /** Renders a frame and encodes the canvas as a PNG. */
  snapshot(): Promise<Blob>;
  measureRender(frames?: number): RenderTiming;
  describeMaterials(): MaterialDescription[];
  /** Runs `hook` before each frame is drawn; 'hold' from it defers the drawing (see HeadView.onFrame). */
  onFrame(hook: FrameHook): () => void;
  /** Runs `hook` after each drawn frame. */
  onRender(hook: () => void): () => void;
}
