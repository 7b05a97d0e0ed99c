import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { newMuscle, RigDocument, type RigChange } from '../src/core/rig/rig-document';
import { mirrorMuscle, twinName } from '../src/core/rig/rig-mirror';
import { RigError } from '../src/core/rig/rig-problems';
import { parseRig } from '../src/core/rig/rig-schema';
import type { LinearMuscle, Rig } from '../src/core/rig/rig-types';

const DEFAULT_TEXT = readFileSync(new URL('../public/rigs/default.json', import.meta.url), 'utf8');
const defaultRig = (): Rig => JSON.parse(DEFAULT_TEXT) as Rig;

/** A document of the default rig and the changes it reports. */
function open() {
  const doc = new RigDocument(defaultRig());
  const changes: RigChange[] = [];
  doc.onChange((c) => changes.push(c));
  return { doc, changes };
}

/** The error `f` throws (it must throw). */
function thrown(f: () => void): Error {
  try {
    f();
  } catch (e) {
    return e as Error;
  }
  throw new Error('no error was thrown');
}

describe('RigDocument edits', () => {
  it('updates one muscle, reports only its index, and undo brings the rig back exactly', () => {
    const { doc, changes } = open();
    const before = JSON.stringify(doc.rig);
    const i = doc.indexOf('zygomaticus-major-l');
    doc.updateMuscle('zygomaticus-major-l', { insertion: [0.05, 0.66, 0.12], strength: 0.5 });
    const m = doc.muscle('zygomaticus-major-l') as LinearMuscle;
    expect(m.insertion).toEqual([0.05, 0.66, 0.12]);
    expect(m.strength).toBe(0.5);
    expect(changes).toEqual([{ kind: 'muscles', indices: [i] }]);
    expect(doc.undo()).toBe(true);
    expect(JSON.stringify(doc.rig)).toBe(before);
    expect(doc.redo()).toBe(true);
    expect((doc.muscle('zygomaticus-major-l') as LinearMuscle).strength).toBe(0.5);
  });

  it('refuses a bad edit with a path-named message and leaves the rig and its history unchanged', () => {
    const { doc, changes } = open();
    const before = JSON.stringify(doc.rig);
    const i = doc.indexOf('zygomaticus-major-l');
    const cases: [Record<string, unknown>, string][] = [
      [{ strength: Number.NaN }, `updateMuscle: muscles[${i}].strength: expected a number, got NaN`],
      [{ insertion: [1e6, 0.7, 0.1] }, `updateMuscle: muscles[${i}].insertion[0]: expected a coordinate within ±10 m, got 1000000`],
      [{ angle: 'wide' }, `updateMuscle: muscles[${i}].angle: expected a number, got "wide"`],
      [{ radii: [1, 1, 1] }, `updateMuscle: muscles[${i}].radii: unknown field`],
      [{ falloffEnd: 0.5 }, `updateMuscle: muscles[${i}].falloffEnd: expected more than falloffStart`],
    ];
    for (const [partial, message] of cases) {
      const e = thrown(() => doc.updateMuscle('zygomaticus-major-l', partial));
      expect(e).toBeInstanceOf(RigError);
      expect(e.message).toContain(message);
    }
    expect(thrown(() => doc.updateMuscle('nobody', { strength: 0.1 })).message).toBe('updateMuscle: no muscle named "nobody"');
    expect(JSON.stringify(doc.rig)).toBe(before);
    expect(changes).toEqual([]);
    expect(doc.canUndo).toBe(false);
  });

  it('makes a whole drag one undo step', () => {
    const { doc } = open();
    const start = (doc.muscle('zygomaticus-major-l') as LinearMuscle).insertion;
    doc.begin();
    for (let k = 1; k <= 20; k++) doc.updateMuscle('zygomaticus-major-l', { insertion: [start[0] + k * 0.0005, start[1], start[2]] });
    doc.end();
    expect(doc.historySizes()).toEqual({ undo: 1, redo: 0 });
    doc.undo();
    expect((doc.muscle('zygomaticus-major-l') as LinearMuscle).insertion).toEqual(start);
  });

  it('clears its history: undo and redo stop at the rig as it is, which stays; refused while an edit is open', () => {
    const { doc } = open();
    doc.updateMuscle('risorius-l', { strength: 0.2 });
    doc.updateMuscle('risorius-l', { strength: 0.3 });
    doc.undo();
    const now = JSON.stringify(doc.rig);
    expect(doc.historySizes()).toEqual({ undo: 1, redo: 1 });
    doc.clearHistory();
    expect(doc.historySizes()).toEqual({ undo: 0, redo: 0 });
    expect(doc.undo()).toBe(false);
    expect(doc.redo()).toBe(false);
    expect(JSON.stringify(doc.rig)).toBe(now);
    doc.begin();
    doc.updateMuscle('risorius-l', { strength: 0.4 });
    expect(thrown(() => doc.clearHistory()).message).toMatch(/^clearRigHistory: an edit is open/);
    doc.end();
    expect(doc.historySizes()).toEqual({ undo: 1, redo: 0 });
  });

  it('keeps 100 steps of undo, each back to its own state', () => {
    const { doc } = open();
    const states = [JSON.stringify(doc.rig)];
    for (let k = 1; k <= 120; k++) {
      doc.updateMuscle('risorius-l', { strength: 0.001 * k });
      states.push(JSON.stringify(doc.rig));
    }
    for (let k = 119; k >= 20; k--) {
      expect(doc.undo()).toBe(true);
      expect(JSON.stringify(doc.rig)).toBe(states[k]);
    }
  });

  it('renames a muscle with its Action Unit links, and reports a structural change', () => {
    const { doc, changes } = open();
    doc.renameMuscle('zygomaticus-major-l', 'smile-l');
    const au12 = doc.rig.actionUnits.find((a) => a.id === 'AU12')!;
    expect(au12.muscles.map((l) => l.muscle)).toContain('smile-l');
    expect(changes).toEqual([{ kind: 'structure' }]);
    expect(thrown(() => doc.renameMuscle('smile-l', 'zygomaticus-major-r')).message).toContain(
      'duplicate muscle name "zygomaticus-major-r"',
    );
  });

  it('adds, duplicates and removes muscles; removing the last muscle of a unit is refused', () => {
    const { doc } = open();
    const count = doc.rig.muscles.length;
    doc.addMuscle(newMuscle('sphincter', 'test-ring', [0, 0.7, 0.1]), 'AU18');
    expect(doc.rig.muscles).toHaveLength(count + 1);
    expect(doc.rig.actionUnits.find((a) => a.id === 'AU18')!.muscles.map((l) => l.muscle)).toContain('test-ring');
    const copy = doc.duplicateMuscle('zygomaticus-major-l');
    expect(copy).toBe('zygomaticus-major-copy-l');
    expect((doc.muscle(copy) as LinearMuscle).insertion[1]).toBeCloseTo(
      (doc.muscle('zygomaticus-major-l') as LinearMuscle).insertion[1] + 0.004,
      9,
    );
    doc.removeMuscle('test-ring');
    expect(doc.rig.actionUnits.find((a) => a.id === 'AU18')!.muscles.map((l) => l.muscle)).not.toContain('test-ring');
    const e = thrown(() => doc.removeMuscle('mentalis'));
    expect(e.message).toMatch(/removeMuscle: actionUnits\[\d+\]\.muscles: expected at least one muscle/);
    expect(doc.rig.muscles.some((m) => m.name === 'mentalis')).toBe(true);
  });

  it('assigns a muscle to an Action Unit on its own side, replacing its previous links', () => {
    const { doc } = open();
    doc.assignMuscle('risorius-l', 'AU12', 0.5);
    const links = doc.rig.actionUnits.flatMap((a) => a.muscles.filter((l) => l.muscle === 'risorius-l').map((l) => ({ id: a.id, ...l })));
    expect(links).toEqual([{ id: 'AU12', muscle: 'risorius-l', side: 'left', weight: 0.5 }]);
    expect(thrown(() => doc.assignMuscle('risorius-l', 'AU99')).message).toContain('no Action Unit "AU99"');
  });
});

describe('mirroring across x = 0', () => {
  it('mirror of a mirror is the muscle itself, and the default rig is its own left side mirrored', () => {
    const rig = parseRig(defaultRig());
    for (const m of rig.muscles) expect(mirrorMuscle(mirrorMuscle(m))).toEqual(m);
    const { doc, changes } = open();
    doc.mirrorSide('left');
    // The default rig's right side is its left side mirrored, so nothing changes.
    expect(changes).toEqual([]);
  });

  it('a mirrored muscle takes its painted brush spheres to the other side', () => {
    const rig = parseRig(defaultRig());
    const left = rig.muscles.find((m) => m.name === 'orbicularis-oculi-orbital-l')!;
    expect(left.brush?.remove.length).toBeGreaterThan(0);
    const mirrored = mirrorMuscle(left);
    expect(mirrored.brush!.remove).toEqual(left.brush!.remove.map(([x, y, z, r]) => [-x, y, z, r]));
  });

  it('a mirrored update moves the twin to the reflected point in the same step', () => {
    const { doc } = open();
    doc.updateMuscle('zygomaticus-major-l', { insertion: [0.051, 0.65, 0.125] }, { mirror: true });
    expect((doc.muscle('zygomaticus-major-r') as LinearMuscle).insertion).toEqual([-0.051, 0.65, 0.125]);
    expect(doc.historySizes().undo).toBe(1);
    doc.undo();
    expect((doc.muscle('zygomaticus-major-r') as LinearMuscle).insertion).toEqual(
      (defaultRig().muscles.find((m) => m.name === 'zygomaticus-major-r') as LinearMuscle).insertion,
    );
  });

  it('mirrors one muscle onto a new twin with mirrored links, and mirrors a whole side', () => {
    const { doc } = open();
    doc.addMuscle(newMuscle('linear', 'test-l', [0.03, 0.7, 0.12]), 'AU12');
    expect(doc.mirrorMuscle('test-l')).toBe('test-r');
    const twin = doc.muscle('test-r') as LinearMuscle;
    expect(twin.side).toBe('right');
    expect(twin.insertion).toEqual([-0.03, 0.7, 0.12]);
    expect(doc.rig.actionUnits.find((a) => a.id === 'AU12')!.muscles).toContainEqual({ muscle: 'test-r', side: 'right', weight: 1 });
    doc.updateMuscle('risorius-r', { strength: 0.33 });
    doc.updateMuscle('platysma-r', { angle: 33 });
    doc.mirrorSide('left');
    expect((doc.muscle('risorius-r') as LinearMuscle).strength).toBe((doc.muscle('risorius-l') as LinearMuscle).strength);
    expect((doc.muscle('platysma-r') as LinearMuscle).angle).toBe((doc.muscle('platysma-l') as LinearMuscle).angle);
    expect(twinName('mentalis')).toBeUndefined();
    expect(thrown(() => doc.mirrorMuscle('mentalis')).message).toContain('has no twin');
  });
});

describe('replacing the rig', () => {
  it('refuses a bad document naming its path, leaves the rig as it was, and migrates a document without a version', () => {
    const { doc } = open();
    const before = JSON.stringify(doc.rig);
    const bad = defaultRig();
    (bad.muscles[3] as LinearMuscle).origin = [0, Number.NaN, 0];
    expect(thrown(() => doc.replace(bad)).message).toBe('setRig: muscles[3].origin[1]: expected a number, got NaN');
    expect(JSON.stringify(doc.rig)).toBe(before);
    const old = defaultRig() as Partial<Rig>;
    delete old.version;
    old.muscles![0] = { ...old.muscles![0], name: 'renamed' } as LinearMuscle;
    old.actionUnits = old.actionUnits!.map((a) => ({
      ...a,
      muscles: a.muscles.map((l) => (l.muscle === 'frontalis-inner-l' ? { ...l, muscle: 'renamed' } : l)),
    }));
    doc.replace(old);
    expect(doc.rig.version).toBe(2);
    expect(doc.rig.muscles[0].name).toBe('renamed');
    doc.undo();
    expect(JSON.stringify(doc.rig)).toBe(before);
  });

  it('refuses a list of muscles over the limit without reading it item by item', () => {
    const { doc } = open();
    const huge = { ...defaultRig(), muscles: new Array(1_000_000).fill(0) };
    expect(thrown(() => doc.replace(huge)).message).toBe('setRig: muscles: expected at most 256 items, got 1000000');
  });
});
