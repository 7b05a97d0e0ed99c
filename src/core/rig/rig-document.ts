/**
 * The rig as an editor changes it: every edit makes a new rig, checked whole by the rig schema before it replaces the
 * current one (a refused edit throws a `RigError` naming the path and changes nothing), with undo and redo of whole
 * steps and transactions that make a drag one step. Pure: no DOM, no three.js.
 */
import { ACTION_UNITS } from '../expression/facs';
import { EditHistory } from './edit-history';
import { mirrorMuscle, otherSide, twinName } from './rig-mirror';
import { RigError } from './rig-problems';
import { parseRig } from './rig-schema';
import type { ActionUnitDefinition, Muscle, MuscleSide, Rig, Vec3 } from './rig-types';

/**
 * What an edit changed: only some muscles' shapes (`muscles`, their indices; the rig's names, order, Action Units and
 * presets are as before, so a solver can update those muscles alone), or more (`structure`: muscles added, removed,
 * renamed or reordered, or the Action Units or presets changed).
 */
export type RigChange = { kind: 'muscles'; indices: number[] } | { kind: 'structure' };

/** Told after every change of the current rig, with the new rig. */
export type RigListener = (change: RigChange, rig: Rig) => void;

/** Options of `updateMuscle`. */
export interface UpdateOptions {
  /** Also reflect the edited muscle onto its left/right twin across x = 0, if the rig has one (one step for both). */
  mirror?: boolean;
}

/** Undo steps kept by default: more than the 100 an editing session is promised. */
const RIG_HISTORY_LIMIT = 200;

const MUSCLE_TYPES = ['linear', 'sphincter', 'lid', 'jaw'] as const;

/**
 * A new muscle of `type` centred near `at` (metres, the model's frame), sized for a face: a 3 cm linear muscle
 * pulling up and out, a 2 cm sphincter, a lid or a small jaw box. Its side follows x (mid within 5 mm of the midline).
 */
export function newMuscle(type: Muscle['type'], name: string, at: Vec3): Muscle {
  if (!MUSCLE_TYPES.includes(type))
    throw new Error(`newMuscle: type must be one of ${MUSCLE_TYPES.join(', ')}, got ${JSON.stringify(type)}`);
  const [x, y, z] = at;
  const side: MuscleSide = x > 0.005 ? 'left' : x < -0.005 ? 'right' : 'mid';
  const outward = x >= 0 ? 1 : -1;
  switch (type) {
    case 'linear':
      return {
        name,
        side,
        type,
        origin: [x + 0.02 * outward, y + 0.02, z - 0.01],
        insertion: [x, y, z],
        angle: 20,
        falloffStart: 0.8,
        falloffEnd: 1.2,
        strength: 0.2,
        normalWeight: 0.2,
      };
    case 'sphincter':
      return {
        name,
        side,
        type,
        center: [x, y, z],
        rotation: [0, 0, 0],
        radii: [0.02, 0.012, 0.012],
        innerRadii: [0.01, 0.006, 0.006],
        scale: [1, 1, 0],
        strength: 0.2,
        normalWeight: 0.2,
      };
    case 'lid':
      return { name, side, type, center: [x, y, z], rotation: [0, 0, 0], radii: [0.02, 0.012, 0.015], maxAngle: 30, innerFraction: 0.5 };
    case 'jaw':
      return { name, side, type, center: [x, y, z], rotation: [0, 0, 0], size: [0.08, 0.05, 0.08], maxAngle: 15, curve: 0, fade: 0.01 };
  }
}

/** Freezes a rig and everything in it: rigs are shared by reference and must never change in place. */
function deepFreeze<T>(x: T): T {
  if (typeof x === 'object' && x !== null && !Object.isFrozen(x)) {
    Object.freeze(x);
    for (const value of Object.values(x)) deepFreeze(value);
  }
  return x;
}

const same = (a: unknown, b: unknown): boolean => JSON.stringify(a) === JSON.stringify(b);

/** What changed from `a` to `b`, or null if nothing did. */
function rigChange(a: Rig, b: Rig): RigChange | null {
  const sameNames = a.muscles.length === b.muscles.length && a.muscles.every((m, i) => m.name === b.muscles[i].name);
  if (!sameNames || !same(a.actionUnits, b.actionUnits) || !same(a.presets, b.presets) || a.version !== b.version)
    return { kind: 'structure' };
  const indices: number[] = [];
  a.muscles.forEach((m, i) => {
    if (!same(m, b.muscles[i])) indices.push(i);
  });
  return indices.length > 0 ? { kind: 'muscles', indices } : null;
}

/** A rig being edited: its current state, the edits that change it, and their history. */
export class RigDocument {
  private current: Rig;
  private readonly history: EditHistory<Rig>;
  private readonly listeners: RigListener[] = [];

  /** `rig` is checked as a document is; throws a `RigError` if it is not valid. */
  constructor(rig: unknown, options: { historyLimit?: number; source?: string } = {}) {
    this.current = deepFreeze(parseRig(rig, options.source ?? 'rig'));
    this.history = new EditHistory<Rig>(options.historyLimit ?? RIG_HISTORY_LIMIT);
  }

  /** The current rig (frozen: copy it to change it, or use the edits below). */
  get rig(): Rig {
    return this.current;
  }

  /** Calls `listener` after every change of the current rig; returns the function that stops it. */
  onChange(listener: RigListener): () => void {
    this.listeners.push(listener);
    return () => {
      const i = this.listeners.indexOf(listener);
      if (i >= 0) this.listeners.splice(i, 1);
    };
  }

  /** The index of the named muscle; throws naming it if there is none. */
  indexOf(name: string, what = 'rig'): number {
    const i = this.current.muscles.findIndex((m) => m.name === name);
    if (i < 0) throw new Error(`${what}: no muscle named ${JSON.stringify(name)}`);
    return i;
  }

  /** The named muscle (frozen); throws if there is none. */
  muscle(name: string): Muscle {
    return this.current.muscles[this.indexOf(name)];
  }

  /** Replaces the whole rig (one undoable step); a document that is not valid throws naming its path, changing nothing. */
  replace(rig: unknown, source = 'setRig'): void {
    this.commit(parseRig(rig, source));
  }

  /**
   * Changes some fields of the named muscle: `{ insertion: [x, y, z] }`, `{ strength: 0.3 }`. A new `name` renames it
   * (its Action Unit links follow), a new `side` moves its links of bilateral units to that side. With `mirror`, its
   * twin across x = 0 follows in the same step.
   */
  updateMuscle(name: string, partial: Partial<Muscle>, options: UpdateOptions = {}): void {
    const what = 'updateMuscle';
    if (typeof partial !== 'object' || partial === null || Array.isArray(partial))
      throw new Error(`${what}: needs an object of muscle fields, got ${String(partial)}`);
    this.edit(what, (rig) => {
      const i = this.indexOf(name, what);
      const before = rig.muscles[i];
      const after = { ...before, ...partial } as Muscle;
      rig.muscles[i] = after;
      if (after.name !== before.name) renameLinks(rig, before.name, after.name);
      if (after.side !== before.side) resideLinks(rig, after.name, after.side);
      if (options.mirror) {
        const twin = twinName(after.name);
        const j = twin === undefined ? -1 : rig.muscles.findIndex((m) => m.name === twin);
        if (j >= 0 && j !== i) rig.muscles[j] = mirrorMuscle(after, twin);
      }
    });
  }

  /** Adds a muscle at the end, linked to nothing unless `actionUnit` is given (see `assignMuscle`). */
  addMuscle(muscle: Muscle, actionUnit: string | null = null, weight = 1): void {
    const what = 'addMuscle';
    if (typeof muscle !== 'object' || muscle === null || Array.isArray(muscle))
      throw new Error(`${what}: needs a muscle object, got ${String(muscle)}`);
    this.edit(what, (rig) => {
      rig.muscles.push(structuredClone(muscle));
      if (actionUnit !== null) link(rig, muscle.name, actionUnit, weight, what);
    });
  }

  /** Removes the named muscle and its Action Unit links (refused if a unit would be left without muscles). */
  removeMuscle(name: string): void {
    const what = 'removeMuscle';
    this.edit(what, (rig) => {
      rig.muscles.splice(this.indexOf(name, what), 1);
      unlink(rig, name);
    });
  }

  /** Renames a muscle; its Action Unit links follow. */
  renameMuscle(name: string, newName: string): void {
    this.updateMuscle(name, { name: newName });
  }

  /** Adds a copy of the named muscle, 4 mm higher and linked to nothing; returns the copy's name. */
  duplicateMuscle(name: string, newName?: string): string {
    const source = this.muscle(name);
    const copyName = newName ?? this.freeName(name);
    const copy = structuredClone(source) as Muscle & Record<string, unknown>;
    copy.name = copyName;
    for (const key of ['origin', 'insertion', 'center', 'joint']) {
      const p = copy[key] as Vec3 | undefined;
      if (p) copy[key] = [p[0], p[1] + 0.004, p[2]];
    }
    this.addMuscle(copy);
    return copyName;
  }

  /**
   * Links the named muscle to one Action Unit (`AU12`), on its own side for a bilateral unit, with `weight`;
   * `null` unlinks it from every unit. Its previous links are replaced. A unit of the catalogue that the rig lacks is
   * added.
   */
  assignMuscle(name: string, actionUnit: string | null, weight = 1): void {
    const what = 'assignMuscle';
    this.edit(what, (rig) => {
      this.indexOf(name, what);
      unlink(rig, name);
      if (actionUnit !== null) link(rig, name, actionUnit, weight, what);
    });
  }

  /**
   * Reflects the named muscle onto its twin across x = 0 (`-l` <-> `-r`): the twin is replaced, or added with the
   * mirrored links of its bilateral Action Units. Returns the twin's name.
   */
  mirrorMuscle(name: string): string {
    const what = 'mirrorMuscle';
    const twin = twinName(name);
    if (twin === undefined) throw new Error(`${what}: ${JSON.stringify(name)} has no twin (only names ending in -l or -r do)`);
    this.edit(what, (rig) => copyToTwin(rig, rig.muscles[this.indexOf(name, what)], twin));
    return twin;
  }

  /** Reflects every muscle of one side onto the other (one step): twins are replaced or added. */
  mirrorSide(from: 'left' | 'right'): void {
    const what = 'mirrorSide';
    if (from !== 'left' && from !== 'right') throw new Error(`${what}: expected "left" or "right", got ${JSON.stringify(from)}`);
    this.edit(what, (rig) => {
      for (const m of rig.muscles.filter((m) => m.side === from)) {
        const twin = twinName(m.name);
        if (twin !== undefined) copyToTwin(rig, m, twin);
      }
    });
  }

  /** Opens a transaction: the edits until `end()` are one undo step (a drag). They nest. */
  begin(): void {
    this.history.begin(this.current);
  }

  end(): void {
    this.history.end();
  }

  get canUndo(): boolean {
    return this.history.canUndo;
  }

  get canRedo(): boolean {
    return this.history.canRedo;
  }

  /** Steps that can be undone and redone now. */
  historySizes(): { undo: number; redo: number } {
    return this.history.sizes;
  }

  /** Forgets every undo and redo step: undo then stops at the rig as it is now. Refused while an edit is open. */
  clearHistory(): void {
    if (this.history.inTransaction) throw new Error('clearRigHistory: an edit is open (beginEdit without endEdit)');
    this.history.clear();
  }

  /** Goes back one step; returns whether there was one. */
  undo(): boolean {
    const rig = this.history.undo(this.current);
    if (!rig) return false;
    this.set(rig);
    return true;
  }

  /** Goes forward one undone step; returns whether there was one. */
  redo(): boolean {
    const rig = this.history.redo(this.current);
    if (!rig) return false;
    this.set(rig);
    return true;
  }

  /** The rig as a JSON document, indented. */
  toJSON(): string {
    return JSON.stringify(this.current, null, 2);
  }

  /** A name not taken yet, from `name`: `x-copy`, `x-copy-2`, ... (a side suffix stays last: `x-copy-l`). */
  freeName(name: string, word = 'copy'): string {
    const suffix = /-[lr]$/.exec(name)?.[0] ?? '';
    const stem = suffix ? name.slice(0, -2) : name;
    const taken = new Set(this.current.muscles.map((m) => m.name));
    for (let k = 1; ; k++) {
      const candidate = `${stem}-${word}${k === 1 ? '' : `-${k}`}${suffix}`;
      if (!taken.has(candidate)) return candidate;
    }
  }

  /** Applies `change` to a copy of the rig and commits it if the schema accepts it. */
  private edit(what: string, change: (rig: Rig) => void): void {
    const draft = structuredClone(this.current) as Rig;
    change(draft);
    this.commit(parseRig(draft, what));
  }

  private commit(next: Rig): void {
    if (rigChange(this.current, next) === null) return;
    this.history.record(this.current);
    this.set(next);
  }

  private set(next: Rig): void {
    const change = rigChange(this.current, next);
    this.current = deepFreeze(next);
    if (change === null) return;
    for (const listener of this.listeners.slice()) listener(change, next);
  }
}

/** Renames a muscle in every Action Unit link. */
function renameLinks(rig: Rig, from: string, to: string): void {
  for (const au of rig.actionUnits) for (const l of au.muscles) if (l.muscle === from) l.muscle = to;
}

/** Moves a muscle's links of bilateral units to its new side. */
function resideLinks(rig: Rig, name: string, side: MuscleSide): void {
  for (const au of rig.actionUnits) if (au.bilateral) for (const l of au.muscles) if (l.muscle === name) l.side = side;
}

/** Removes every link to the named muscle. */
function unlink(rig: Rig, name: string): void {
  for (const au of rig.actionUnits) au.muscles = au.muscles.filter((l) => l.muscle !== name);
}

/** Links a muscle to an Action Unit, adding the unit from the catalogue if the rig lacks it. */
function link(rig: Rig, name: string, actionUnit: string, weight: number, what: string): void {
  let au = rig.actionUnits.find((a) => a.id === actionUnit);
  if (!au) {
    const known = ACTION_UNITS.find((a) => a.id === actionUnit);
    if (!known)
      throw new RigError(what, [
        { path: 'actionUnits', message: `no Action Unit ${JSON.stringify(actionUnit)} in the rig or the catalogue` },
      ]);
    au = { id: known.id, name: known.name, bilateral: known.bilateral, muscles: [] } satisfies ActionUnitDefinition;
    rig.actionUnits.push(au);
  }
  const muscle = rig.muscles.find((m) => m.name === name);
  au.muscles.push({ muscle: name, side: au.bilateral ? (muscle?.side ?? 'mid') : 'mid', weight });
}

/** Writes `source` mirrored as `twin`: replaced in place, or added with the mirrored links of its bilateral units. */
function copyToTwin(rig: Rig, source: Muscle, twin: string): void {
  const mirrored = mirrorMuscle(source, twin);
  const j = rig.muscles.findIndex((m) => m.name === twin);
  if (j >= 0) {
    rig.muscles[j] = mirrored;
    return;
  }
  rig.muscles.push(mirrored);
  for (const au of rig.actionUnits) {
    if (!au.bilateral) continue;
    for (const l of au.muscles.filter((l) => l.muscle === source.name))
      au.muscles.push({ muscle: twin, side: otherSide(l.side), weight: l.weight });
  }
}
