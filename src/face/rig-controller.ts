import { refusal } from '../core/check';
import type { RigDocument, UpdateOptions } from '../core/rig/rig-document';
import { parseRigText } from '../core/rig/rig-schema';
import type { Muscle, Rig } from '../core/rig/rig-types';
import type { EditorSession } from './editor-session';
import type { FaceParts } from './face-parts';

/** The face's rig as a document: read it, replace it, edit its muscles and links, undo and redo. */
export class RigController {
  constructor(
    private readonly parts: FaceParts,
    private readonly session: EditorSession,
  ) {}

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
    if (typeof source !== 'string') throw refusal('setRig', 'source', 'a string', source);
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

  /** Removes a muscle and its Action Unit links (refused, naming the unit, if a unit would be left without muscles). */
  removeMuscle(name: string): void {
    this.document().removeMuscle(name);
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

  /** Closes the undo step `beginEdit` started. */
  endEdit(): void {
    this.document().end();
    // The step is in the history now (the panels' undo counts).
    this.parts.emit('editor');
  }

  /** Undoes the last rig edit; returns whether there was one. */
  undo(): boolean {
    return this.document().undo();
  }

  /** Redoes the last undone rig edit; returns whether there was one. */
  redo(): boolean {
    return this.document().redo();
  }

  /**
   * Forgets the rig's undo and redo steps: undo then stops at the rig as it is now, as an editor's "clear history"
   * does after a document is saved or loaded. Refused while an edit `beginEdit` started is open.
   */
  clearRigHistory(): void {
    this.document().clearHistory();
    // The panels' undo and redo counts.
    this.parts.emit('editor');
  }

  /** The current rig as a JSON document (the text a rig file holds). */
  exportRig(): string {
    return this.document().toJSON();
  }

  private document(): RigDocument {
    this.parts.alive();
    return this.session.document();
  }
}

/** The handle's methods that RigController answers. */
export const RIG_METHODS = [
  'getRig',
  'setRig',
  'updateMuscle',
  'addMuscle',
  'removeMuscle',
  'duplicateMuscle',
  'assignMuscle',
  'mirrorMuscle',
  'mirrorSide',
  'beginEdit',
  'endEdit',
  'undo',
  'redo',
  'clearRigHistory',
  'exportRig',
] as const;
