import { describe, expect, it } from 'vitest';
import { ExpressionState, gradeOf } from '../src/core/expression/facs';
import { facsCode, GRADE_INTENSITY, parseFACSCode, type FACSTerm } from '../src/core/expression/facs-code';
import { mulberry32 } from '../src/core/random';
import { loadDefaultRig } from './fixtures/head-simulation';

/** A code's terms as an object, id to intensity. */
const read = (code: string): Record<string, number> => Object.fromEntries(parseFACSCode(code).map((t: FACSTerm) => [t.id, t.intensity]));

describe('FACS codes', () => {
  it('read units, sides and intensity letters, with no letter at full intensity', () => {
    expect(read('1+2+5B+26')).toEqual({ AU1: 1, AU2: 1, AU5: 0.2, AU26: 1 });
    expect(read('L12C+R14A')).toEqual({ AU12L: 0.4, AU14R: 0.1 });
    // U: one side, which one not coded; the left here.
    expect(read('U14')).toEqual({ AU14L: 1 });
    // Spaces separate too (a URL's query form turns + into a space), and case does not matter.
    expect(read(' 1 2  5b ')).toEqual(read('1+2+5B'));
    expect(read('l12c + r12a')).toEqual({ AU12L: 0.4, AU12R: 0.1 });
    expect(read('')).toEqual({});
    expect(read('0')).toEqual({});
  });

  it('give each letter an intensity inside the band the panel shows that letter for', () => {
    for (const [letter, intensity] of Object.entries(GRADE_INTENSITY)) expect(gradeOf(intensity)).toBe(letter);
  });

  it('refuse what they cannot read, naming the unit and its place, 1-based', () => {
    const refused = (code: string) => {
      try {
        parseFACSCode(code);
      } catch (e) {
        return (e as Error).message;
      }
      return 'read';
    };
    expect(refused('1+2+99')).toMatch(/^setFACS: at 5 of "1\+2\+99": expected an Action Unit the face has \(1, 2, 4, .*\), got "99"$/);
    expect(refused('1++2')).toMatch(/^setFACS: at 3 of "1\+\+2": expected a unit on each side of every plus sign/);
    // A code that starts or ends with a plus sign: that sign's place.
    expect(refused('+1')).toMatch(/^setFACS: at 1 of "\+1": expected a unit on each side/);
    expect(refused('12+')).toMatch(/^setFACS: at 3 of "12\+": expected a unit on each side/);
    expect(refused('1+2+ ')).toMatch(/^setFACS: at 4 of "1\+2\+ ": expected a unit on each side/);
    expect(refused('1+')).toMatch(/^setFACS: at 2 of /);
    expect(refused('L17')).toMatch(/^setFACS: at 1 of "L17": expected 17 without a side .*, got "L17"$/);
    expect(refused('12+L12')).toMatch(/^setFACS: at 4 of "12\+L12": expected AU12 once per side, got "L12"$/);
    expect(refused('6 12X')).toMatch(/^setFACS: at 3 of "6 12X": expected a unit like 12, 12C, L12 or R12B, got "12X"$/);
    expect(refused('x'.repeat(1001))).toMatch(/^setFACS: expected a FACS code of at most 1000 characters/);
    expect(() => parseFACSCode(12 as unknown as string)).toThrow(/^setFACS: expected a FACS code like "1\+2\+5B\+26", got 12$/);
  });

  it('write intensities with the letters of their grades, both sides as one where they agree', () => {
    expect(facsCode({ AU12L: 0.8, AU12R: 0.8 })).toBe('12D');
    expect(facsCode({ AU12L: 0.8, AU12R: 0.15, AU17: 0.3 })).toBe('L12D+R12B+17C');
    expect(facsCode({ AU26: 1, AU1L: 1, AU1R: 1, AU5L: 0.2, AU5R: 0.2, AU2L: 0.95, AU2R: 1 })).toBe('1E+2E+5B+26E');
    expect(facsCode({})).toBe('');
  });

  it('round-trip every preset: its code read back writes the same code', () => {
    const rig = loadDefaultRig();
    const state = new ExpressionState(rig.presets);
    for (const preset of rig.presets) {
      state.reset();
      state.applyPreset(preset.name, 1);
      const code = facsCode(state.expressionIntensities());
      expect(code, preset.name).not.toBe('');
      state.reset();
      for (const t of parseFACSCode(code)) state.setActionUnit(t.id, t.intensity);
      expect(facsCode(state.expressionIntensities()), preset.name).toBe(code);
    }
  });

  it('read or refuse 100 random codes, a refusal always at a place within the code', () => {
    const random = mulberry32(20261128);
    const pieces = [
      '1',
      '2',
      '4',
      '5',
      '6',
      '12',
      '17',
      '26',
      '43',
      '99',
      '0',
      'L',
      'R',
      'U',
      'A',
      'B',
      'C',
      'E',
      'F',
      '+',
      '+',
      '+',
      ' ',
      'x',
      '-',
    ];
    let read = 0;
    for (let n = 0; n < 100; n++) {
      const length = 1 + Math.floor(random() * 12);
      let code = '';
      for (let k = 0; k < length; k++) code += pieces[Math.floor(random() * pieces.length)];
      try {
        const terms = parseFACSCode(code);
        read++;
        // What was read writes a code that reads back to the same intensities.
        const intensities = Object.fromEntries(terms.flatMap(spread));
        const again = parseFACSCode(facsCode(intensities));
        expect(facsCode(Object.fromEntries(again.flatMap(spread))), code).toBe(facsCode(intensities));
      } catch (e) {
        const message = (e as Error).message;
        if (message.startsWith('expected')) throw e;
        const at = /^setFACS: at (\d+) of /.exec(message);
        expect(at, `${JSON.stringify(code)}: ${message}`).not.toBeNull();
        expect(Number(at![1])).toBeGreaterThanOrEqual(1);
        expect(Number(at![1])).toBeLessThanOrEqual(code.length);
      }
    }
    // Both outcomes occur: the pieces make readable codes and unreadable ones.
    expect(read).toBeGreaterThan(5);
    expect(read).toBeLessThan(95);
  });
});

const BILATERAL = new Set(
  new ExpressionState()
    .listActionUnits()
    .filter((au) => au.sides.length === 2)
    .map((au) => au.id),
);
/** A term as side ids: a bilateral unit's id without a side stands for both. */
function spread(t: FACSTerm): [string, number][] {
  return BILATERAL.has(t.id)
    ? [
        [`${t.id}L`, t.intensity],
        [`${t.id}R`, t.intensity],
      ]
    : [[t.id, t.intensity]];
}
