import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { ACTION_UNITS, ExpressionState, gradeOf } from '../src/core/expression/facs';
import { parseRigText } from '../src/core/rig/rig-schema';
import type { LinearMuscle, MuscleSide, Rig } from '../src/core/rig/rig-types';

const DEFAULT_RIG = parseRigText(readFileSync(new URL('../public/rigs/default.json', import.meta.url), 'utf8'), 'default.json');

function linear(name: string, side: MuscleSide): LinearMuscle {
  return {
    name,
    side,
    type: 'linear',
    origin: [0, 0, 0],
    insertion: [0, 1, 0],
    angle: 20,
    falloffStart: 0.8,
    falloffEnd: 1.2,
    strength: 0.2,
    normalWeight: 0.2,
  };
}

/** A small rig: AU12 on two muscles per side with different weights, AU26 and AU27 sharing one jaw-like muscle. */
const SMALL_RIG: Rig = {
  format: 'softface-rig',
  version: 2,
  muscles: [linear('zyg-l', 'left'), linear('zyg-r', 'right'), linear('ris-l', 'left'), linear('ris-r', 'right'), linear('jaw', 'mid')],
  actionUnits: [
    {
      id: 'AU12',
      name: 'lip corner puller',
      bilateral: true,
      muscles: [
        { muscle: 'zyg-l', side: 'left', weight: 1 },
        { muscle: 'zyg-r', side: 'right', weight: 1 },
        { muscle: 'ris-l', side: 'left', weight: 0.25 },
        { muscle: 'ris-r', side: 'right', weight: 0.25 },
      ],
    },
    { id: 'AU26', name: 'jaw drop', bilateral: false, muscles: [{ muscle: 'jaw', side: 'mid', weight: 0.48 }] },
    { id: 'AU27', name: 'mouth stretch', bilateral: false, muscles: [{ muscle: 'jaw', side: 'mid', weight: 1 }] },
  ],
  presets: [
    { name: 'smile', source: 'test', actionUnits: { AU12: 0.6 } },
    { name: 'grin-right', source: 'test', actionUnits: { AU12R: 0.5, AU26: 0.5 } },
  ],
};

function contractions(state: ExpressionState, rig: Rig = SMALL_RIG): Record<string, number> {
  const c = state.muscleContractions(rig, new Float32Array(rig.muscles.length));
  return Object.fromEntries(rig.muscles.map((m, i) => [m.name, c[i]]));
}

describe('the Action Unit catalogue', () => {
  it('has the 45 Action Units, with midline ones 9, 17, 18, 22 to 27, the head positions 51 to 58 and the eye positions 61 to 66', () => {
    expect(ACTION_UNITS.map((a) => a.number)).toEqual([
      1, 2, 4, 5, 6, 7, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 20, 22, 23, 24, 25, 26, 27, 38, 39, 41, 42, 43, 44, 45, 46, 51, 52, 53, 54,
      55, 56, 57, 58, 61, 62, 63, 64, 65, 66,
    ]);
    expect(ACTION_UNITS.filter((a) => !a.bilateral).map((a) => a.id)).toEqual([
      'AU9',
      'AU17',
      'AU18',
      'AU22',
      'AU23',
      'AU24',
      'AU25',
      'AU26',
      'AU27',
      'AU51',
      'AU52',
      'AU53',
      'AU54',
      'AU55',
      'AU56',
      'AU57',
      'AU58',
      'AU61',
      'AU62',
      'AU63',
      'AU64',
      'AU65',
      'AU66',
    ]);
    expect(ACTION_UNITS.find((a) => a.id === 'AU12')).toEqual({ id: 'AU12', number: 12, name: 'lip corner puller', bilateral: true });
  });

  it('matches the default rig (ids, names, sides), but for the head positions and sideways eye turns, which no muscle makes', () => {
    // AU51 to AU58 turn the whole head (head-pose.ts); AU61, AU62, AU65 and AU66 turn the eyeballs only (gaze.ts);
    // AU63 and AU64 also move the upper lids through the rig.
    const noMuscle = ['AU51', 'AU52', 'AU53', 'AU54', 'AU55', 'AU56', 'AU57', 'AU58', 'AU61', 'AU62', 'AU65', 'AU66'];
    expect(DEFAULT_RIG.actionUnits.map(({ id, name, bilateral }) => ({ id, name, bilateral }))).toEqual(
      ACTION_UNITS.filter((a) => !noMuscle.includes(a.id)).map(({ id, name, bilateral }) => ({ id, name, bilateral })),
    );
  });
});

describe('gradeOf', () => {
  it.each([
    [0, ''],
    [-0.1, ''],
    [Number.NaN, ''],
    [0.0001, 'A'],
    [0.1, 'A'],
    [0.1001, 'B'],
    [0.2, 'B'],
    [0.2001, 'C'],
    [0.55, 'C'],
    [0.5501, 'D'],
    [0.9, 'D'],
    [0.9001, 'E'],
    [1, 'E'],
    [1.5, 'E'],
  ])('grades %f as %j', (intensity, grade) => {
    expect(gradeOf(intensity)).toBe(grade);
  });
});

describe('ExpressionState sliders', () => {
  it('sets both sides with AU12 and one side with AU12L', () => {
    const s = new ExpressionState();
    s.setActionUnit('AU12', 0.4);
    expect(s.getActionUnits()).toMatchObject({ AU12L: 0.4, AU12R: 0.4 });
    s.setActionUnit('AU12L', 0.9);
    expect(s.getActionUnits()).toMatchObject({ AU12L: 0.9, AU12R: 0.4 });
    s.setActionUnit('AU26', 0.3);
    expect(s.getActionUnits().AU26).toBe(0.3);
  });

  it('clamps values above 1 and below 0', () => {
    const s = new ExpressionState();
    s.setActionUnit('AU1', 1.7);
    s.setActionUnit('AU2R', -0.5);
    expect(s.getActionUnits()).toMatchObject({ AU1L: 1, AU1R: 1, AU2R: 0 });
  });

  it('throws on an unknown id or a non-finite value, naming it, and changes nothing', () => {
    const s = new ExpressionState();
    s.setActionUnit('AU4', 0.5);
    const before = s.getActionUnits();
    expect(() => s.setActionUnit('AU99', 0.5)).toThrow(
      'setActionUnit: expected an Action Unit id like "AU12", "AU12L", "AU12R" or "AU17", got "AU99"',
    );
    // A midline unit has no sides.
    expect(() => s.setActionUnit('AU26L', 0.5)).toThrow(/^setActionUnit: expected an Action Unit id like .*, got "AU26L"$/);
    expect(() => s.setActionUnit('AU4', Number.NaN)).toThrow(/AU4: expected a finite number, got NaN/);
    expect(() => s.setActionUnit('AU4L', Number.POSITIVE_INFINITY)).toThrow(/AU4L: expected a finite number, got Infinity/);
    expect(() => s.setActionUnit('AU4', '0.7' as unknown as number)).toThrow(/AU4: expected a finite number, got "0.7"/);
    expect(s.getActionUnits()).toEqual(before);
    expect(s.effective()).toEqual(before);
  });

  it('lists the Action Units with their sides', () => {
    const list = new ExpressionState().listActionUnits();
    expect(list).toHaveLength(45);
    expect(list.find((a) => a.id === 'AU12')).toEqual({ id: 'AU12', number: 12, name: 'lip corner puller', sides: ['L', 'R'] });
    expect(list.find((a) => a.id === 'AU17')).toEqual({ id: 'AU17', number: 17, name: 'chin raiser', sides: ['M'] });
  });
});

describe('ExpressionState presets', () => {
  it('adds weighted presets to the sliders and clamps the sum (happiness + surprise)', () => {
    const s = new ExpressionState(DEFAULT_RIG.presets);
    const amount = (preset: string, au: string): number => DEFAULT_RIG.presets.find((p) => p.name === preset)?.actionUnits[au] ?? 0;
    const happy12 = amount('happiness', 'AU12');
    expect(happy12).toBeGreaterThan(0.5); // so that 0.5 + it clamps
    s.applyPreset('happiness', 1);
    s.applyPreset('surprise', 0.5);
    s.setActionUnit('AU12L', 0.5);
    s.setActionUnit('AU26', 0.1);
    const e = s.effective();
    expect(e.AU12L).toBe(1); // 0.5 + happiness's AU12, clamped
    expect(e.AU12R).toBeCloseTo(happy12, 12);
    expect(e.AU6L).toBeCloseTo(amount('happiness', 'AU6'), 12);
    expect(e.AU1R).toBeCloseTo(0.5 * amount('surprise', 'AU1'), 12);
    expect(e.AU5L).toBeCloseTo(0.5 * amount('surprise', 'AU5'), 12);
    expect(e.AU26).toBeCloseTo(0.1 + 0.5 * amount('surprise', 'AU26'), 12);
    expect(e.AU15L).toBe(0);
    expect(s.getActionUnits().AU12R).toBe(0); // sliders stay what was set
  });

  it('sums presets that share an Action Unit, and applies AU12 to both sides but AU12R to the right only', () => {
    const s = new ExpressionState(SMALL_RIG.presets);
    s.applyPreset('smile', 1);
    s.applyPreset('grin-right', 1);
    expect(s.effective()).toMatchObject({ AU12L: 0.6, AU12R: 1, AU26: 0.5 });
  });

  it('drives only the right lip corner with the contempt preset: AU14 at grade D, AU12 at grade C', () => {
    const s = new ExpressionState(DEFAULT_RIG.presets);
    s.applyPreset('contempt', 1);
    const e = s.effective();
    expect(e).toMatchObject({ AU12L: 0, AU14L: 0 });
    expect(gradeOf(e.AU12R)).toBe('C');
    expect(gradeOf(e.AU14R)).toBe('D');
    const c = contractions(s, DEFAULT_RIG);
    expect(c['zygomaticus-major-r']).toBeCloseTo(0.25, 6);
    expect(c['buccinator-r']).toBeCloseTo(0.7, 6);
    const driven = Object.entries(c)
      .filter(([, v]) => v > 0)
      .map(([name]) => name);
    expect(driven.sort()).toEqual(['buccinator-r', 'zygomaticus-major-r']);
  });

  it('clamps preset weights and rejects unknown presets or non-finite weights, changing nothing', () => {
    const s = new ExpressionState(SMALL_RIG.presets);
    s.applyPreset('smile', 3);
    expect(s.listPresets()).toEqual([
      { name: 'smile', source: 'test', weight: 1 },
      { name: 'grin-right', source: 'test', weight: 0 },
    ]);
    expect(() => s.applyPreset('frown', 1)).toThrow(/^applyPreset: expected one of the presets .*, got "frown"$/);
    expect(() => s.applyPreset('grin-right', Number.NaN)).toThrow(/applyPreset: grin-right: expected a finite number, got NaN/);
    expect(s.listPresets().map((p) => p.weight)).toEqual([1, 0]);
    s.applyPreset('smile', -1);
    expect(s.effective().AU12L).toBe(0);
  });

  it('refuses presets naming Action Units outside the catalogue', () => {
    expect(() => new ExpressionState([{ name: 'odd', source: 'test', actionUnits: { AU99: 0.5 } }])).toThrow(
      /preset "odd" names unknown Action Unit id "AU99"/,
    );
    expect(() => new ExpressionState([{ name: 'odd', source: 'test', actionUnits: { AU17R: 0.5 } }])).toThrow(/"AU17R"/);
  });
});

describe('ExpressionState.muscleContractions', () => {
  it('maps each Action Unit side to its muscles with their weights', () => {
    const s = new ExpressionState();
    s.setActionUnit('AU12L', 0.8);
    s.setActionUnit('AU26', 0.5);
    const c = contractions(s);
    expect(c['zyg-l']).toBeCloseTo(0.8, 6);
    expect(c['ris-l']).toBeCloseTo(0.2, 6);
    expect(c['zyg-r']).toBe(0);
    expect(c['ris-r']).toBe(0);
    expect(c.jaw).toBeCloseTo(0.24, 6);
  });

  it('sums the Action Units on a shared muscle and clamps at 1', () => {
    const s = new ExpressionState();
    s.setActionUnit('AU26', 1);
    expect(contractions(s).jaw).toBeCloseTo(0.48, 6);
    s.setActionUnit('AU27', 0.7);
    expect(contractions(s).jaw).toBe(1); // 0.48 + 0.7
  });

  it('drives the default rig: AU26 opens the jaw about 12 degrees, AU27 about 25', () => {
    const jaw = DEFAULT_RIG.muscles.findIndex((m) => m.type === 'jaw');
    const maxAngle = (DEFAULT_RIG.muscles[jaw] as { maxAngle: number }).maxAngle;
    const s = new ExpressionState(DEFAULT_RIG.presets);
    const into = new Float32Array(DEFAULT_RIG.muscles.length);
    s.setActionUnit('AU26', 1);
    expect(s.muscleContractions(DEFAULT_RIG, into)[jaw] * maxAngle).toBeCloseTo(12, 0);
    s.reset();
    s.setActionUnit('AU27', 1);
    expect(s.muscleContractions(DEFAULT_RIG, into)[jaw] * maxAngle).toBeCloseTo(25, 0);
  });

  it('fills the given array, leaving entries past the muscles alone, and refuses one too short', () => {
    const s = new ExpressionState();
    s.setActionUnit('AU12', 1);
    const into = new Float32Array(SMALL_RIG.muscles.length + 1).fill(7);
    expect(s.muscleContractions(SMALL_RIG, into)).toBe(into);
    expect(Array.from(into)).toEqual([1, 1, 0.25, 0.25, 0, 7]);
    expect(() => s.muscleContractions(SMALL_RIG, new Float32Array(2))).toThrow(RangeError);
  });

  it('refuses a rig whose Action Units do not fit the catalogue', () => {
    const odd: Rig = {
      ...SMALL_RIG,
      actionUnits: [{ ...SMALL_RIG.actionUnits[1], bilateral: true, muscles: [{ muscle: 'jaw', side: 'left', weight: 1 }] }],
    };
    expect(() => new ExpressionState().muscleContractions(odd, new Float32Array(5))).toThrow(/AU26 as bilateral/);
  });
});

describe('ExpressionState.reset', () => {
  it('clears sliders, preset weights and contractions', () => {
    const s = new ExpressionState(DEFAULT_RIG.presets);
    s.setActionUnit('AU4', 0.7);
    s.applyPreset('fear', 1);
    s.reset();
    expect(Object.values(s.getActionUnits()).every((v) => v === 0)).toBe(true);
    expect(Object.values(s.effective()).every((v) => v === 0)).toBe(true);
    expect(s.listPresets().every((p) => p.weight === 0)).toBe(true);
    expect(Array.from(s.muscleContractions(DEFAULT_RIG, new Float32Array(DEFAULT_RIG.muscles.length))).every((v) => v === 0)).toBe(true);
  });
});

describe('ExpressionState overlay', () => {
  it('adds to sliders and presets, clamped, without moving a slider; reset leaves it', () => {
    const s = new ExpressionState(SMALL_RIG.presets);
    s.setActionUnit('AU12L', 0.3);
    s.applyPreset('smile', 0.5); // AU12 0.3 on both sides
    expect(s.setOverlay('AU12L', 0.2)).toBe(true);
    expect(s.setOverlay('AU12L', 0.2)).toBe(false); // unchanged
    expect(s.getActionUnits().AU12L).toBe(0.3);
    expect(s.effective().AU12L).toBeCloseTo(0.8, 9);
    expect(s.effective().AU12R).toBeCloseTo(0.3, 9);
    expect(contractions(s)['zyg-l']).toBeCloseTo(0.8, 6);
    s.setOverlay('AU12', 0.9);
    expect(s.effective().AU12L).toBe(1);
    expect(s.effective().AU12R).toBeCloseTo(1, 9);
    s.reset();
    expect(s.getActionUnits().AU12L).toBe(0);
    expect(s.effective().AU12L).toBeCloseTo(0.9, 9);
    expect(s.getOverlay().AU12R).toBeCloseTo(0.9, 9);
    expect(s.clearOverlay()).toBe(true);
    expect(s.clearOverlay()).toBe(false);
    expect(s.effective().AU12L).toBe(0);
  });

  it('throws on an unknown id or a non-finite value, changing nothing', () => {
    const s = new ExpressionState();
    expect(() => s.setOverlay('AU99', 0.5)).toThrow(/AU99/);
    expect(() => s.setOverlay('AU43L', Number.NaN)).toThrow(/AU43L/);
    expect(Object.values(s.getOverlay()).every((v) => v === 0)).toBe(true);
  });
});
