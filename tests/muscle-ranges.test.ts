import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { parseRig } from '../src/core/rig/rig-schema';
import { validateMuscle } from '../src/core/rig/muscle-validation';
import { accepts, type FieldRange, MUSCLE_RANGES } from '../src/core/rig/muscle-ranges';

const defaultRig: unknown = JSON.parse(readFileSync(new URL('../public/rigs/default.json', import.meta.url), 'utf8'));

const fields = Object.entries(MUSCLE_RANGES).flatMap(([type, table]) =>
  Object.entries(table as Record<string, FieldRange>).map(([key, field]) => ({ type, key, field })),
);

describe('MUSCLE_RANGES', () => {
  it('offers on the panel only values the rig accepts', () => {
    for (const { field } of fields) {
      const [min, max] = field.slider ?? field.range;
      expect(field.step).toBeGreaterThan(0);
      if (field.slider || !field.open) {
        expect(accepts(field, min)).toBe(true);
        expect(accepts(field, max)).toBe(true);
      }
    }
  });

  it('is what both the schema and validateMuscle enforce, with the same words', () => {
    const rig = parseRig(defaultRig);
    for (const { type, key, field } of fields) {
      const index = rig.muscles.findIndex((m) => m.type === type);
      if (index < 0) continue;
      const muscle = rig.muscles[index];
      // Just past the greatest accepted value (or at it, for an open bound).
      const bad = field.open === 'greatest' ? field.range[1] : field.range[1] + 1;
      const value = field.vector ? [bad, bad, bad] : bad;
      const path = field.vector ? `${key}[0]` : key;
      expect(() => validateMuscle({ ...muscle, [key]: value } as never)).toThrow(
        `muscle ${muscle.name}: ${path}: expected ${field.expected}, got ${bad}`,
      );
      const muscles = rig.muscles.map((m, i) => (i === index ? { ...m, [key]: value } : m));
      expect(() => parseRig({ ...rig, muscles })).toThrow(`rig: muscles[${index}].${path}: expected ${field.expected}, got ${bad}`);
    }
  });
});
