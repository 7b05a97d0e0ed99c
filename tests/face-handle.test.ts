import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { parseRigText } from '../src/core/rig/rig-schema';
import { FaceExpression } from '../src/face/face-expression';
import { createControllers, FaceHandle } from '../src/face/face-handle';
import { FaceParts } from '../src/face/face-parts';
import type { FaceChange } from '../src/face/face-ports';
import type { SkinSimulation } from '../src/sim/main/skin-simulation';

const RIG = parseRigText(readFileSync(new URL('../public/rigs/default.json', import.meta.url), 'utf8'), 'default.json');

/** A handle over fake parts: a real expression of the default rig, and a simulation that only counts contractions sent. */
function makeFace() {
  const parts = new FaceParts();
  let teardowns = 0;
  let sent = 0;
  let resolve!: () => void;
  const ready = new Promise<void>((r) => {
    resolve = r;
  });
  const handle = new FaceHandle(parts, createControllers(parts, ready), ready, () => teardowns++);
  const start = (): void => {
    parts.simulation = { rest: new Float32Array(3) } as unknown as SkinSimulation;
    parts.expression = new FaceExpression(RIG, () => sent++);
    resolve();
  };
  const changes: FaceChange[] = [];
  handle.onChange((c) => changes.push(c));
  return { parts, handle, start, changes, teardowns: () => teardowns, sent: () => sent };
}

describe('FaceHandle', () => {
  it('answers every delegated method through its controller, which tells listeners what changed', () => {
    const { handle, start, changes, sent } = makeFace();
    start();
    handle.setActionUnit('AU12L', 0.5);
    expect(handle.getActionUnits().AU12L).toBe(0.5);
    expect(handle.getActionUnits().AU12R).toBe(0);
    expect(changes).toEqual(['expression']);
    expect(sent()).toBeGreaterThan(0);
    handle.applyPreset('happiness', 0.4);
    expect(handle.listPresets().find((p) => p.name === 'happiness')?.weight).toBe(0.4);
    expect(changes).toEqual(['expression', 'expression']);
  });

  it('has each delegated method on its prototype, not on the instance', () => {
    const { handle } = makeFace();
    for (const name of ['setActionUnit', 'setTimeline', 'loadHead', 'exportGLTF', 'setLight', 'undo', 'setEditor', 'settle'])
      expect(Object.hasOwn(FaceHandle.prototype, name), name).toBe(true);
    expect(Object.keys(handle)).not.toContain('setActionUnit');
  });

  it('refuses calls before the face is ready, naming what to wait for', () => {
    const { handle, changes } = makeFace();
    expect(() => handle.setActionUnit('AU12', 1)).toThrow('the face is not ready yet: await face.ready first');
    expect(() => handle.play()).toThrow('not ready yet');
    expect(changes).toEqual([]);
  });

  it('changes nothing and tells no one when a controller refuses a value', () => {
    const { handle, start, changes } = makeFace();
    start();
    expect(() => handle.setActionUnit('AU99', 1)).toThrow(/AU99/);
    expect(() => handle.setOverlay(['AU12L', 'AU12R'], [1])).toThrow('setOverlay: values: expected 2 values, one per id, got [1]');
    expect(() => handle.setOverlay(['AU12L'], [Number.NaN])).toThrow('setOverlay: AU12L: expected a finite number, got NaN');
    expect(handle.getOverlay().AU12L ?? 0).toBe(0);
    expect(changes).toEqual([]);
  });

  it('after dispose throws from every method, tells no listener and tears down once', () => {
    const { handle, start, changes, teardowns } = makeFace();
    start();
    handle.dispose();
    handle.dispose();
    expect(teardowns()).toBe(1);
    expect(handle.isDisposed()).toBe(true);
    expect(() => handle.setActionUnit('AU12', 1)).toThrow('the face was disposed');
    expect(() => handle.getMuscleDisplay()).toThrow('the face was disposed');
    expect(() => handle.onChange(() => {})).toThrow('the face was disposed');
    expect(changes).toEqual([]);
  });

  it('tells every listener even when one unsubscribes while being told', () => {
    const { handle, start } = makeFace();
    start();
    const told: string[] = [];
    const stopA = handle.onChange(() => {
      told.push('a');
      stopA();
    });
    handle.onChange(() => told.push('b'));
    handle.reset();
    handle.reset();
    expect(told).toEqual(['a', 'b', 'b']);
  });
});
