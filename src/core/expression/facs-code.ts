/**
 * FACS codes as text, the form coders write expressions in: `1+2+5B+26`, `L12C+R14A`, `U14`. Pure: no DOM.
 *
 * A code is units joined by `+` (spaces also separate, as a URL's query form turns `+` into one). A unit is an
 * optional side (`L` the subject's left, `R` right, `U` unilateral with its side not coded, taken here as the left),
 * the Action Unit's number, and an optional intensity letter A to E. FACS grades are not evenly spaced (see
 * `gradeOf`), so each letter stands for an intensity inside its band: A 0.1, B 0.2, C 0.4, D 0.7, E 1; no letter is
 * E, the unit at full intensity. A bilateral unit without a side sets both sides; a midline one (`17`) takes no side.
 * `0` or an empty code is the neutral face.
 */
import { refusal, show } from '../check';
import { ACTION_UNITS, gradeOf, type ActionUnitInfo } from './facs';

/** The intensity each FACS letter sets (each within the band `gradeOf` gives that letter). */
export const GRADE_INTENSITY: Readonly<Record<'A' | 'B' | 'C' | 'D' | 'E', number>> = Object.freeze({
  A: 0.1,
  B: 0.2,
  C: 0.4,
  D: 0.7,
  E: 1,
});

/** Longest code read, in characters: every unit on both sides with a grade is far shorter. */
const MAX_FACS_CODE_CHARS = 1000;

/** One unit of a code: the id `setActionUnit` takes (`AU12`, `AU12L`, `AU17`) and its intensity. */
export interface FACSTerm {
  id: string;
  intensity: number;
}

const BY_NUMBER: ReadonlyMap<number, ActionUnitInfo> = new Map(ACTION_UNITS.map((au) => [au.number, au]));
const NUMBERS = ACTION_UNITS.map((au) => au.number).join(', ');
const UNIT = /^([LRU]?)(\d{1,3})([A-E]?)$/;

/**
 * Reads a FACS code into the Action Unit intensities it sets. Throws, naming the unit and its place (1-based), on
 * anything it cannot read: `setFACS: at 5 of "1+2+99": expected an Action Unit the face has (1, 2, 4, ...), got "99"`.
 */
export function parseFACSCode(code: unknown, what = 'setFACS'): FACSTerm[] {
  if (typeof code !== 'string') throw refusal(what, '', 'a FACS code like "1+2+5B+26"', code);
  if (code.length > MAX_FACS_CODE_CHARS) throw refusal(what, '', `a FACS code of at most ${MAX_FACS_CODE_CHARS} characters`, code);
  const terms: FACSTerm[] = [];
  // Which sides each unit has set already: a side given twice is a slip, not a sum.
  const sides = new Map<number, Set<string>>();
  if (code.trim() === '' || code.trim() === '0') return terms;
  // Units between plus signs (each part may hold several, apart by spaces); an empty part is a stray plus sign.
  let start = 0;
  const parts = code.split('+');
  for (const [i, part] of parts.entries()) {
    if (part.trim() === '') {
      // The stray plus sign: the one after an empty part, or before the last (a code ending in a plus).
      const at = i === parts.length - 1 ? start : start + part.length + 1;
      throw refusal(what, `at ${at} of ${show(code)}`, 'a unit on each side of every plus sign', part);
    }
    for (const m of part.matchAll(/\S+/g)) terms.push(readUnit(m[0], `at ${start + m.index + 1} of ${show(code)}`));
    start += part.length + 1;
  }
  return terms;

  function readUnit(text: string, where: string): FACSTerm {
    const unit = UNIT.exec(text.toUpperCase());
    if (!unit) throw refusal(what, where, 'a unit like 12, 12C, L12 or R12B', text);
    const [, side, digits, letter] = unit;
    const au = BY_NUMBER.get(Number(digits));
    if (!au) throw refusal(what, where, `an Action Unit the face has (${NUMBERS})`, digits);
    if (side && !au.bilateral) throw refusal(what, where, `${digits} without a side (AU${digits} acts on both sides as one)`, text);
    const own = side === '' ? (au.bilateral ? ['L', 'R'] : ['']) : [side === 'R' ? 'R' : 'L'];
    const seen = sides.get(au.number) ?? new Set<string>();
    if (own.some((s) => seen.has(s))) throw refusal(what, where, `AU${digits} once per side`, text);
    for (const s of own) seen.add(s);
    sides.set(au.number, seen);
    const intensity = GRADE_INTENSITY[(letter || 'E') as keyof typeof GRADE_INTENSITY];
    return { id: side === '' ? au.id : `${au.id}${own[0]}`, intensity };
  }
}

/** A FACS code's Action Unit intensities by id, as `setActionUnit` takes them (`{ AU1: 1, AU5: 0.2 }`). */
export function facsIntensities(code: unknown, what = 'setFACS'): Record<string, number> {
  return Object.fromEntries(parseFACSCode(code, what).map((t) => [t.id, t.intensity]));
}

/**
 * The FACS code of Action Unit intensities by side id (`{ AU12L: 0.8, AU12R: 0.8, AU17: 0.3 }`), units in FACS order,
 * each with the letter of its grade: both sides of a unit at one grade as one unit (`12D`), otherwise one per side
 * (`L12D+R12B`). Intensities of 0 are left out; the neutral face is `""`.
 */
export function facsCode(intensities: Readonly<Record<string, number>>): string {
  const units: string[] = [];
  for (const au of ACTION_UNITS) {
    if (!au.bilateral) {
      const grade = gradeOf(intensities[au.id] ?? 0);
      if (grade) units.push(`${au.number}${grade}`);
      continue;
    }
    const left = gradeOf(intensities[`${au.id}L`] ?? 0);
    const right = gradeOf(intensities[`${au.id}R`] ?? 0);
    if (left && left === right) units.push(`${au.number}${left}`);
    else {
      if (left) units.push(`L${au.number}${left}`);
      if (right) units.push(`R${au.number}${right}`);
    }
  }
  return units.join('+');
}
