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

  /** Connects the running simulation and resolves `ready`. */
  attach(simulation: SkinSimulation): void {
    this.simulation = simulation;
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
