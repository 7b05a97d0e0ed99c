/**
 * Which muscles the scene shows: every muscle, or those of some Action Units. Pure: the handle checks and keeps the
 * state, the muscle view draws it.
 */

import { checkBoolean, refusal } from '../check';
import { ACTION_UNITS } from '../expression/facs';
import type { Rig } from './rig-types';

/** What is shown: all muscles, and (independently, so that switching `all` off restores them) some Action Units. */
export interface MuscleDisplay {
  /** Whether every muscle of the rig is shown, whatever `actionUnits` lists. */
  all: boolean;
  /** Action Unit ids without a side (`AU12`), in catalogue order. */
  actionUnits: string[];
}

const CATALOGUE_ORDER: ReadonlyMap<string, number> = new Map(ACTION_UNITS.map((au, i) => [au.id, i]));

/**
 * Checks a partial display for `setMuscleDisplay` and returns the whole display it makes of `current`; throws,
 * naming the culprit, on an unknown key, a non-boolean `all`, or an id that is not a catalogue Action Unit (sides
 * like `AU12L` are refused: both sides of a unit are shown together).
 */
export function nextMuscleDisplay(current: MuscleDisplay, partial: unknown): MuscleDisplay {
  const where = 'setMuscleDisplay';
  if (typeof partial !== 'object' || partial === null || Array.isArray(partial))
    throw refusal(where, '', 'an object like { all: true } or { actionUnits: ["AU12"] }', partial);
  const p = partial as Record<string, unknown>;
  for (const key of Object.keys(p))
    if (key !== 'all' && key !== 'actionUnits') throw refusal(where, '', 'one of the options all, actionUnits', key);
  let all = current.all;
  if (p.all !== undefined) {
    all = checkBoolean(where, 'all', p.all);
  }
  let actionUnits = current.actionUnits;
  if (p.actionUnits !== undefined) {
    if (!Array.isArray(p.actionUnits)) throw refusal(where, 'actionUnits', 'an array of Action Unit ids', p.actionUnits);
    for (const id of p.actionUnits as unknown[]) {
      if (typeof id !== 'string' || !CATALOGUE_ORDER.has(id)) {
        throw refusal(where, 'actionUnits', 'Action Unit ids like "AU12", without a side', id);
      }
    }
    actionUnits = [...new Set(p.actionUnits as string[])].sort((a, b) => CATALOGUE_ORDER.get(a)! - CATALOGUE_ORDER.get(b)!);
  }
  return { all, actionUnits: [...actionUnits] };
}

/** The names of the muscles `display` shows in `rig`, in the rig's muscle order (each once). */
export function shownMuscleNames(rig: Rig, display: MuscleDisplay): string[] {
  if (display.all) return rig.muscles.map((m) => m.name);
  const wanted = new Set<string>();
  for (const au of rig.actionUnits) if (display.actionUnits.includes(au.id)) for (const link of au.muscles) wanted.add(link.muscle);
  return rig.muscles.filter((m) => wanted.has(m.name)).map((m) => m.name);
}
