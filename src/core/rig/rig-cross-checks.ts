/**
 * Checks of a rig document across fields, which the schema cannot express: names that must exist or be unique, sides
 * that must match, a muscle's geometry that must hang together. They read the document defensively, so that they can
 * report alongside the schema's problems even when parts of it are malformed; values the schema refused are skipped
 * here, so nothing is reported twice.
 */
import { pathStep, type RigProblem } from './rig-problems';

export type Obj = Record<string, unknown>;

export const isObj = (x: unknown): x is Obj => typeof x === 'object' && x !== null && !Array.isArray(x);

const list = (x: unknown): unknown[] => (Array.isArray(x) ? x : []);
const isNum = (x: unknown): x is number => typeof x === 'number' && Number.isFinite(x);
const isPositive = (x: unknown): x is number => isNum(x) && x > 0;
const isVec3 = (x: unknown): x is [number, number, number] => Array.isArray(x) && x.length === 3 && x.every(isNum);
/** Every problem the checks across fields find in a rig document (none for a document that is not an object). */
export function crossChecks(doc: unknown): RigProblem[] {
  if (!isObj(doc)) return [];
  const problems: RigProblem[] = [];
  const muscleSides = checkMuscles(list(doc.muscles), problems);
  const bilateralById = checkActionUnits(list(doc.actionUnits), muscleSides, problems);
  checkPresets(list(doc.presets), bilateralById, problems);
  return problems;
}

/** Unique names and each muscle's own geometry; returns the side of every named muscle. */
function checkMuscles(muscles: unknown[], problems: RigProblem[]): Map<string, unknown> {
  const sides = new Map<string, unknown>();
  const firstIndex = new Map<string, number>();
  muscles.forEach((m, i) => {
    if (!isObj(m)) return;
    const at = `muscles[${i}]`;
    if (typeof m.name === 'string') {
      const first = firstIndex.get(m.name);
      if (first !== undefined) problems.push({ path: `${at}.name`, message: `duplicate muscle name "${m.name}" (also muscles[${first}])` });
      else {
        firstIndex.set(m.name, i);
        sides.set(m.name, m.side);
      }
    }
    problems.push(...geometryProblems(m, at));
  });
  return sides;
}

/**
 * What is wrong across the fields of one muscle's geometry, with paths under `at` ('' for the muscle itself);
 * `validateMuscle` reports the same for muscles handed to the solver.
 */
export function geometryProblems(m: Obj, at = ''): RigProblem[] {
  const problems: RigProblem[] = [];
  const path = (key: string): string => at + pathStep(key, at === '');
  if (m.type === 'linear') {
    if (isPositive(m.falloffStart) && isPositive(m.falloffEnd) && !(m.falloffStart < m.falloffEnd)) {
      problems.push({ path: path('falloffEnd'), message: `expected more than falloffStart (${m.falloffStart}), got ${m.falloffEnd}` });
    }
    // The pull runs along origin -> insertion, which needs a length.
    if (isVec3(m.origin) && isVec3(m.insertion) && m.origin.every((x, k) => x === (m.insertion as number[])[k])) {
      problems.push({ path: path('insertion'), message: 'expected a point apart from the origin, got the same point' });
    }
  }
  if (m.type === 'sphincter' && isVec3(m.radii) && m.radii.every(isPositive) && isVec3(m.innerRadii) && m.innerRadii.every(isPositive)) {
    // An inner ellipsoid poking out of the outer one would make the pull stop in a step over a patch of skin. Equal
    // radii on an axis are allowed (a rig may want no fade along the depth): the step is then only at that axis's
    // two poles, the outer ellipsoid's tips, and the fade is steep only near them.
    const radii = m.radii;
    m.innerRadii.forEach((r, k) => {
      if (r > radii[k])
        problems.push({ path: `${path('innerRadii')}[${k}]`, message: `expected at most radii[${k}] (${radii[k]}), got ${r}` });
    });
  }
  return problems;
}

/** Unique ids, muscles that exist, and sides that fit the unit; returns whether each Action Unit id is bilateral. */
function checkActionUnits(units: unknown[], muscleSides: Map<string, unknown>, problems: RigProblem[]): Map<string, boolean> {
  const bilateralById = new Map<string, boolean>();
  units.forEach((u, i) => {
    if (!isObj(u)) return;
    const at = `actionUnits[${i}]`;
    if (typeof u.id === 'string') {
      if (bilateralById.has(u.id)) problems.push({ path: `${at}.id`, message: `duplicate Action Unit id "${u.id}"` });
      else if (typeof u.bilateral === 'boolean') bilateralById.set(u.id, u.bilateral);
    }
    if (typeof u.bilateral === 'boolean') checkActionUnitMuscles(u, at, muscleSides, problems);
  });
  return bilateralById;
}

function checkActionUnitMuscles(u: Obj, at: string, muscleSides: Map<string, unknown>, problems: RigProblem[]): void {
  const label = typeof u.id === 'string' ? u.id : 'this Action Unit';
  const seen = new Set<string>();
  const sidesPresent = new Set<unknown>();
  list(u.muscles).forEach((e, j) => {
    if (!isObj(e) || typeof e.muscle !== 'string') return;
    const here = `${at}.muscles[${j}]`;
    sidesPresent.add(e.side);
    // Only a string side can be a duplicate; anything else is the schema's to report (and String() of a deeply nested
    // array would overflow the stack).
    const key = `${e.muscle}\u0000${typeof e.side === 'string' ? e.side : '?'}`;
    if (seen.has(key)) problems.push({ path: `${here}.muscle`, message: `"${e.muscle}" is listed twice for this side` });
    seen.add(key);
    if (!muscleSides.has(e.muscle)) {
      problems.push({ path: `${here}.muscle`, message: `no muscle named "${e.muscle}" in muscles` });
      return;
    }
    const muscleSide = muscleSides.get(e.muscle);
    if (u.bilateral && e.side === 'mid') {
      problems.push({ path: `${here}.side`, message: `expected "left" or "right" for bilateral ${label}, got "mid"` });
    } else if (u.bilateral && (e.side === 'left' || e.side === 'right') && muscleSide !== e.side) {
      const where = muscleSide === 'mid' ? 'the midline' : `the ${typeof muscleSide === 'string' ? muscleSide : 'unknown'} side`;
      problems.push({ path: `${here}.side`, message: `"${e.side}" does not match muscle "${e.muscle}", which is on ${where}` });
    } else if (!u.bilateral && (e.side === 'left' || e.side === 'right')) {
      problems.push({ path: `${here}.side`, message: `expected "mid" for midline ${label}, got "${e.side}"` });
    }
  });
  if (u.bilateral && list(u.muscles).length > 0) {
    for (const s of ['left', 'right']) {
      if (!sidesPresent.has(s)) problems.push({ path: `${at}.muscles`, message: `bilateral ${label} has no muscle on the ${s} side` });
    }
  }
}

/** Unique names, and Action Unit ids that exist: `AU12`, or `AU12L` / `AU12R` for a bilateral unit. */
function checkPresets(presets: unknown[], bilateralById: Map<string, boolean>, problems: RigProblem[]): void {
  const names = new Set<string>();
  presets.forEach((p, i) => {
    if (!isObj(p)) return;
    const at = `presets[${i}]`;
    if (typeof p.name === 'string') {
      if (names.has(p.name)) problems.push({ path: `${at}.name`, message: `duplicate preset name "${p.name}"` });
      names.add(p.name);
    }
    if (!isObj(p.actionUnits)) return;
    for (const id of Object.keys(p.actionUnits)) {
      const message = presetIdProblem(id, bilateralById);
      if (message) problems.push({ path: `${at}.actionUnits${pathStep(id, false)}`, message });
    }
  });
}

function presetIdProblem(id: string, bilateralById: Map<string, boolean>): string | undefined {
  const match = /^(AU[1-9]\d*)([LR]?)$/.exec(id);
  if (!match) return 'expected an Action Unit id like "AU12", "AU12L" or "AU12R"';
  const [, base, sideLetter] = match;
  const bilateral = bilateralById.get(base);
  if (bilateral === undefined) return `no Action Unit ${base} in actionUnits`;
  if (sideLetter && !bilateral) return `${base} is a midline Action Unit and has no sides: use "${base}"`;
  return undefined;
}
