import { readFileSync } from 'node:fs';
import { Matrix4, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { eulerMatrix } from '../src/core/math3';
import { nextMuscleDisplay, shownMuscleNames, type MuscleDisplay } from '../src/core/rig/muscle-display';
import { parseRigText } from '../src/core/rig/rig-schema';
import { MuscleView, rotationOf } from '../src/render/muscle-view';

const RIG = parseRigText(readFileSync(new URL('../public/rigs/default.json', import.meta.url), 'utf8'), 'default.json');
const NONE: MuscleDisplay = { all: false, actionUnits: [] };

describe('muscle display', () => {
  it('maps Action Units to their muscles, both sides, in rig order, each once', () => {
    expect(shownMuscleNames(RIG, { all: false, actionUnits: ['AU12'] })).toEqual(['zygomaticus-major-l', 'zygomaticus-major-r']);
    // AU27 and AU25 share the lower lip depressors.
    expect(shownMuscleNames(RIG, { all: false, actionUnits: ['AU27', 'AU25'] })).toEqual([
      'depressor-labii-inferioris-l',
      'depressor-labii-inferioris-r',
      'risorius-l',
      'risorius-r',
      'jaw',
    ]);
    expect(shownMuscleNames(RIG, NONE)).toEqual([]);
    expect(shownMuscleNames(RIG, { all: true, actionUnits: ['AU12'] })).toHaveLength(RIG.muscles.length);
  });

  it('every muscle of the default rig belongs to some Action Unit', () => {
    const all = nextMuscleDisplay(NONE, { actionUnits: RIG.actionUnits.map((au) => au.id) });
    expect(shownMuscleNames(RIG, all)).toEqual(RIG.muscles.map((m) => m.name));
  });

  it('keeps what a partial leaves out, sorts and dedupes ids, and refuses bad input naming it', () => {
    const a = nextMuscleDisplay(NONE, { actionUnits: ['AU12', 'AU6', 'AU12'] });
    expect(a).toEqual({ all: false, actionUnits: ['AU6', 'AU12'] });
    expect(nextMuscleDisplay(a, { all: true })).toEqual({ all: true, actionUnits: ['AU6', 'AU12'] });
    expect(() => nextMuscleDisplay(a, { actionUnits: ['AU12', 'AU99'] })).toThrow(/"AU99"/);
    expect(() => nextMuscleDisplay(a, { actionUnits: ['AU12L'] })).toThrow(/"AU12L"/);
    expect(() => nextMuscleDisplay(a, { all: 1 })).toThrow(/all: expected true or false/);
    expect(() => nextMuscleDisplay(a, { every: true })).toThrow(/"every"/);
    expect(() => nextMuscleDisplay(a, null)).toThrow();
    expect(a).toEqual({ all: false, actionUnits: ['AU6', 'AU12'] });
  });
});

describe('MuscleView', () => {
  it('builds a glyph per muscle, hidden, and shows exactly the names asked for', () => {
    const view = new MuscleView(RIG.muscles);
    expect(view.group.children).toHaveLength(RIG.muscles.length);
    expect(view.group.visible).toBe(false);
    expect(view.shown()).toEqual([]);
    view.setVisible(new Set(['mentalis', 'jaw', 'not-a-muscle']));
    expect(view.group.visible).toBe(true);
    expect(view.shown()).toEqual(['mentalis', 'jaw']);
    view.setVisible('all');
    expect(view.shown()).toHaveLength(RIG.muscles.length);
    view.setVisible('none');
    expect(view.group.visible).toBe(false);
    view.dispose();
  });

  it('puts a linear muscle rod from origin to insertion in the frame given', () => {
    const frame = new Matrix4().makeTranslation(0.1, 0, 0);
    const view = new MuscleView(RIG.muscles, frame);
    view.group.updateMatrixWorld(true);
    const zyg = RIG.muscles.find((m) => m.name === 'zygomaticus-major-l');
    if (zyg?.type !== 'linear') throw new Error('no zygomaticus');
    const rod = view.group.getObjectByName('zygomaticus-major-l')!.children[0];
    // The unit rod runs from y = -0.5 to 0.5.
    const a = new Vector3(0, -0.5, 0).applyMatrix4(rod.matrixWorld);
    const b = new Vector3(0, 0.5, 0).applyMatrix4(rod.matrixWorld);
    expect(a.distanceTo(new Vector3(...zyg.origin).add(new Vector3(0.1, 0, 0)))).toBeLessThan(1e-6);
    expect(b.distanceTo(new Vector3(...zyg.insertion).add(new Vector3(0.1, 0, 0)))).toBeLessThan(1e-6);
    view.dispose();
  });

  it('turns frames as the rig does (R = Rz Ry Rx)', () => {
    const rotation: [number, number, number] = [20, -35, 50];
    const r = new Array<number>(9);
    eulerMatrix(rotation, r);
    const m = new Matrix4().makeRotationFromQuaternion(rotationOf(rotation)).elements; // column-major
    for (let row = 0; row < 3; row++) for (let col = 0; col < 3; col++) expect(m[col * 4 + row]).toBeCloseTo(r[row * 3 + col], 12);
  });

  it('brightens a contracted muscle and leaves the others', () => {
    const view = new MuscleView(RIG.muscles);
    const mesh = (name: string): { color: { r: number } } =>
      (view.group.getObjectByName(name)!.children[0] as unknown as { material: { color: { r: number } } }).material;
    const before = mesh('mentalis').color.r;
    const c = new Float32Array(RIG.muscles.length);
    c[RIG.muscles.findIndex((m) => m.name === 'mentalis')] = 1;
    view.setContractions(c);
    expect(mesh('mentalis').color.r).toBeGreaterThan(before + 0.1);
    expect(mesh('zygomaticus-major-l').color.r).toBeCloseTo(before, 6);
    view.dispose();
  });
});
