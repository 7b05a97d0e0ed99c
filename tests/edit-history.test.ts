import { describe, expect, it } from 'vitest';
import { EditHistory } from '../src/core/rig/edit-history';

/** A counter edited through the history, as RigDocument drives it. */
function counter(limit?: number) {
  const history = new EditHistory<number>(limit);
  let value = 0;
  return {
    history,
    get value() {
      return value;
    },
    set(next: number) {
      history.record(value);
      value = next;
    },
    undo() {
      const v = history.undo(value);
      if (v !== undefined) value = v;
      return v !== undefined;
    },
    redo() {
      const v = history.redo(value);
      if (v !== undefined) value = v;
      return v !== undefined;
    },
  };
}

describe('EditHistory', () => {
  it('undoes and redoes steps in order, and a new edit clears the redo steps', () => {
    const c = counter();
    c.set(1);
    c.set(2);
    c.set(3);
    expect(c.undo()).toBe(true);
    expect(c.value).toBe(2);
    expect(c.undo()).toBe(true);
    expect(c.value).toBe(1);
    expect(c.redo()).toBe(true);
    expect(c.value).toBe(2);
    c.set(10);
    expect(c.history.canRedo).toBe(false);
    expect(c.redo()).toBe(false);
    expect(c.undo()).toBe(true);
    expect(c.value).toBe(2);
    expect(c.undo() && c.undo()).toBe(true);
    expect(c.value).toBe(0);
    expect(c.undo()).toBe(false);
  });

  it('keeps at least 100 steps, and drops the oldest past its limit', () => {
    const c = counter(150);
    for (let i = 1; i <= 200; i++) c.set(i);
    let undone = 0;
    while (undone <= 200 && c.undo()) undone++;
    expect(undone).toBe(150);
    expect(c.value).toBe(50);
  });

  it('makes a transaction of many edits one step, back to the state before it; nested ones join the outer one', () => {
    const c = counter();
    c.set(1);
    c.history.begin(c.value);
    for (let i = 2; i < 30; i++) c.set(i);
    c.history.begin(c.value);
    c.set(99);
    c.history.end();
    expect(c.history.canUndo).toBe(false);
    c.history.end();
    expect(c.history.sizes).toEqual({ undo: 2, redo: 0 });
    c.undo();
    expect(c.value).toBe(1);
    c.redo();
    expect(c.value).toBe(99);
  });

  it('records no step for a transaction without edits, and refuses an end without a begin', () => {
    const c = counter();
    c.history.begin(c.value);
    c.history.end();
    expect(c.history.sizes).toEqual({ undo: 0, redo: 0 });
    expect(() => c.history.end()).toThrow('end() without begin()');
  });
});
