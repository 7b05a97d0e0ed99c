import type { RigChange, RigDocument } from '../core/rig/rig-document';
import type { Rig } from '../core/rig/rig-types';
import type { MuscleView } from '../render/muscle-view';
import type { SkinSimulation } from '../sim/main/skin-simulation';
import type { FaceExpression } from './face-expression';

/** What an edited rig reaches on a face: the solver, the glyphs, the expression, and the jaw's teeth. */
export interface RigTargets {
  simulation: SkinSimulation;
  muscles: MuscleView;
  expression: FaceExpression;
  /** A jaw muscle changed: the teeth must turn about its new hinge. */
  jawChanged(rig: Rig): void;
}

/**
 * Applies every change of a rig document to a running face. A change of some muscles' shapes (a drag) sends only
 * those muscles to the solver, which recomputes their skin alone; anything else (muscles added, removed or renamed,
 * links, presets) sends the new muscle list and the contractions it takes.
 */
export class RigBinding {
  private readonly unsubscribe: () => void;

  constructor(
    document: RigDocument,
    private readonly targets: RigTargets,
  ) {
    this.unsubscribe = document.onChange((change, rig) => this.apply(change, rig));
  }

  dispose(): void {
    this.unsubscribe();
  }

  private apply(change: RigChange, rig: Rig): void {
    const { simulation, muscles, expression } = this.targets;
    if (change.kind === 'muscles') {
      let jaw = false;
      for (const i of change.indices) {
        simulation.updateMuscle(i, rig.muscles[i]);
        muscles.updateMuscle(i, rig.muscles[i]);
        jaw ||= rig.muscles[i].type === 'jaw';
      }
      // The contractions are the same; the expression only needs the new rig object for its next change.
      expression.setRig(rig, jaw);
      if (jaw) this.targets.jawChanged(rig);
      return;
    }
    simulation.setMuscles(rig.muscles);
    muscles.setMuscles(rig.muscles);
    this.targets.jawChanged(rig);
    // Sends the new list's contractions in the same input batch as the list.
    expression.setRig(rig);
  }
}
