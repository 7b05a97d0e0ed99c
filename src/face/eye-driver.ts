import { Euler, Quaternion, type Object3D } from 'three';
import { DEGREES } from '../core/math3';
import { EyeSimulation, type EyeSimulationOptions } from '../core/expression/eye-simulation';
import { actionUnitGaze, type Gaze } from '../core/expression/gaze';
import type { EyeStats, FaceEyes, FaceHandle } from './face-handle';
import type { FrameHook } from '../render/head-view';

/** Something that runs a hook before every rendered frame (HeadView). */
export interface FrameHooks {
  onFrame(hook: FrameHook): () => void;
}

/** Options of the eye driver. */
export interface EyeDriverOptions {
  /** The state machine's options: seed, timing, gaze range, how far the lids follow the gaze. */
  simulation?: Partial<EyeSimulationOptions>;
  /** Whether to move the lids through the face's overlay (needs a muscle rig); the eyes turn either way. */
  lids?: boolean;
}

const EYE_DRIVER_DEFAULTS: Required<EyeDriverOptions> = { simulation: {}, lids: true };

/** The overlay entries the driver writes: AU43 closes both upper lids, AU5 raises them. */
const LID_IDS: readonly string[] = ['AU43', 'AU5'];

/**
 * Turns the eyes on the page: every frame it reads the eye positions the expression asks for (AU61 to AU66, see
 * gaze.ts) and, while the eye simulation runs, advances its state machine to the frame's time and adds its gaze;
 * it turns the eyeballs about their centres (their nodes sit at the model's eye pivots) and sets the simulation's lid
 * Action Units in the face's overlay, so blinks happen on the skin, through the lid muscles, on top of whatever the
 * sliders say.
 */
export class EyeDriver implements FaceEyes {
  private simulation: EyeSimulation;
  private readonly o: Required<EyeDriverOptions>;
  private readonly rest: Quaternion[];
  private readonly euler = new Euler(0, 0, 0, 'YXZ');
  private readonly rotation = new Quaternion();
  private readonly lidValues = new Float64Array(LID_IDS.length);
  private readonly stopFrames: () => void;
  private on = false;
  /** Frame time at which the simulation's clock reads 0 (NaN until the first frame after switching on). */
  private startedAt = Number.NaN;
  /** The gaze last shown (NaN: none yet), so that a held fixation draws nothing. */
  private shownYaw = Number.NaN;
  private shownPitch = Number.NaN;
  private shownVergence = Number.NaN;
  /** The eye positions' gaze, rewritten every frame. */
  private readonly asked: Gaze = { yaw: 0, pitch: 0, vergence: 0 };

  /** `units` reads an Action Unit's effective intensity by id (`AU61`), as the expression adds it up. */
  constructor(
    private readonly face: FaceHandle,
    frames: FrameHooks,
    private readonly eyes: readonly Object3D[],
    private readonly units: (id: string) => number,
    options: EyeDriverOptions = {},
  ) {
    this.o = { ...EYE_DRIVER_DEFAULTS, ...options };
    this.simulation = new EyeSimulation(this.o.simulation);
    this.rest = eyes.map((e) => e.quaternion.clone());
    this.stopFrames = frames.onFrame((now) => this.frame(now));
  }

  /**
   * Starts (from a fresh clock and zeroed counts) or stops the simulation; stopping puts eyes and lids back. With
   * `simulation` options (checked by the caller), the simulation takes them over the defaults and starts afresh.
   */
  setEnabled(on: boolean, simulation?: Partial<EyeSimulationOptions>): void {
    if (simulation) {
      this.simulation = new EyeSimulation(simulation);
      if (on && this.on) this.on = false;
    }
    if (on === this.on) return;
    this.on = on;
    if (on) {
      this.simulation.reset();
      this.startedAt = Number.NaN;
      this.shownYaw = this.shownPitch = Number.NaN;
    } else this.putBack();
  }

  /**
   * Turns the eyes to the gaze the expression asks for now (with the simulation's, while it runs, as last advanced),
   * without waiting for a frame: for a recorder or a snapshot that draws the next picture itself.
   */
  showGaze(): void {
    actionUnitGaze(this.units, this.asked);
    const s = this.simulation;
    this.turn(this.asked.yaw + (this.on ? s.yaw : 0), this.asked.pitch + (this.on ? s.pitch : 0), this.asked.vergence);
  }

  enabled(): boolean {
    return this.on;
  }

  /** Counts since the simulation was last switched on, and the gaze now. */
  stats(): EyeStats {
    const s = this.simulation;
    return { on: this.on, blinks: s.blinks, saccades: s.saccades, blink: s.blink, time: s.now, gaze: { yaw: s.yaw, pitch: s.pitch } };
  }

  /** Stops following frames, for good: the face it drives is going away, so nothing is put back. */
  dispose(): void {
    this.stopFrames();
    this.on = false;
  }

  /**
   * Moves the eyes (and lids) to the frame's time; returns whether they moved. Between saccades and blinks the eyes
   * hold still, and the view need not draw for them (a face with its eyes alive costs a battery only when they move).
   */
  private frame(now: number): boolean {
    actionUnitGaze(this.units, this.asked);
    if (!this.on) return this.turn(this.asked.yaw, this.asked.pitch, this.asked.vergence);
    if (Number.isNaN(this.startedAt)) this.startedAt = now;
    const s = this.simulation;
    s.advance(now - this.startedAt);
    const close = this.o.lids ? s.lidClose() : 0;
    const raise = this.o.lids ? s.lidRaise() : 0;
    const turned = this.turn(this.asked.yaw + s.yaw, this.asked.pitch + s.pitch, this.asked.vergence);
    if (close === this.lidValues[0] && raise === this.lidValues[1]) return turned;
    this.lidValues[0] = close;
    this.lidValues[1] = raise;
    if (this.o.lids) this.face.setOverlay(LID_IDS, this.lidValues);
    return true;
  }

  /**
   * Turns both eyes to a gaze (degrees; `vergence` turns each toward the nose) unless they show it already; returns
   * whether they turned.
   */
  private turn(yaw: number, pitch: number, vergence: number): boolean {
    if (yaw === this.shownYaw && pitch === this.shownPitch && vergence === this.shownVergence) return false;
    this.shownYaw = yaw;
    this.shownPitch = pitch;
    this.shownVergence = vergence;
    for (let i = 0; i < this.eyes.length; i++) {
      // Yaw about the head's up axis, then pitch about the turned eye's x axis; the left eye (+x) turns toward the
      // nose by turning right.
      const inward = this.eyes[i].name === 'eye-r' ? vergence : -vergence;
      this.euler.set(-pitch * DEGREES, (yaw + inward) * DEGREES, 0);
      this.rotation.setFromEuler(this.euler);
      this.eyes[i].quaternion.multiplyQuaternions(this.rotation, this.rest[i]);
    }
    return true;
  }

  /** The simulation stopped: the eyes go back to the gaze the expression asks for, the lids to the sliders. */
  private putBack(): void {
    this.lidValues.fill(0);
    this.showGaze();
    if (this.o.lids) this.face.clearOverlay();
  }
}
