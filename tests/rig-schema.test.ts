import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { RigError } from '../src/core/rig/rig-problems';
import { MAX_RIG_BYTES, parseRig, parseRigText } from '../src/core/rig/rig-schema';
import type { Muscle, Rig } from '../src/core/rig/rig-types';

const DEFAULT_TEXT = readFileSync(new URL('../public/rigs/default.json', import.meta.url), 'utf8');

/** A fresh, mutable copy of the default rig document. */
function defaultDoc(): Rig {
  return JSON.parse(DEFAULT_TEXT) as Rig;
}

/** The error `parseRig` throws for the default document after `mutate`. */
function rejection(mutate: (doc: Rig) => void, source?: string): RigError {
  const doc = defaultDoc();
  mutate(doc);
  try {
    parseRig(doc, source);
  } catch (e) {
    expect(e).toBeInstanceOf(RigError);
    return e as RigError;
  }
  throw new Error('the document was accepted');
}

function textRejection(text: string, source?: string): RigError {
  try {
    parseRigText(text, source);
  } catch (e) {
    expect(e).toBeInstanceOf(RigError);
    return e as RigError;
  }
  throw new Error('the text was accepted');
}

const indexOfType = (doc: Rig, type: Muscle['type']) => doc.muscles.findIndex((m) => m.type === type);

describe('the default rig (public/rigs/default.json)', () => {
  const rig = parseRigText(DEFAULT_TEXT, 'default.json');

  it('parses, with muscles, Action Units and presets', () => {
    expect(rig.format).toBe('softface-rig');
    expect(rig.muscles.length).toBeGreaterThan(30);
    expect(rig.actionUnits).toHaveLength(33);
    expect(rig.presets.map((p) => p.name)).toEqual(
      expect.arrayContaining([
        'thesis-happiness',
        'thesis-sadness',
        'thesis-laughing',
        'thesis-anger',
        'thesis-surprise',
        'happiness',
        'sadness',
        'surprise',
        'fear',
        'anger',
        'disgust',
        'contempt',
      ]),
    );
  });

  it('mirrors every left muscle exactly onto the right (x negated, brush spheres too, Euler y and z negated, all else equal)', () => {
    const byName = new Map(rig.muscles.map((m) => [m.name, m]));
    const left = rig.muscles.filter((m) => m.side === 'left');
    expect(left.length).toBe(rig.muscles.filter((m) => m.side === 'right').length);
    for (const l of left) {
      const r = byName.get(l.name.replace(/-l$/, '-r'));
      expect(r, l.name).toBeDefined();
      const mirrored = JSON.parse(JSON.stringify(l), (key, value) => {
        if (['origin', 'insertion', 'center'].includes(key)) return [-value[0] || 0, value[1], value[2]];
        if (key === 'rotation') return [value[0], -value[1] || 0, -value[2] || 0];
        if (key === 'add' || key === 'remove') return value.map((s: number[]) => [-s[0] || 0, s[1], s[2], s[3]]);
        return value;
      });
      expect({ ...r, name: l.name, side: 'left' }).toEqual(mirrored);
      const xs = [l, r!].map((m) => ('origin' in m ? m.insertion[0] : m.center[0]));
      expect(xs[0]).toBeGreaterThan(0); // the subject's left is +x
    }
  });

  it('keeps midline muscles on the midline', () => {
    for (const m of rig.muscles.filter((x) => x.side === 'mid')) {
      const points = 'origin' in m ? [m.origin, m.insertion] : [m.center];
      for (const p of points) expect(p[0], m.name).toBe(0);
    }
  });
});

describe('parseRig', () => {
  it('rejects a negative radius with its path, the problem and the value found', () => {
    const i = indexOfType(defaultDoc(), 'sphincter');
    const e = rejection((doc) => {
      (doc.muscles[i] as { radii: number[] }).radii[1] = -0.01;
    });
    expect(e.message).toBe(`rig: muscles[${i}].radii[1]: expected a positive length of at most 10 m, got -0.01`);
    expect(e.problems).toEqual([{ path: `muscles[${i}].radii[1]`, message: 'expected a positive length of at most 10 m, got -0.01' }]);
  });

  it('rejects a missing field', () => {
    const e = rejection((doc) => {
      delete (doc.muscles[0] as Partial<Muscle>).name;
    });
    expect(e.message).toContain('rig: muscles[0].name: missing');
  });

  it('rejects an unknown muscle type and an unknown field', () => {
    const e = rejection((doc) => {
      (doc.muscles[2] as { type: string }).type = 'spring';
      (doc.muscles[3] as unknown as Record<string, unknown>).colour = 'red';
    });
    expect(e.message).toContain('rig: muscles[2].type: expected a muscle type: "linear", "sphincter", "lid" or "jaw", got "spring"');
    expect(e.message).toContain('rig: muscles[3].colour: unknown field');
  });

  it('rejects a duplicate muscle name, pointing at the second one', () => {
    const e = rejection((doc) => {
      doc.muscles.push({ ...doc.muscles[1] });
    });
    const last = defaultDoc().muscles.length;
    expect(e.message).toBe(`rig: muscles[${last}].name: duplicate muscle name "${defaultDoc().muscles[1].name}" (also muscles[1])`);
  });

  it('rejects an Action Unit that names a missing muscle', () => {
    const e = rejection((doc) => {
      doc.actionUnits[0].muscles[1].muscle = 'no-such-muscle';
    });
    expect(e.message).toContain('rig: actionUnits[0].muscles[1].muscle: no muscle named "no-such-muscle" in muscles');
  });

  it('rejects sides that do not fit the Action Unit', () => {
    const doc = defaultDoc();
    const bilateral = doc.actionUnits.findIndex((u) => u.bilateral);
    const midline = doc.actionUnits.findIndex((u) => !u.bilateral);
    const e = rejection((d) => {
      d.actionUnits[bilateral].muscles = d.actionUnits[bilateral].muscles.filter((m) => m.side === 'left');
      d.actionUnits[midline].muscles[0].side = 'left';
    });
    expect(e.message).toContain(
      `rig: actionUnits[${bilateral}].muscles: bilateral ${doc.actionUnits[bilateral].id} has no muscle on the right side`,
    );
    expect(e.message).toContain(
      `rig: actionUnits[${midline}].muscles[0].side: expected "mid" for midline ${doc.actionUnits[midline].id}, got "left"`,
    );
  });

  it('rejects a preset naming an unknown Action Unit, or a side of a midline one', () => {
    const e = rejection((doc) => {
      doc.presets[0].actionUnits.AU99 = 0.5;
      doc.presets[1].actionUnits.AU26L = 0.5;
    });
    expect(e.message).toContain('rig: presets[0].actionUnits.AU99: no Action Unit AU99 in actionUnits');
    expect(e.message).toContain('rig: presets[1].actionUnits.AU26L: AU26 is a midline Action Unit and has no sides: use "AU26"');
  });

  it('rejects falloffStart >= falloffEnd, |maxAngle| > 90 and non-finite numbers', () => {
    const doc = defaultDoc();
    const linear = indexOfType(doc, 'linear');
    const lid = indexOfType(doc, 'lid');
    const jaw = indexOfType(doc, 'jaw');
    const e = rejection((d) => {
      Object.assign(d.muscles[linear], { falloffStart: 1.3, falloffEnd: 1.2 });
      Object.assign(d.muscles[lid], { maxAngle: -91 });
      Object.assign(d.muscles[jaw], { fade: Infinity });
    });
    expect(e.problems).toEqual(
      expect.arrayContaining([
        { path: `muscles[${linear}].falloffEnd`, message: 'expected more than falloffStart (1.3), got 1.2' },
        { path: `muscles[${lid}].maxAngle`, message: 'expected an angle from -90 to 90 degrees, got -91' },
        { path: `muscles[${jaw}].fade`, message: 'expected a finite number, got Infinity' },
      ]),
    );
  });

  it('lists every problem, one line each, under the given source name', () => {
    const e = rejection((doc) => {
      (doc as { version: number }).version = 3;
      doc.presets[0].actionUnits.AU12 = 1.5;
    }, 'rigs/custom.json');
    expect(e.message.split('\n')).toEqual([
      'rigs/custom.json: version: expected version 2, got 3',
      'rigs/custom.json: presets[0].actionUnits.AU12: expected a number from 0 to 1, got 1.5',
    ]);
  });

  it('rejects what is not a rig document at all', () => {
    expect(() => parseRig(null)).toThrow('rig: expected a rig document (a JSON object), got null');
    expect(() => parseRig([])).toThrow('rig: expected a rig document (a JSON object), got []');
  });

  it('returns a copy, not the input', () => {
    const doc = defaultDoc();
    const rig = parseRig(doc);
    expect(rig).toEqual(doc);
    expect(rig).not.toBe(doc);
    expect(rig.muscles[0]).not.toBe(doc.muscles[0]);
  });
});

describe('parseRigText', () => {
  it('reports a JSON syntax error with its line and column, under the source name', () => {
    const e = textRejection('{\n  "format": "softface-rig",\n  "version" 1\n}', 'broken.json');
    expect(e.message).toBe("broken.json: invalid JSON at line 3, column 13: expected ':' after a property name, got '1'");
  });

  it.each([
    ['{"a":1,}', "line 1, column 8: expected a property name in double quotes, got '}'"],
    ['[1,]', "line 1, column 4: expected a value, got ']'"],
    ['', 'line 1, column 1: expected a value, got the end of the text'],
    ['{"a": "b', `line 1, column 9: expected a closing '"' for the string, got the end of the text`],
    ['{} x', "line 1, column 4: expected the end of the text after the document, got 'x'"],
  ])('places the error in %j', (text, where) => {
    expect(textRejection(text).message).toBe(`rig: invalid JSON at ${where}`);
  });

  it('refuses a text over the size limit before parsing it', () => {
    const text = `${' '.repeat(MAX_RIG_BYTES - 1)}{}`; // valid JSON, one byte too long
    const e = textRejection(text, 'huge.json');
    expect(e.message).toBe(
      `huge.json: the document is ${MAX_RIG_BYTES + 1} bytes (5 MiB), over the limit of ${MAX_RIG_BYTES} bytes (5 MiB) for rig documents`,
    );
  });

  it('counts the size in UTF-8 bytes', () => {
    const text = `{"x":"${'é'.repeat(MAX_RIG_BYTES / 2)}"}`; // 2 bytes per character
    expect(textRejection(text).message).toContain('over the limit');
  });

  it('accepts a byte-order mark', () => {
    expect(parseRigText(`\uFEFF${DEFAULT_TEXT}`).muscles.length).toBeGreaterThan(0);
  });
});
