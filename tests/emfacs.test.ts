import { describe, expect, it } from 'vitest';
import { EMFACS, EMOTIONS, emotionVariants } from '../src/core/expression/emfacs';
import { facsIntensities, parseFACSCode } from '../src/core/expression/facs-code';

describe('the EMFACS table', () => {
  it('gives every emotion prototypes, each face a code the face reads, named by emotion, kind and place', () => {
    for (const emotion of EMOTIONS) expect(EMFACS.filter((v) => v.emotion === emotion && v.kind === 'prototype').length).toBeGreaterThan(0);
    for (const v of EMFACS) {
      expect(() => parseFACSCode(v.code), v.name).not.toThrow();
      expect(v.name).toMatch(new RegExp(`^${v.emotion}-${v.kind}-\\d+$`));
      expect(v.source.length).toBeGreaterThan(10);
    }
    expect(new Set(EMFACS.map((v) => v.name)).size).toBe(EMFACS.length);
    expect(new Set(EMFACS.map((v) => `${v.emotion} ${v.code}`)).size).toBe(EMFACS.length);
  });

  it('holds the table’s prototypes: surprise 1+2+5B with 26 or 27, fear 1+2+4+5 with an open mouth, anger 4+5+7', () => {
    expect(emotionVariants('surprise:prototype').map((v) => v.code)).toEqual(['1+2+5B+26', '1+2+5B+27']);
    expect(emotionVariants('surprise:variant').map((v) => v.code)).toEqual(['1+2+5B', '1+2+26', '1+2+27', '5B+26', '5B+27']);
    for (const v of emotionVariants('fear:prototype')) {
      const units = Object.keys(facsIntensities(v.code));
      expect(units, v.code).toEqual(expect.arrayContaining(['AU1', 'AU2', 'AU4', 'AU5']));
      expect(
        ['AU25', 'AU26', 'AU27'].filter((u) => units.includes(u)),
        v.code,
      ).toHaveLength(1);
    }
    for (const v of emotionVariants('anger:prototype')) expect(v.code.startsWith('4+5+7+'), v.code).toBe(true);
    // Anger's variants: a prototype with one of 4, 5, 7 or 10 left out.
    const anger = emotionVariants('anger:variant');
    expect(anger.map((v) => v.code)).toContain('5+7+10+22+23+25');
    expect(anger.map((v) => v.code)).toContain('4+5+7+22+23+26');
    // Sadness with and without the head and eyes down.
    expect(emotionVariants('sadness-prototype-2').map((v) => v.code)).toEqual(['1+4+11+15B+54+64']);
    expect(emotionVariants('happiness').map((v) => v.code)).toEqual(['6+12', '12C', '12D']);
    // Contempt: a one-sided dimpler with the lip corner raised.
    expect(emotionVariants('contempt-prototype-1')[0].code).toBe('R12A+R14A');
  });

  it('refuses a selector it does not know, naming it', () => {
    expect(() => emotionVariants('joy', 'setEmotion')).toThrow(
      /^setEmotion: expected an emotion \(surprise, fear, \.\.\.\), .* got "joy"$/,
    );
    expect(() => emotionVariants('fear:maybe')).toThrow(/got "fear:maybe"$/);
    expect(() => emotionVariants('fear-prototype-99')).toThrow(/got "fear-prototype-99"$/);
    expect(() => emotionVariants(3)).toThrow(/got 3$/);
    expect(emotionVariants('happiness:variant')).toEqual([]);
  });
});
