import { checkBoolean } from '../core/check';
import { checkEyeSimulationOptions, type EyeSimulationOptions } from '../core/expression/eye-simulation';
import type { FaceParts } from './face-parts';
import type { EyeStats } from './face-ports';

/** The eye simulation: switched on and off, its options, what it has done. */
export class EyesController {
  constructor(private readonly parts: FaceParts) {}

  /**
   * Starts or stops the eye simulation (thesis 5.3.3): random blinks through the lids and gaze saccades, added on top
   * of the sliders. Off by default, so that pictures of the face are repeatable. `options` (seed, blink intervals and
   * phases, fixation and saccade times, gaze range, how far the lids follow the gaze; docs/features.md, "Eye simulation") replace
   * the simulation's over its defaults, and it starts afresh; bad ones throw, naming the option, and change nothing.
   */
  setEyeSimulation(on: boolean, options?: Partial<EyeSimulationOptions>): void {
    checkBoolean('setEyeSimulation', '', on);
    if (options !== undefined) checkEyeSimulationOptions(options, 'setEyeSimulation');
    this.parts.running();
    this.parts.eyeSimulation().setEnabled(on, options);
    this.parts.emit('eyes');
  }

  /** Whether the eye simulation runs. */
  getEyeSimulation(): boolean {
    this.parts.alive();
    return this.parts.eyes?.enabled() ?? false;
  }

  /** The eye simulation's blink and saccade counts and the gaze now. */
  eyeStats(): EyeStats {
    return this.parts.eyeSimulation().stats();
  }
}

/** The handle's methods that EyesController answers. */
export const EYES_METHODS = ['setEyeSimulation', 'getEyeSimulation', 'eyeStats'] as const;
