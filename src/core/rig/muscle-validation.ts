/**
 * Checking a muscle before it is packed: every field in its range (MUSCLE_RANGES, the rig schema's own), and its zone
 * a shape with a smooth falloff (the rig schema's checks across fields).
 */
import { refusal } from '../check';
import { accepts, BRUSH_RANGES, type FieldRange, MUSCLE_RANGES } from './muscle-ranges';
import { geometryProblems, isObj } from './rig-cross-checks';
import type { Muscle } from './rig-types';

const TYPES = Object.keys(MUSCLE_RANGES);

/**
 * Throws the first problem of a muscle, as `muscle <name>: <field>: expected ..., got ...`: a field out of its range
 * (MUSCLE_RANGES), a brush that is not spheres, or a zone whose field would be undefined or stepped.
 */
export function validateMuscle(m: Muscle): void {
  const what = `muscle ${typeof m?.name === 'string' ? m.name : '(unnamed)'}`;
  const number = (field: FieldRange, path: string, x: unknown): void => {
    if (!accepts(field, x)) throw refusal(what, path, field.expected, x);
  };
  const type: unknown = (m as { type?: unknown })?.type;
  if (!TYPES.includes(type as string)) throw refusal(what, 'type', 'a muscle type: "linear", "sphincter", "lid" or "jaw"', type);
  if (m.brush !== undefined) {
    if (!isObj(m.brush)) throw refusal(what, 'brush', 'a brush { add: [...], remove: [...] }', m.brush);
    for (const kind of ['add', 'remove'] as const) {
      const list: unknown = m.brush[kind];
      if (!Array.isArray(list)) throw refusal(what, `brush.${kind}`, 'an array of spheres', list);
      list.forEach((s: unknown, i) => {
        const at = `brush.${kind}[${i}]`;
        if (!Array.isArray(s) || s.length !== 4) throw refusal(what, at, 'a sphere [x, y, z, radius]', s);
        for (let k = 0; k < 3; k++) number(BRUSH_RANGES.coordinate, `${at}[${k}]`, s[k]);
        number(BRUSH_RANGES.radius, `${at}[3]`, s[3]);
      });
    }
  }
  const fields = m as unknown as Record<string, unknown>;
  for (const [key, field] of Object.entries(MUSCLE_RANGES[m.type]) as [string, FieldRange][]) {
    const value = fields[key];
    if (value === undefined && field.optional) continue;
    if (!field.vector) number(field, key, value);
    else if (!Array.isArray(value) || value.length !== 3) throw refusal(what, key, '3 numbers [x, y, z]', value);
    else value.forEach((x: unknown, i) => number(field, `${key}[${i}]`, x));
  }
  const [problem] = geometryProblems(fields);
  if (problem) throw new Error(`${what}: ${problem.path}: ${problem.message}`);
}
