import { describe, expect, it } from 'vitest';
import { ARKIT_BLENDSHAPES, ARKIT_MAPPING, BLENDSHAPE_UNIT_IDS, blendshapeUnits, readBlendshapes } from '../src/core/expression/arkit';
import { isActionUnitId } from '../src/core/expression/facs';

/** The units one blendshape alone at `value` drives, as id -> intensity (the others at 0). */
function alone(name: string, value = 1): Record<string, number> {
  const b = new Float64Array(ARKIT_BLENDSHAPES.length);
  readBlendshapes({ [name]: value }, b);
  const out = blendshapeUnits(b, new Float64Array(BLENDSHAPE_UNIT_IDS.length));
  return Object.fromEntries(BLENDSHAPE_UNIT_IDS.map((id, i) => [id, out[i]]).filter(([, v]) => v !== 0));
}

describe('ARKit blendshapes as Action Units', () => {
  it('know the 52 names once each, a table row for each in Apple’s order, units the face has', () => {
    expect(ARKIT_BLENDSHAPES).toHaveLength(52);
    expect(new Set(ARKIT_BLENDSHAPES).size).toBe(52);
    expect(ARKIT_MAPPING.map((m) => m.blendshape)).toEqual([...ARKIT_BLENDSHAPES]);
    for (const m of ARKIT_MAPPING) for (const id of m.units) expect(isActionUnitId(id), `${m.blendshape}: ${id}`).toBe(true);
    for (const id of BLENDSHAPE_UNIT_IDS)
      expect(
        ARKIT_MAPPING.some((m) => m.units.includes(id)),
        id,
      ).toBe(true);
  });

  it.each(ARKIT_MAPPING.map((m) => [m.blendshape, m.units] as const))('%s alone drives %j and nothing else', (name, units) => {
    const driven = alone(name);
    // Every unit it drives is in its row; a row's unit may need a partner (the other eye) to move.
    for (const id of Object.keys(driven)) expect(units, `${name} drove ${id}`).toContain(id);
    if (units.length === 0) expect(driven).toEqual({});
  });

  it('map sides to the subject’s sides and the issue’s examples', () => {
    expect(alone('mouthSmileLeft', 0.8)).toEqual({ AU12L: 0.8 });
    expect(alone('browInnerUp', 0.5)).toEqual({ AU1L: 0.5, AU1R: 0.5 });
    expect(alone('cheekSquintRight')).toEqual({ AU6R: 1 });
    expect(alone('noseSneerLeft', 0.6)).toEqual({ AU9: 0.6 });
    expect(alone('mouthPucker')).toEqual({ AU18: 1 });
    expect(alone('mouthFunnel')).toEqual({ AU22: 1 });
    expect(alone('eyeBlinkLeft')).toEqual({ AU43L: 1 });
    // The jaw: its first half drops it (26, with the lips parting), the second stretches the mouth (27).
    expect(alone('jawOpen', 0.3)).toEqual({ AU25: 0.3, AU26: 0.6 });
    expect(alone('jawOpen', 0.75)).toEqual({ AU25: 0.75, AU26: 1, AU27: 0.5 });
    // The eyes: one eye's look is half the eye position; both eyes in is a cross-eye with no sideways turn.
    expect(alone('eyeLookOutLeft')).toEqual({ AU61: 0.5 });
    const b = new Float64Array(52);
    readBlendshapes({ eyeLookInLeft: 1, eyeLookInRight: 1, jawOpen: 0.4, mouthClose: 0.4 }, b);
    const units = blendshapeUnits(b, new Float64Array(BLENDSHAPE_UNIT_IDS.length));
    const at = (id: string) => units[BLENDSHAPE_UNIT_IDS.indexOf(id)];
    expect([at('AU61'), at('AU62'), at('AU66')]).toEqual([0.5, 0.5, 1]);
    // mouthClose holds the lips together while the jaw opens.
    expect([at('AU25'), at('AU26')]).toEqual([0, 0.8]);
  });

  it('clamp values to 0..1, keep names not given, and refuse an unknown name or a non-number naming it, changing nothing', () => {
    const b = new Float64Array(52);
    readBlendshapes({ jawOpen: 2, mouthSmileLeft: -1, browInnerUp: 0.25 }, b);
    readBlendshapes({ browInnerUp: 0.5 }, b);
    expect([
      b[ARKIT_BLENDSHAPES.indexOf('jawOpen')],
      b[ARKIT_BLENDSHAPES.indexOf('mouthSmileLeft')],
      b[ARKIT_BLENDSHAPES.indexOf('browInnerUp')],
    ]).toEqual([1, 0, 0.5]);
    const before = b.slice();
    expect(() => readBlendshapes({ jawOpen: 0.2, mouthSmile_L: 1 }, b)).toThrow(
      'setBlendshapes: expected one of the 52 ARKit blendshape names (eyeBlinkLeft, jawOpen, ...), got "mouthSmile_L"',
    );
    expect(() => readBlendshapes({ jawOpen: Number.NaN }, b)).toThrow(/^setBlendshapes: jawOpen: expected a finite number, got NaN$/);
    expect(() => readBlendshapes([0.5], b)).toThrow(/^setBlendshapes: expected an object of ARKit blendshape names/);
    expect(b).toEqual(before);
  });
});
