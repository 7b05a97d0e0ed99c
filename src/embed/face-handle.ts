import { ExpressionState, type ActionUnitListing, type PresetListing } from '../core/facs';
import type { Rig } from '../core/rig-types';
import type { SkinParameters } from '../core/solver';
import type { SkinSimulation, SkinSimulationStats } from '../worker/skin-simulation';

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
 * A face on the page, as scripts (and the tests) drive it: `window.face`. The embedding API will hand out the same
 * object. Vertices are simulation vertex indices, the order of `getSkin().rest`.
 */
export class FaceHandle {
  /** Resolves once the head is shown and its skin solver runs; rejects if either fails. */
  readonly ready: Promise<void>;
  private simulation: SkinSimulation | undefined;
  private rig: Rig | undefined;
  private expression = new ExpressionState();
  /** Contraction per rig muscle, reused for every change. */
  private contractions = new Float32Array(0);
  /** Called with the rig's muscle contractions whenever they change (the page turns the jaw's teeth with them). */
  onContractions: ((contractions: Float32Array) => void) | undefined;
  private resolveReady!: () => void;
  private rejectReady!: (error: Error) => void;

  constructor() {
    this.ready = new Promise<void>((resolve, reject) => {
      this.resolveReady = resolve;
      this.rejectReady = reject;
    });
    // The page reports a failed start itself; this keeps an unobserved rejection from being logged a second time.
    this.ready.catch(() => {});
  }

  /** Connects the running simulation (driving `rig`'s muscles, if given) and resolves `ready`. */
  attach(simulation: SkinSimulation, rig?: Rig): void {
    this.simulation = simulation;
    if (rig) {
      this.rig = rig;
      this.expression = new ExpressionState(rig.presets);
      this.contractions = new Float32Array(rig.muscles.length);
    }
    this.resolveReady();
  }

  /** Rejects `ready`: the face could not start. */
  fail(error: Error): void {
    this.rejectReady(error);
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
  }

  /**
   * Sets an Action Unit's intensity, 0..1 (clamped): `AU12` drives both sides, `AU12L` and `AU12R` one (the subject's
   * left is +x). An unknown id or a non-finite value throws an error naming it and changes nothing.
   */
  setActionUnit(id: string, value: number): void {
    this.running();
    this.expression.setActionUnit(id, value);
    this.drive();
  }

  /** The Action Unit sliders, per side: `{ AU1L: 0, AU1R: 0, ..., AU17: 0, ... }`. */
  getActionUnits(): Record<string, number> {
    return this.expression.getActionUnits();
  }

  /** Every Action Unit: id, FACS number, name and sides (`L`, `R` or `M`). */
  listActionUnits(): ActionUnitListing[] {
    return this.expression.listActionUnits();
  }

  /** Sets a preset's weight, 0..1 (clamped); presets and Action Units add up (and clamp) per side. */
  applyPreset(name: string, weight = 1): void {
    this.running();
    this.expression.applyPreset(name, weight);
    this.drive();
  }

  /** The rig's presets with their current weights. */
  listPresets(): PresetListing[] {
    return this.expression.listPresets();
  }

  /** Zeroes every Action Unit and preset: the neutral face. */
  reset(): void {
    this.running();
    this.expression.reset();
    this.drive();
  }

  /** Sends the muscle contractions the current Action Units and presets add up to. */
  private drive(): void {
    const simulation = this.running();
    if (!this.rig) throw new Error('the face has no muscle rig: Action Units cannot move it');
    simulation.setContractions(this.expression.muscleContractions(this.rig, this.contractions));
    this.onContractions?.(this.contractions);
  }

  private running(): SkinSimulation {
    if (!this.simulation) throw new Error('the face is not ready yet: await face.ready first');
    return this.simulation;
  }
}

declare global {
  interface Window {
    /** The page's face, for scripts and tests. */
    face: FaceHandle;
  }
}
