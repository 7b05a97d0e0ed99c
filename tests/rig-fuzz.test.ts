import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { MuscleRig } from '../src/core/rig/muscles';
import { mulberry32 as random } from '../src/core/random';
import { RigDocument } from '../src/core/rig/rig-document';
import { RigError } from '../src/core/rig/rig-problems';

const DEFAULT_TEXT = readFileSync(new URL('../public/rigs/default.json', import.meta.url), 'utf8');

type Json = unknown;

/** Every path to a value in a document: [container, key] pairs. */
function slots(doc: Json): [Record<string | number, Json>, string | number][] {
  const out: [Record<string | number, Json>, string | number][] = [];
  const walk = (x: Json): void => {
    if (typeof x !== 'object' || x === null) return;
    for (const key of Object.keys(x)) {
      const k = Array.isArray(x) ? Number(key) : key;
      out.push([x as Record<string | number, Json>, k]);
      walk((x as Record<string, Json>)[key]);
    }
  };
  walk(doc);
  return out;
}

function deep(depth: number): Json {
  let x: Json = 1;
  for (let i = 0; i < depth; i++) x = [x];
  return x;
}

/** Replacement values: out of range, not finite, of the wrong type, huge or deeply nested. */
function value(r: () => number, old: Json): Json {
  // Two in five are plausible tweaks of a number, which the schema often accepts; the rest are hostile.
  const pick = r() < 0.4 ? 4 + Math.floor(r() * 2) : Math.floor(r() * 16);
  switch (pick) {
    case 0:
      return Number.NaN;
    case 1:
      return Number.POSITIVE_INFINITY;
    case 2:
      return 1e6 * (r() - 0.5); // a point up to 500 km away
    case 3:
      return -r();
    case 4:
      return typeof old === 'number' ? old * (1 + (r() - 0.5) * 0.2) : r(); // a plausible tweak, often accepted
    case 5:
      return typeof old === 'number' ? old + (r() - 0.5) * 0.02 : 0.5;
    case 6:
      return 'text';
    case 7:
      return null;
    case 8:
      return {};
    case 9:
      return [];
    case 10:
      return new Array(100_000).fill(0.1);
    case 11:
      return deep(5_000);
    case 12:
      return [r(), r()];
    case 13:
      return true;
    case 14:
      return typeof old === 'string' ? `${old}-x` : 'zygomaticus-major-r';
    default:
      return { extra: r() };
  }
}

/** Rest points over the face (a box around the mouth, nose and brows) where accepted rigs are tried. */
const REST = (() => {
  const p: number[] = [];
  for (let x = -0.08; x <= 0.08; x += 0.01)
    for (let y = 0.6; y <= 0.84; y += 0.01) for (let z = 0.09; z <= 0.16; z += 0.01) p.push(x, y, z);
  return Float32Array.from(p);
})();

describe('setRig with 1,200 seeded mutations of the default rig', () => {
  it('accepts each with finite muscle targets, or refuses it naming a path, never changing the current rig', () => {
    const r = random(20_240_611);
    let accepted = 0;
    let refused = 0;
    for (let c = 0; c < 1200; c++) {
      const doc = new RigDocument(JSON.parse(DEFAULT_TEXT));
      const before = JSON.stringify(doc.rig);
      const mutant = JSON.parse(DEFAULT_TEXT) as Json;
      const edits = 1 + Math.floor(r() * 3);
      for (let e = 0; e < edits; e++) {
        const all = slots(mutant);
        const [container, key] = all[Math.floor(r() * all.length)];
        const action = r();
        if (action < 0.15 && !Array.isArray(container)) delete container[key];
        else if (action < 0.25 && !Array.isArray(container)) container[`extra${c}`] = 1;
        else container[key] = value(r, container[key]);
      }
      try {
        doc.replace(mutant);
      } catch (error) {
        expect(error, `case ${c}`).toBeInstanceOf(RigError);
        const problems = (error as RigError).problems;
        expect(problems.length, `case ${c}`).toBeGreaterThan(0);
        for (const p of problems) {
          expect(p.message, `case ${c}`).toMatch(/\S/);
          expect(typeof p.path, `case ${c}`).toBe('string');
        }
        // Each line names the source and, for a problem inside the document, its path.
        for (const p of problems.slice(0, 50))
          expect((error as Error).message, `case ${c}`).toContain(p.path ? `setRig: ${p.path}: ` : 'setRig: ');
        expect((error as Error).message.startsWith('setRig: '), `case ${c}`).toBe(true);
        expect(JSON.stringify(doc.rig), `case ${c}`).toBe(before);
        refused++;
        continue;
      }
      accepted++;
      const rig = new MuscleRig(REST, doc.rig.muscles);
      const n = REST.length / 3;
      const out = { targets: new Float32Array(3 * n), weights: new Float32Array(n), normalWeights: new Float32Array(n) };
      rig.compute(new Float32Array(doc.rig.muscles.length).fill(1), out);
      for (let i = 0; i < out.targets.length; i++) {
        if (!Number.isFinite(out.targets[i]) || Math.abs(out.targets[i] - REST[i]) > 100)
          throw new Error(`case ${c}: target ${i} is ${out.targets[i]}`);
      }
    }
    console.log(`fuzz: ${accepted} accepted, ${refused} refused`);
    expect(accepted).toBeGreaterThan(50);
    expect(refused).toBeGreaterThan(500);
  });
});
