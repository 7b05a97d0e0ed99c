import type { SkinParameters } from '../core/solver/skin-parameters';
import type { FaceParts } from './face-parts';
import type { FaceStats, SkinSnapshot } from './face-ports';

/** The face's skin as scripts reach it: its solved shape, its parameters, and targets that pull it. */
export class SkinController {
  constructor(
    private readonly parts: FaceParts,
    private readonly ready: Promise<void>,
  ) {}

  /** Resolves once the skin has converged for every input given so far (rejects after `timeoutMs`, if given). */
  async settle(timeoutMs?: number): Promise<void> {
    await this.ready;
    return this.parts.running().settle(timeoutMs);
  }

  /** A copy of the skin's newest solved shape, in the head's own frame (before the head positions turn it, see `getHeadPose`). */
  getSkin(): SkinSnapshot {
    const simulation = this.parts.running();
    const positions = new Float32Array(simulation.rest.length);
    const normals = new Float32Array(simulation.rest.length);
    simulation.readSimulation(positions, normals);
    return { rest: simulation.rest.slice(), positions, normals, triangles: simulation.triangles.slice() };
  }

  /** The solver now: its mode, vertex, edge and constraint counts, the last frame's time, frames solved, whether it sleeps. */
  stats(): FaceStats {
    return this.parts.running().stats();
  }

  /**
   * Pulls vertices toward targets (xyz each) with a weight from 0 to 1 along the skin's surface and one along its
   * normal (by default the same); throws, changing nothing, on bad input.
   */
  setMuscleTargets(vertices: ArrayLike<number>, targets: ArrayLike<number>, weight = 1, normalWeight = weight): void {
    this.parts.running().setMuscleTargets(vertices, targets, weight, normalWeight);
  }

  /** Lets go of every target `setMuscleTargets` set. */
  clearMuscleTargets(): void {
    this.parts.running().clearMuscleTargets();
  }

  /** Changes some skin parameters; throws, changing nothing, if one is unknown or not a finite number in range. */
  setSkinParameters(partial: Partial<SkinParameters>): void {
    this.parts.running().setParameters(partial);
    this.parts.emit('skin');
  }

  /** The skin parameters as last set. */
  getSkinParameters(): SkinParameters {
    return this.parts.running().parameters();
  }
}

/** The handle's methods that SkinController answers. */
export const SKIN_METHODS = [
  'settle',
  'getSkin',
  'stats',
  'setMuscleTargets',
  'clearMuscleTargets',
  'setSkinParameters',
  'getSkinParameters',
] as const;
