import { isActionUnitId, type ActionUnitListing, type PresetListing } from '../core/facs';
import { nextMuscleDisplay, shownMuscleNames, type MuscleDisplay } from '../core/muscle-display';
import type { SkinParameters } from '../core/solver';
import type { RenderTiming } from '../render/head-view';
import type { MaterialDescription } from '../render/materials';
import type { LightOptions, RenderOptions } from '../render/view-options';
import type { SkinSimulation, SkinSimulationStats } from '../worker/skin-simulation';
import { readExpression, type ExpressionEntries } from './expression-hash';
import type { FaceExpression } from './face-expression';

/** The welded skin at one moment, in simulation vertex order. */
export interface SkinSnapshot {
  /** Rest positions, xyz per vertex. */
  rest: Float32Array;
  /** Current positions and unit normals, xyz per vertex. */
  positions: Float32Array;
  normals: Float32Array;
  /** Triangles over the vertices, counter-clockwise from outside. */
  triangles: Uint32Array;
}

export type FaceStats = SkinSimulationStats;

/**
 * What a handle call changed: the Action Units or presets, the light, the render options, the skin parameters,
 * whether the eye simulation runs, or which muscles are shown.
 */
export type FaceChange = 'expression' | 'light' | 'render' | 'skin' | 'eyes' | 'muscles';

export type { MuscleDisplay };

/** The muscle glyphs the handle shows and hides (MuscleView). */
export interface FaceMuscles {
  setVisible(names: ReadonlySet<string> | 'all' | 'none'): void;
  /** The names of the muscles drawn now. */
  shown(): string[];
}

/** What the eye simulation has done since the page started it first: counts, and the gaze now in degrees. */
export interface EyeStats {
  /** Whether it runs. */
  on: boolean;
  /** Blinks and saccades started. */
  blinks: number;
  saccades: number;
  /** Lid closure of the blink now, 0 open .. 1 closed. */
  blink: number;
  /** The simulation's clock: ms of rendered frames since it was switched on. */
  time: number;
  /** Positive yaw looks to the subject's left, positive pitch up. */
  gaze: { yaw: number; pitch: number };
}

/** The eye simulation the handle switches (EyeDriver). */
export interface FaceEyes {
  setEnabled(on: boolean): void;
  enabled(): boolean;
  stats(): EyeStats;
}

/** Told after every successful change made through the handle (panels refresh their sliders with it). */
export type FaceChangeListener = (change: FaceChange) => void;

/** The view the handle drives lights and render options through (HeadView). */
export interface FaceView {
  setLight(partial: Partial<LightOptions>): void;
  lightOptions(): LightOptions;
  setRenderOptions(partial: Partial<RenderOptions>): void;
  renderOptions(): RenderOptions;
  /** Renders a frame and encodes the canvas as a PNG. */
  snapshot(): Promise<Blob>;
  measureRender(frames?: number): RenderTiming;
  describeMaterials(): MaterialDescription[];
}

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
  private muscles: FaceMuscles | undefined;
  private muscleDisplay: MuscleDisplay = { all: false, actionUnits: [] };
  private readonly listeners: FaceChangeListener[] = [];
  private expression: FaceExpression | undefined;
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
   * Connects the muscle glyphs that `setMuscleDisplay` shows, and shows what was asked for so far.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  attachMuscles(muscles: FaceMuscles): void {
    this.muscles = muscles;
    this.showMuscles();
  }

  /** Calls `listener` after every change made through the handle; returns the function that stops it. */
  onChange(listener: FaceChangeListener): () => void {
    this.alive();
    this.listeners.push(listener);
    return () => {
      const i = this.listeners.indexOf(listener);
      if (i >= 0) this.listeners.splice(i, 1);
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
    this.listeners.length = 0;
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

  /** Changes some render options (`wireframe`, `showEyes`, `showTeeth`, booleans); bad input throws and changes nothing. */
  setRenderOptions(partial: Partial<RenderOptions>): void {
    this.shown().setRenderOptions(partial);
    this.emit('render');
  }

  getRenderOptions(): RenderOptions {
    return this.shown().renderOptions();
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
    if (!Number.isInteger(frames) || frames < 1 || frames > 10_000) throw new Error(`measureRender: frames must be an integer within 1..10000, got ${String(frames)}`);
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
      if (typeof values[i] !== 'number' || !Number.isFinite(values[i])) throw new Error(`setOverlay: ${ids[i]} needs a finite number, got ${String(values[i])}`);
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

  /**
   * Starts or stops the eye simulation (thesis 5.3.3): random blinks through the lids and gaze saccades, added on top
   * of the sliders. Off by default, so that pictures of the face are repeatable.
   */
  setEyeSimulation(on: boolean): void {
    if (typeof on !== 'boolean') throw new Error(`setEyeSimulation: needs a boolean, got ${String(on)}`);
    this.running();
    this.eyeSimulation().setEnabled(on);
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

  /** A PNG of the canvas, rendered just before it is read. */
  savePNG(): Promise<Blob> {
    return this.shown().snapshot();
  }

  /** Makes the glyphs show the muscles the display asks for (none until the glyphs and the expression are attached). */
  private showMuscles(): void {
    if (!this.muscles) return;
    const d = this.muscleDisplay;
    if (d.all) this.muscles.setVisible('all');
    else if (!this.expression || d.actionUnits.length === 0) this.muscles.setVisible('none');
    else this.muscles.setVisible(new Set(shownMuscleNames(this.expression.rig, d)));
  }

  private eyeSimulation(): FaceEyes {
    this.alive();
    if (!this.eyes) throw new Error('the face has no eye simulation yet: await face.ready first');
    return this.eyes;
  }

  private emit(change: FaceChange): void {
    // A copy, so that a listener that unsubscribes while being told does not make the next one miss the change.
    for (const listener of this.listeners.slice()) listener(change);
  }

  private shown(): FaceView {
    this.alive();
    if (!this.view) throw new Error('the face has no view yet');
    return this.view;
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
