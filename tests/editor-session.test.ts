import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { RigDocument } from '../src/core/rig/rig-document';
import type { Rig } from '../src/core/rig/rig-types';
import { EditorSession, type FaceEditorView } from '../src/face/editor-session';
import type { FaceExpression } from '../src/face/face-expression';

const DEFAULT_TEXT = readFileSync(new URL('../public/rigs/default.json', import.meta.url), 'utf8');

/** A session over the default rig, with a fake view and expression that record what they are told. */
function open() {
  const doc = new RigDocument(JSON.parse(DEFAULT_TEXT) as Rig);
  // The rig the face was made with, as the face keeps it: the document's own, checked and filled in.
  const rig = structuredClone(doc.rig) as Rig;
  const previews: [number | null, number][] = [];
  const expression = { setPreview: (index: number | null, value = 0) => previews.push([index, value]) } as unknown as FaceExpression;
  const session = new EditorSession(() => expression);
  let changes = 0;
  session.attachRig(doc, rig, 'default', () => changes++);
  const told: string[] = [];
  const view: FaceEditorView = {
    setEnabled: (on) => told.push(`enabled ${on}`),
    select: (name) => told.push(`select ${name}`),
    setMode: (mode) => told.push(`mode ${mode}`),
    setPart: (part) => told.push(`part ${part}`),
    part: () => null,
    gizmoPoint: () => null,
    musclePoint: () => ({ x: 1, y: 2 }),
    brushChanged: () => told.push('brush'),
    frontPoint: () => [0.02, 0.7, 0.1],
  };
  return { session, doc, previews, view, told, changes: () => changes };
}

describe('EditorSession', () => {
  it('shows a view attached later the state so far', () => {
    const { session, view, told } = open();
    session.setGizmoMode('rotate');
    session.select('zygomaticus-major-l');
    session.setEnabled(true);
    session.attachView(view);
    expect(told).toEqual(['mode rotate', 'enabled true', 'select zygomaticus-major-l']);
  });

  it('refuses an unknown muscle, a bad mode, a part the muscle lacks and a bad brush, changing nothing', () => {
    const { session, view, told } = open();
    session.attachView(view);
    session.select('zygomaticus-major-l');
    told.length = 0;
    const before = session.describe();
    expect(() => session.select('no-such-muscle')).toThrow('selectMuscle');
    expect(() => session.setGizmoMode('fly' as never)).toThrow('setGizmoMode: expected one of "translate", "rotate", "scale", got "fly"');
    expect(() => session.setGizmoPart('box')).toThrow('setGizmoPart: expected one of "insertion", "origin", got "box"');
    expect(() => session.setBrush({ radius: 1 })).toThrow('setBrush: radius: expected a number from 0.001 to 0.05, got 1');
    expect(() => session.setBrush({ mode: 'add', size: 2 } as never)).toThrow(
      'setBrush: expected one of the options mode, radius, got "size"',
    );
    expect(() => session.setPreviewContraction(Number.NaN)).toThrow('setPreviewContraction: expected a finite number, got NaN');
    expect(session.describe()).toEqual(before);
    expect(told).toEqual([]);
  });

  it('gives the preview contraction to the selected muscle and follows the selection', () => {
    const { session, doc, previews } = open();
    session.select('zygomaticus-major-l');
    session.setPreviewContraction(1.5);
    const index = doc.rig.muscles.findIndex((m) => m.name === 'zygomaticus-major-l');
    expect(previews.at(-1)).toEqual([index, 1]);
    session.select(null);
    expect(previews.at(-1)).toEqual([null, 1]);
  });

  it('keeps the selection through a rename, drops it when the muscle goes, and tells each rig change', () => {
    const { session, doc, view, changes } = open();
    session.attachView(view); // it looks at the face's left side: the new muscle is a left one
    const name = session.createMuscle('sphincter');
    expect(name).toBe('new-sphincter-l');
    expect(session.selection()).toBe(name);
    session.renameMuscle(name, 'cheek-ring-l');
    expect(session.selection()).toBe('cheek-ring-l');
    doc.removeMuscle('cheek-ring-l');
    expect(session.selection()).toBeNull();
    expect(changes()).toBe(3);
    expect(session.isRigEdited()).toBe(false);
  });

  it('reports the rig as edited until it is reverted, and undoes the revert', () => {
    const { session, doc } = open();
    doc.updateMuscle('zygomaticus-major-l', { strength: 0.3 });
    expect(session.isRigEdited()).toBe(true);
    session.revertRig();
    expect(session.isRigEdited()).toBe(false);
    doc.undo();
    expect(session.isRigEdited()).toBe(true);
  });

  it('says the face is not ready before it has a rig', () => {
    const session = new EditorSession(() => undefined);
    expect(() => session.setEnabled(true)).toThrow('the face is not ready yet');
    expect(session.enabled()).toBe(false);
  });
});
