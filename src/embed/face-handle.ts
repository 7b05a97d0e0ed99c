import { checkEyeSimulationOptions, type EyeSimulationOptions } from '../core/expression/eye-simulation';
import { isActionUnitId, type ActionUnitListing, type PresetListing } from '../core/expression/facs';
import { nextMuscleDisplay, shownMuscleNames, type MuscleDisplay } from '../core/rig/muscle-display';
import type { RigDocument, UpdateOptions } from '../core/rig/rig-document';
import { parseRigText } from '../core/rig/rig-schema';
import type { Muscle, Rig } from '../core/rig/rig-types';
import type { SkinParameters } from '../core/solver/skin-parameters';
import type { RenderTiming } from '../render/head-view';
import {
  EditorSession,
  type AutosaveStatus,
  type BrushOptions,
  type EditorState,
  type FaceEditorView,
  type GizmoMode,
  type GizmoPart,
} from './editor-session';
import type { MaterialDescription } from '../render/materials';
import type { HairSnapshot } from '../render/hair-view';
import type { AppearanceOptions, CameraOptions, LightOptions, RenderOptions } from '../render/view-options';
import type { SkinSimulation } from '../sim/main/skin-simulation';
import { readExpression, type ExpressionEntries } from './expression-hash';
import type { HeadDescription, HeadSource, LoadHeadOptions } from './head-loader';
import type { LandmarkGuideState } from './landmark-guide';
import type { Vec3 } from '../core/rig/rig-types';
import type { FaceExpression } from './face-expression';
import type { Timeline } from '../core/timeline/timeline';
import { parseTimeline, parseTimelineText } from '../core/timeline/timeline-schema';
import { checkExportOptions, type GLTFExportOptions } from './gltf-export-options';
import { bakeGLTF } from './gltf-bake';
import { checkVideoOptions, type VideoOptions } from './video-options';

export { gizmoParts, type BrushOptions, type EditorState, type FaceEditorView, type GizmoMode, type GizmoPart } from './editor-session';
export type { MuscleDisplay };
export type {
  SkinSnapshot,
  FaceStats,
  FaceChange,
  FaceMuscles,
  EyeStats,
  FaceEyes,
  FaceHeads,
  FaceShell,
  CarriedState,
  TimelineState,
  FaceTimeline,
  FaceGLTFWriter,
  FaceRecorder,
  FaceChangeListener,
  FaceView,
} from './face-ports';
import type {
  SkinSnapshot,
  FaceStats,
  FaceChange,
  FaceMuscles,
  EyeStats,
  FaceEyes,
  FaceHeads,
  FaceShell,
  CarriedState,
  TimelineState,
  FaceTimeline,
  FaceGLTFWriter,
  FaceRecorder,
  FaceChangeListener,
  FaceView,
} from './face-ports';

/**
 * A face on the page, as scripts (and the tests) drive it: what `createFace` resolves to, and `window.face` in the
 * app. Vertices are simulation vertex indices, the order of `getSkin().rest`.
 */
export class FaceHandle {
  /** Resolves once the head is shown and its skin solver runs; rejects if either fails. */
  readonly ready: Promise<void>;
  private simulation: SkinSimulation | undefined;
  private view: FaceView | undefined;
  private eyes: FaceEyes | undefined;
  private player: FaceTimeline | undefined;
  private gltfWriter: FaceGLTFWriter | undefined;
  /** Whether `exportGLTF` is solving its targets (one export at a time: each moves the face). */
  private exporting = false;
  private recorder: FaceRecorder | undefined;
  private muscles: FaceMuscles | undefined;
  private muscleDisplay: MuscleDisplay = { all: false, actionUnits: [] };
  /**
   * Replaced, never changed in place, when a listener comes or goes: `emit` walks the array it started with (a
   * listener that unsubscribes while being told does not make the next one miss the change) without copying it, as
   * a playing timeline emits every frame.
   */
  private listeners: readonly FaceChangeListener[] = [];
  private expression: FaceExpression | undefined;
  private heads: FaceHeads | undefined;
  private shell: FaceShell | undefined;
  /** The muscle editor's state (selection, gizmo, preview, mirror, brush) and the rig document it edits. */
  private readonly editor = new EditorSession(() => this.expression);
  private disposed = false;
  private resolveReady!: () => void;
  private rejectReady!: (error: Error) => void;

  /**
   * `teardown` stops and frees everything the face is made of; `dispose` calls it once.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  constructor(private readonly teardown: () => void = () => {}) {
    this.ready = new Promise<void>((resolve, reject) => {
      this.resolveReady = resolve;
      this.rejectReady = reject;
    });
    // The page reports a failed start itself; this keeps an unobserved rejection from being logged a second time.
    this.ready.catch(() => {});
  }

  /**
   * Connects the running simulation and the expression that drives its muscles, and resolves `ready`.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attach(simulation: SkinSimulation, expression: FaceExpression): void {
    this.simulation = simulation;
    this.expression = expression;
    this.resolveReady();
  }

  /**
   * Connects the view that shows the face, for `setLight` and `setRenderOptions` (usable before `ready`).
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachView(view: FaceView): void {
    this.view = view;
  }

  /**
   * Connects the eye simulation that `setEyeSimulation` switches.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachEyes(eyes: FaceEyes): void {
    this.eyes = eyes;
  }

  /**
   * Connects the timeline player that `setTimeline`, `play`, `pause` and `seek` drive.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachTimeline(player: FaceTimeline): void {
    this.player = player;
  }

  /**
   * Connects the shown head's glTF writer, for `exportGLTF` (a new head brings its own).
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachGLTFWriter(writer: FaceGLTFWriter): void {
    this.gltfWriter = writer;
  }

  /**
   * Connects the recorder that `recordVideo` drives (one per shown head).
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachRecorder(recorder: FaceRecorder): void {
    this.recorder = recorder;
  }

  /**
   * Sets the sliders and preset weights of a timeline frame (see `ExpressionState.setFrame`) and tells listeners if
   * they changed; returns whether they did. Does nothing before the face is ready.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  applyTimelineFrame(ids: readonly string[], values: ArrayLike<number>, presets: readonly string[], weights: ArrayLike<number>): boolean {
    if (this.disposed || !this.expression) return false;
    const changed = this.expression.setFrame(ids, values, presets, weights);
    if (changed) this.emit('expression');
    return changed;
  }

  /**
   * Tells listeners that the playing timeline's clock moved.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  timelineChanged(): void {
    if (!this.disposed) this.emit('timeline');
  }

  /**
   * Connects the muscle glyphs that `setMuscleDisplay` shows, and shows what was asked for so far.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachMuscles(muscles: FaceMuscles): void {
    this.muscles = muscles;
    this.showMuscles();
  }

  /**
   * Connects the rig document the editing methods change; its changes (from the handle, the panels or the gizmo) are
   * told to listeners as `'rig'`.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachRig(document: RigDocument, original: Rig, name: string): void {
    this.editor.attachRig(document, original, name, () => {
      if (this.disposed) return;
      this.showMuscles();
      this.emit('rig');
    });
  }

  /**
   * Connects the autosave, whose status `describeEditor` reports.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachAutosave(status: () => AutosaveStatus): void {
    this.editor.attachAutosave(status);
  }

  /**
   * Tells listeners that the editor's state changed outside a handle call (the autosave wrote).
   * @internal the face's own wiring, left out of the library's type declarations
   */
  editorChanged(): void {
    if (!this.disposed) this.emit('editor');
  }

  /**
   * Connects the editor's view side (gizmo, picking, highlight).
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachEditor(view: FaceEditorView): void {
    this.editor.attachView(view);
  }

  /**
   * Connects the head side: `loadHead`, `revertHead`, `describeHead`.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachHeads(heads: FaceHeads): void {
    this.heads = heads;
  }

  /**
   * Connects the face's element: `setPanels`, `setBackground`.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachShell(shell: FaceShell): void {
    this.shell = shell;
  }

  /**
   * Shows or removes the face's panels. They load on first use (lil-gui with them), so a page that never shows them
   * never fetches them; resolves once they are shown or gone. A value that is not a boolean rejects, naming it.
   */
  async setPanels(on: boolean): Promise<void> {
    return this.shellSide().setPanels(on);
  }

  /** Whether the face shows its panels. */
  hasPanels(): boolean {
    return this.shellSide().hasPanels();
  }

  /** Changes the background: a colour `"#rrggbb"` or `"transparent"`; a bad value throws naming it, and nothing changes. */
  setBackground(background: string): void {
    this.shellSide().setBackground(background);
  }

  /** The background: `"#rrggbb"` or `"transparent"`. */
  getBackground(): string {
    return this.shellSide().getBackground();
  }

  /**
   * The state a new head takes over from the current one.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  carriedState(): CarriedState {
    return {
      expression: { actionUnits: this.getActionUnits(), presets: Object.fromEntries(this.listPresets().map((p) => [p.name, p.weight])) },
      eyes: this.eyes?.enabled() ?? false,
      skin: this.getSkinParameters(),
    };
  }

  /**
   * Gives a new head the state the previous one had.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  restoreState(state: CarriedState): void {
    try {
      this.expressed().set(state.expression, 'loadHead');
    } catch (error) {
      // A preset the new head's rig does not have (an imported rig had it): the new head starts neutral.
      console.warn(`the expression was not carried over to the new head: ${(error as Error).message}`);
    }
    this.running().setParameters(state.skin);
    this.eyes?.setEnabled(state.eyes);
  }

  /**
   * Tells listeners that another head is shown.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  headChanged(): void {
    if (!this.disposed) this.emit('head');
  }

  /**
   * Loads a head (a `.glb`, a `.gltf` with its files, or an `.obj`: a URL, a File or a list of Files), carries the
   * rig over to it by its landmarks and shows it in place of the current one, keeping the expression. Resolves to
   * what was loaded; a file that is not a head (not a mesh, truncated, non-finite, no face found, over 200,000
   * triangles or 64 MB) rejects with a message naming the file and what is wrong, and the current head stays.
   */
  async loadHead(source: HeadSource, options?: LoadHeadOptions): Promise<HeadDescription> {
    this.alive();
    await this.ready;
    return this.headSide().loadHead(source, options);
  }

  /** Shows the default head again, with the face's own rig (a kept loaded head is forgotten). */
  async revertHead(): Promise<void> {
    this.alive();
    await this.ready;
    return this.headSide().revertHead();
  }

  /**
   * Loads a head as `loadHead` does; where its landmarks cannot all be found, shows its skin alone and has the
   * missing ones placed by clicking on it (the Head folder says which: "click the left mouth corner"), then loads it
   * with them. Resolves once the head is shown; rejects if the guide is cancelled or the file is refused otherwise.
   */
  async guideLandmarks(source: HeadSource, options?: LoadHeadOptions): Promise<HeadDescription> {
    this.alive();
    await this.ready;
    return this.headSide().guideLandmarks(source, options);
  }

  /** The landmark guide under way (what to click next, what is placed), or null. */
  describeLandmarkGuide(): LandmarkGuideState | null {
    return this.headSide().landmarkGuide()?.state() ?? null;
  }

  /** Places the guide's next landmark at a point of the shown skin (metres), as a click on it does. */
  placeLandmark(point: Vec3): void {
    const guide = this.headSide().landmarkGuide();
    if (!guide) throw new Error('placeLandmark: no landmark guide is under way');
    guide.place(point);
  }

  /** Where a point of the skin the guide shows is on the page (client pixels), to click it (read-only, for tests). */
  locateLandmarkPoint(point: Vec3): { x: number; y: number } | null {
    return this.headSide().landmarkGuide()?.locate(point) ?? null;
  }

  /** Stops the landmark guide; its `guideLandmarks` rejects and the face keeps its head. */
  cancelLandmarkGuide(): void {
    this.headSide().landmarkGuide()?.cancel();
  }

  /**
   * Tells listeners that the landmark guide changed.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  guideChanged(): void {
    if (!this.disposed) this.emit('landmarks');
  }

  /** The head shown: default or loaded, its file, size, units, axes and landmarks (read-only). */
  describeHead(): HeadDescription {
    return this.headSide().describeHead();
  }

  /** Calls `listener` after every change made through the handle; returns the function that stops it. */
  onChange(listener: FaceChangeListener): () => void {
    this.alive();
    this.listeners = [...this.listeners, listener];
    return () => {
      const i = this.listeners.indexOf(listener);
      if (i >= 0) this.listeners = [...this.listeners.slice(0, i), ...this.listeners.slice(i + 1)];
    };
  }

  /**
   * Rejects `ready`: the face could not start.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  fail(error: Error): void {
    this.rejectReady(error);
  }

  /**
   * Stops the face: its solver (and worker), render loop, panels and listeners end, its canvas and panels leave the
   * page and its GPU resources are freed. The other methods throw from then on; a second call does nothing.
   */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.listeners = [];
    this.rejectReady(new Error('the face was disposed before it was ready'));
    this.teardown();
  }

  /** Whether `dispose` was called. */
  isDisposed(): boolean {
    return this.disposed;
  }

  /** Resolves once the skin has converged for every input given so far (rejects after `timeoutMs`, if given). */
  async settle(timeoutMs?: number): Promise<void> {
    await this.ready;
    return this.running().settle(timeoutMs);
  }

  /** A copy of the skin's newest solved shape. */
  getSkin(): SkinSnapshot {
    const simulation = this.running();
    const positions = new Float32Array(simulation.rest.length);
    const normals = new Float32Array(simulation.rest.length);
    simulation.readSimulation(positions, normals);
    return { rest: simulation.rest.slice(), positions, normals, triangles: simulation.triangles.slice() };
  }

  stats(): FaceStats {
    return this.running().stats();
  }

  /**
   * Pulls vertices toward targets (xyz each) with a weight from 0 to 1 along the skin's surface and one along its
   * normal (by default the same); throws, changing nothing, on bad input.
   */
  setMuscleTargets(vertices: ArrayLike<number>, targets: ArrayLike<number>, weight = 1, normalWeight = weight): void {
    this.running().setMuscleTargets(vertices, targets, weight, normalWeight);
  }

  clearMuscleTargets(): void {
    this.running().clearMuscleTargets();
  }

  /** Changes some skin parameters; throws, changing nothing, if one is unknown or not a finite number in range. */
  setSkinParameters(partial: Partial<SkinParameters>): void {
    this.running().setParameters(partial);
    this.emit('skin');
  }

  /** The skin parameters as last set. */
  getSkinParameters(): SkinParameters {
    return this.running().parameters();
  }

  /**
   * Changes some light options (`ambientIntensity`, `keyAzimuth` 0..360, `keyElevation` -90..90, `keyIntensity`,
   * `keyColor` "#rrggbb"); an unknown option or a value of the wrong type or range throws naming it and changes nothing.
   */
  setLight(partial: Partial<LightOptions>): void {
    this.shown().setLight(partial);
    this.emit('light');
  }

  getLight(): LightOptions {
    return this.shown().lightOptions();
  }

  /**
   * Moves the camera relative to the head's framing from the front: `yaw` degrees round it (-180..180, 90 from the
   * subject's left), `pitch` degrees up (-80..80), `distance` as a multiple of the framing distance (0.2..5); bad input
   * throws naming it and changes nothing. The user's orbit drags move the same camera.
   */
  setCamera(partial: Partial<CameraOptions>): void {
    this.shown().setCamera(partial);
    this.emit('camera');
  }

  getCamera(): CameraOptions {
    return this.shown().cameraOptions();
  }

  /**
   * Where a point of the head (the skin's model space, metres, as `getSkin` gives them) is on the page, in client
   * pixels, as the camera sees it now (for overlays and tests); null before a head is shown.
   */
  locatePoint(point: Vec3): { x: number; y: number } | null {
    return this.shown().locate(point);
  }

  /** Changes some render options (`wireframe`, `showEyes`, `showTeeth`, booleans); bad input throws and changes nothing. */
  setRenderOptions(partial: Partial<RenderOptions>): void {
    this.shown().setRenderOptions(partial);
    this.emit('render');
  }

  getRenderOptions(): RenderOptions {
    return this.shown().renderOptions();
  }

  /**
   * Changes how the face's hair looks: `brows` and `lashes` (booleans: off for a bare face), `browColor` and
   * `lashColor` (`#rrggbb`), `browDensity` (0..1, the share of brow hairs drawn); bad input throws and changes nothing.
   */
  setAppearance(partial: Partial<AppearanceOptions>): void {
    this.shown().setAppearance(partial);
    this.emit('appearance');
  }

  getAppearance(): AppearanceOptions {
    return this.shown().appearanceOptions();
  }

  /**
   * The brows and lashes as drawn now: per kind, the drawn hairs' ribbon vertices (a hair's first two are its root)
   * and each hair's anchor (three skin vertices in simulation order, as `getSkin` gives them, and barycentric weights).
   */
  getHair(): HairSnapshot {
    const rest = this.running().rest;
    const byPosition = new Map<string, number>();
    for (let v = rest.length / 3 - 1; v >= 0; v--) byPosition.set(`${rest[3 * v]},${rest[3 * v + 1]},${rest[3 * v + 2]}`, v);
    const hair = this.shown().describeHair((x, y, z) => {
      const v = byPosition.get(`${Math.fround(x)},${Math.fround(y)},${Math.fround(z)}`);
      if (v === undefined) throw new Error(`getHair: no skin vertex at (${x}, ${y}, ${z})`);
      return v;
    });
    if (!hair) throw new Error('getHair: the head has no hair');
    return hair;
  }

  /**
   * Shows the rig's muscles over the skin: `all` of them, and/or those of some Action Units (`["AU12", "AU6"]`, ids
   * without a side: both sides are shown; the list replaces the previous one). Either key may be left out to keep it.
   * An unknown key, a non-boolean `all` or an unknown id throws naming it and changes nothing.
   */
  setMuscleDisplay(partial: Partial<MuscleDisplay>): void {
    this.alive();
    this.muscleDisplay = nextMuscleDisplay(this.muscleDisplay, partial);
    this.showMuscles();
    this.emit('muscles');
  }

  /** Which muscles are asked for (a copy): `{ all, actionUnits }`. */
  getMuscleDisplay(): MuscleDisplay {
    this.alive();
    return { all: this.muscleDisplay.all, actionUnits: [...this.muscleDisplay.actionUnits] };
  }

  /** The names of the muscles the scene draws now, in rig order (read-only: what the glyphs show, for tests). */
  describeMuscleDisplay(): string[] {
    this.alive();
    return this.muscles?.shown() ?? [];
  }

  /** The head's materials as plain data: colours, roughness, sheen, textures, the subsurface look (read-only). */
  describeMaterials(): MaterialDescription[] {
    return this.shown().describeMaterials();
  }

  /** Renders `frames` frames (default 100) back to back and reports their main-thread time (a benchmark: it blocks the page). */
  measureRender(frames = 100): RenderTiming {
    if (!Number.isInteger(frames) || frames < 1 || frames > 10_000)
      throw new Error(`measureRender: frames must be an integer within 1..10000, got ${String(frames)}`);
    return this.shown().measureRender(frames);
  }

  /**
   * Sets an Action Unit's intensity, 0..1 (clamped): `AU12` drives both sides, `AU12L` and `AU12R` one (the subject's
   * left is +x). An unknown id or a non-finite value throws an error naming it and changes nothing.
   */
  setActionUnit(id: string, value: number): void {
    this.expressed().setActionUnit(id, value);
    this.emit('expression');
  }

  /** The Action Unit sliders, per side: `{ AU1L: 0, AU1R: 0, ..., AU17: 0, ... }`. */
  getActionUnits(): Record<string, number> {
    return this.expressed().getActionUnits();
  }

  /**
   * Replaces the whole expression: the Action Units and preset weights given are set, every other one goes to 0. As
   * text in the URL-hash form (`"AU12=0.8&AU6L=0.5&preset:happiness=0.3"`) or as an object of the same entries
   * (`{ AU12: 0.8, 'preset:happiness': 0.3 }`). An unknown id or preset, or a value that is not a finite number,
   * throws naming it and changes nothing.
   */
  setExpression(expression: string | ExpressionEntries): void {
    this.expressed().set(readExpression(expression, 'setExpression'), 'setExpression');
    this.emit('expression');
  }

  /**
   * What each Action Unit side adds up to with the presets and the overlay (the eye simulation's lids), clamped to
   * 0..1, by side id like `getActionUnits`.
   */
  getEffectiveActionUnits(): Record<string, number> {
    return this.expressed().effective();
  }

  /** Every Action Unit: id, FACS number, name and sides (`L`, `R` or `M`). */
  listActionUnits(): ActionUnitListing[] {
    return this.expressed().listActionUnits();
  }

  /** Sets a preset's weight, 0..1 (clamped); presets and Action Units add up (and clamp) per side. */
  applyPreset(name: string, weight = 1): void {
    this.expressed().applyPreset(name, weight);
    this.emit('expression');
  }

  /** The rig's presets with their current weights. */
  listPresets(): PresetListing[] {
    return this.expressed().listPresets();
  }

  /** Zeroes every Action Unit and preset: the neutral face. */
  reset(): void {
    this.expressed().reset();
    this.emit('expression');
  }

  /**
   * Sets the page's own contribution to some Action Unit sides (`ids[i]` to `values[i]`, each clamped to 0..1): it
   * adds to the sliders and presets (clamped per side) without moving them, and tells no listener, because it may
   * change every frame. The eye simulation drives the lids with it. Bad input throws and changes nothing.
   */
  setOverlay(ids: readonly string[], values: ArrayLike<number>): void {
    const expression = this.expressed();
    if (ids.length !== values.length) throw new Error(`setOverlay: ${ids.length} ids but ${values.length} values`);
    for (let i = 0; i < ids.length; i++) {
      if (!isActionUnitId(ids[i])) throw new Error(`setOverlay: unknown Action Unit id ${JSON.stringify(ids[i])}`);
      if (typeof values[i] !== 'number' || !Number.isFinite(values[i]))
        throw new Error(`setOverlay: ${ids[i]} needs a finite number, got ${String(values[i])}`);
    }
    expression.setOverlay(ids, values);
  }

  /** Removes the page's whole contribution (see `setOverlay`). */
  clearOverlay(): void {
    this.expressed().clearOverlay();
  }

  /** The overlay by side id, like `getActionUnits`. */
  getOverlay(): Record<string, number> {
    return this.expressed().getOverlay();
  }

  // ---- the timeline -----------------------------------------------------------------------------------------

  /**
   * Loads a timeline (a timeline document as JSON text or an object; see the README's "Timeline"), paused at 0 with
   * the face set to its start. It is checked whole first: a problem throws a `TimelineError` naming its path
   * (`setTimeline: tracks.AU12L.keys[2].time: ...`; `source`, such as a file's name, replaces `setTimeline` there)
   * and changes nothing. While it plays or is sought it sets the sliders and presets it names; the rest stay.
   */
  setTimeline(timeline: string | object, source = 'setTimeline'): void {
    if (typeof source !== 'string') throw new Error(`setTimeline: source must be a string, got ${String(source)}`);
    const player = this.timelinePlayer();
    const options = { presets: this.listPresets().map((p) => p.name) };
    const parsed = typeof timeline === 'string' ? parseTimelineText(timeline, source, options) : parseTimeline(timeline, source, options);
    player.set(parsed);
    this.emit('timeline');
  }

  /** A copy of the loaded timeline document, or null. */
  getTimeline(): Timeline | null {
    const t = this.timelinePlayer().timeline();
    return t ? structuredClone(t) : null;
  }

  /** Unloads the timeline; the face keeps the values it had last. */
  clearTimeline(): void {
    this.timelinePlayer().set(null);
    this.emit('timeline');
  }

  /** Plays the timeline from its clock (from the start again after a timeline without loop has ended). */
  play(): void {
    const player = this.timelinePlayer();
    if (!player.timeline()) throw new Error('play: no timeline is loaded (setTimeline first)');
    player.play();
    this.emit('timeline');
  }

  /** Pauses the timeline: the face holds, and the sliders are the user's again until the next play or seek. */
  pause(): void {
    this.timelinePlayer().pause();
    this.emit('timeline');
  }

  /**
   * Moves the timeline's clock to `seconds` (wrapped with loop, clamped to 0..duration without) and sets the face to
   * the values there, playing or not. A non-finite time throws and changes nothing.
   */
  seek(seconds: number): void {
    const player = this.timelinePlayer();
    if (typeof seconds !== 'number' || !Number.isFinite(seconds))
      throw new Error(`seek: needs a finite number of seconds, got ${String(seconds)}`);
    if (!player.timeline()) throw new Error('seek: no timeline is loaded (setTimeline first)');
    player.seek(seconds);
    this.emit('timeline');
  }

  /** Whether a timeline is loaded and plays, its clock and duration (seconds) and loop flag. */
  timelineState(): TimelineState {
    return this.timelinePlayer().state();
  }

  /**
   * Starts or stops the eye simulation (thesis 5.3.3): random blinks through the lids and gaze saccades, added on top
   * of the sliders. Off by default, so that pictures of the face are repeatable. `options` (seed, blink intervals and
   * phases, fixation and saccade times, gaze range, how far the lids follow the gaze; README, "Eye simulation") replace
   * the simulation's over its defaults, and it starts afresh; bad ones throw, naming the option, and change nothing.
   */
  setEyeSimulation(on: boolean, options?: Partial<EyeSimulationOptions>): void {
    if (typeof on !== 'boolean') throw new Error(`setEyeSimulation: needs a boolean, got ${String(on)}`);
    if (options !== undefined) checkEyeSimulationOptions(options, 'setEyeSimulation');
    this.running();
    this.eyeSimulation().setEnabled(on, options);
    this.emit('eyes');
  }

  /** Whether the eye simulation runs. */
  getEyeSimulation(): boolean {
    this.alive();
    return this.eyes?.enabled() ?? false;
  }

  /** The eye simulation's blink and saccade counts and the gaze now. */
  eyeStats(): EyeStats {
    return this.eyeSimulation().stats();
  }

  /**
   * Records the timeline frame by frame (see the README's "Video"): a WebM video (VP9, else VP8) or a zip of PNG
   * frames of `width` x `height`, `fps` frames a second, for `seconds` or the timeline's duration. `timeline` loads
   * one first, as `setTimeline` does. The solver runs a fixed number of frames per video frame, so a slow machine
   * records the same video as a fast one; the eye simulation is off meanwhile. Bad options reject naming the option
   * and change nothing; aborting `signal` stops the recording, which then rejects with the signal's reason.
   */
  async recordVideo(options: VideoOptions = {}): Promise<Blob> {
    const o = checkVideoOptions(options);
    const player = this.timelinePlayer();
    if (!this.recorder) throw new Error('recordVideo: the face is not ready yet: await face.ready first');
    if (this.recorder.recording()) throw new Error('recordVideo: a recording is already running');
    if (o.timeline === null && o.seconds === 0 && !player.timeline()) {
      throw new Error(
        'recordVideo: seconds: give a length in seconds, or a timeline to record (the timeline option, or setTimeline first)',
      );
    }
    o.signal?.throwIfAborted();
    if (o.timeline !== null) this.setTimeline(o.timeline, 'recordVideo: timeline');
    return this.recorder.record(o, o.seconds > 0 ? o.seconds : player.state().duration);
  }

  /** Whether a recording is running. */
  isRecording(): boolean {
    return this.recorder?.recording() ?? false;
  }

  /** A PNG of the canvas, rendered just before it is read. */
  savePNG(): Promise<Blob> {
    return this.shown().snapshot();
  }

  /**
   * Exports the head (skin, eyes, teeth) as glTF (see the README's "Export to glTF"): each Action Unit and preset
   * asked for becomes a morph target named after it, holding the skin it gives on its own at 1 once settled, and the
   * timeline (the loaded one, unless `timeline` is false) becomes an animation of the morph weights. Every target is
   * solved from the neutral face in turn, so this takes a while (`onProgress`, `signal`); the face shows it, and gets
   * its expression back afterwards. Bad options reject naming the option, changing nothing.
   */
  async exportGLTF(options?: GLTFExportOptions): Promise<Blob> {
    const o = checkExportOptions(options);
    this.alive();
    await this.ready;
    const writer = this.gltfWriter;
    if (!writer) throw new Error('exportGLTF: the face has no head to export yet');
    return bakeGLTF(
      {
        expression: this.expressed(),
        simulation: this.running(),
        player: this.timelinePlayer(),
        writer,
        eyes: this.eyes,
        presets: this.listPresets().map((p) => p.name),
        expressionChanged: () => this.emit('expression'),
        restorePreview: () => this.editor.applyPreview(),
        alive: () => !this.disposed,
        begin: () => {
          if (this.exporting) throw new Error('exportGLTF: another export is under way');
          this.exporting = true;
        },
        end: () => {
          this.exporting = false;
        },
      },
      o,
    );
  }

  // ---- the rig editor ----------------------------------------------------------------------------------------

  /**
   * Switches the muscle editor on or off: on, every muscle is drawn, a click on one selects it and a gizmo moves,
   * turns or scales the selected muscle's part; off, the display is as `setMuscleDisplay` asked.
   */
  setEditor(on: boolean): void {
    this.alive();
    this.editor.setEnabled(on);
    this.showMuscles();
    this.emit('editor');
  }

  /** Whether the editor is on. */
  getEditor(): boolean {
    this.alive();
    return this.editor.enabled();
  }

  /** Selects a muscle by name for the gizmo and the Muscle panel, or `null` for none; an unknown name throws. */
  selectMuscle(name: string | null): void {
    this.alive();
    this.editor.select(name);
    this.emit('editor');
  }

  /** The selected muscle's name, or null. */
  getSelectedMuscle(): string | null {
    this.alive();
    return this.editor.selection();
  }

  /** What the gizmo does: `translate`, `rotate` or `scale` (what a part cannot do, it ignores). */
  setGizmoMode(mode: GizmoMode): void {
    this.alive();
    this.editor.setGizmoMode(mode);
    this.emit('editor');
  }

  /** Attaches the gizmo to a part of the selected muscle (see GizmoPart); a part it does not have throws. */
  setGizmoPart(part: GizmoPart): void {
    this.alive();
    this.editor.setGizmoPart(part);
    this.emit('editor');
  }

  /**
   * Contracts the selected muscle by at least `value` (0..1) while it is edited, on top of the Action Units (0 ends
   * it); it follows the selection.
   */
  setPreviewContraction(value: number): void {
    this.alive();
    this.editor.setPreviewContraction(value);
    this.emit('editor');
  }

  /** With `on`, the gizmo's and the Muscle panel's edits also reflect the muscle onto its left/right twin. */
  setMirrorEdits(on: boolean): void {
    this.alive();
    this.editor.setMirrorEdits(on);
    this.emit('editor');
  }

  getMirrorEdits(): boolean {
    this.alive();
    return this.editor.mirrorEdits();
  }

  /**
   * Sets the vertex brush (see BrushOptions; `radius` from 0.001 to 0.05 m): while it is on, dragging over the skin
   * paints the selected muscle's influence instead of turning the view. Bad input throws and changes nothing.
   */
  setBrush(partial: Partial<BrushOptions>): void {
    this.alive();
    this.editor.setBrush(partial);
    this.emit('editor');
  }

  getBrush(): BrushOptions {
    this.alive();
    return this.editor.getBrush();
  }

  /** The editor's state and where its gizmo is on the page (read-only: for tests and tools). */
  describeEditor(): EditorState {
    this.alive();
    return this.editor.describe();
  }

  /** Whether the rig differs from the one the face was made with (its `rig` option, or the package's). */
  isRigEdited(): boolean {
    this.alive();
    return this.editor.isRigEdited();
  }

  /** Brings back the rig the face was made with (one undoable step). */
  revertRig(): void {
    this.alive();
    this.editor.revertRig();
  }

  /** Where a shown muscle's glyph can be clicked on the page, in client pixels, or null (read-only: for tests). */
  locateMuscle(name: string): { x: number; y: number } | null {
    this.alive();
    return this.editor.locateMuscle(name);
  }

  /** A plain copy of the current rig document (changing it changes nothing). */
  getRig(): Rig {
    return structuredClone(this.document().rig) as Rig;
  }

  /**
   * Replaces the rig by a rig document, as JSON text or an object (one undoable step). It is checked whole first: a
   * problem throws a `RigError` naming its path (`setRig: muscles[3].radii[1]: expected ...`; `source`, such as a
   * file's name, replaces `setRig` there) and changes nothing.
   */
  setRig(rig: string | Rig, source = 'setRig'): void {
    if (typeof source !== 'string') throw new Error(`setRig: source must be a string, got ${String(source)}`);
    const doc = this.document();
    doc.replace(typeof rig === 'string' ? parseRigText(rig, source) : rig, source);
  }

  /**
   * Changes some fields of a muscle (`{ insertion: [x, y, z] }`, `{ strength: 0.3 }`, `{ name: 'new-name' }`); with
   * `{ mirror: true }` its left/right twin follows across x = 0. Only that muscle is recomputed on the skin. A bad
   * value throws naming its path and changes nothing.
   */
  updateMuscle(name: string, partial: Partial<Muscle>, options: UpdateOptions = {}): void {
    this.document().updateMuscle(name, partial, options);
  }

  /** Adds a muscle (checked as in a rig document), linked to the Action Unit `actionUnit` on its side if given. */
  addMuscle(muscle: Muscle, actionUnit: string | null = null, weight = 1): void {
    this.document().addMuscle(muscle, actionUnit, weight);
  }

  /**
   * Adds a new muscle of `type` (`linear`, `sphincter`, `lid`, `jaw`) where the view looks at the skin, linked to no
   * Action Unit, and selects it; returns its name (`new-sphincter`, `new-sphincter-2`, ... with `-l` / `-r` off the
   * midline).
   */
  createMuscle(type: Muscle['type']): string {
    this.alive();
    const name = this.editor.createMuscle(type);
    this.emit('editor');
    return name;
  }

  /** Removes a muscle and its Action Unit links (refused, naming the unit, if a unit would be left without muscles). */
  removeMuscle(name: string): void {
    this.document().removeMuscle(name);
  }

  /** Renames a muscle; its links and the selection follow. */
  renameMuscle(name: string, newName: string): void {
    this.alive();
    const wasSelected = this.editor.selection() === name;
    this.editor.renameMuscle(name, newName);
    if (wasSelected) this.emit('editor');
  }

  /** Adds a copy of a muscle, 4 mm higher and linked to no Action Unit; returns its name. */
  duplicateMuscle(name: string): string {
    return this.document().duplicateMuscle(name);
  }

  /** Links a muscle to one Action Unit (on its own side for a bilateral unit) with `weight`, or to none (`null`). */
  assignMuscle(name: string, actionUnit: string | null, weight = 1): void {
    this.document().assignMuscle(name, actionUnit, weight);
  }

  /** Reflects a muscle onto its left/right twin across x = 0 (replaced, or added); returns the twin's name. */
  mirrorMuscle(name: string): string {
    return this.document().mirrorMuscle(name);
  }

  /** Reflects every muscle of one side onto the other. */
  mirrorSide(from: 'left' | 'right'): void {
    this.document().mirrorSide(from);
  }

  /** Starts one undo step made of several edits (a drag); `endEdit` closes it. */
  beginEdit(): void {
    this.document().begin();
  }

  endEdit(): void {
    this.document().end();
    // The step is in the history now (the panels' undo counts).
    this.emit('editor');
  }

  /** Undoes the last rig edit; returns whether there was one. */
  undo(): boolean {
    return this.document().undo();
  }

  /** Redoes the last undone rig edit; returns whether there was one. */
  redo(): boolean {
    return this.document().redo();
  }

  /** The current rig as a JSON document (the text a rig file holds). */
  exportRig(): string {
    return this.document().toJSON();
  }

  private document(): RigDocument {
    this.alive();
    return this.editor.document();
  }

  /** Makes the glyphs show the muscles the display asks for (none until the glyphs and the expression are attached). */
  private showMuscles(): void {
    if (!this.muscles) return;
    const d = this.muscleDisplay;
    if (d.all || this.editor.enabled()) this.muscles.setVisible('all');
    else if (!this.expression || d.actionUnits.length === 0) this.muscles.setVisible('none');
    else this.muscles.setVisible(new Set(shownMuscleNames(this.expression.rig, d)));
  }

  private timelinePlayer(): FaceTimeline {
    this.expressed();
    if (!this.player) throw new Error('the face has no timeline player yet: await face.ready first');
    return this.player;
  }

  private eyeSimulation(): FaceEyes {
    this.alive();
    if (!this.eyes) throw new Error('the face has no eye simulation yet: await face.ready first');
    return this.eyes;
  }

  private emit(change: FaceChange): void {
    const listeners = this.listeners;
    for (let i = 0; i < listeners.length; i++) listeners[i](change);
  }

  private shown(): FaceView {
    this.alive();
    if (!this.view) throw new Error('the face has no view yet');
    return this.view;
  }

  private shellSide(): FaceShell {
    this.alive();
    if (!this.shell) throw new Error('the face has no element yet');
    return this.shell;
  }

  private headSide(): FaceHeads {
    this.alive();
    if (!this.heads) throw new Error('the face is not ready yet: await face.ready first');
    return this.heads;
  }

  private running(): SkinSimulation {
    this.alive();
    if (!this.simulation) throw new Error('the face is not ready yet: await face.ready first');
    return this.simulation;
  }

  private expressed(): FaceExpression {
    this.running();
    return this.expression!;
  }

  private alive(): void {
    if (this.disposed) throw new Error('the face was disposed');
  }
}
