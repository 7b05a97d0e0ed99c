import { describe, expect, it } from 'vitest';
import { PanelSlot } from '../src/face/panel-slot';

/** A slot whose module load is held until `release` is called; counts the panels made and disposed. */
function heldSlot() {
  let release!: () => void;
  const loaded = new Promise<void>((r) => {
    release = r;
  });
  const counts = { loads: 0, made: 0, disposed: 0 };
  const slot = new PanelSlot(async () => {
    counts.loads++;
    await loaded;
    return () => {
      counts.made++;
      return { dispose: () => counts.disposed++ };
    };
  });
  return { slot, release, counts };
}

describe('PanelSlot', () => {
  it('loads and makes the panels on first use, once, and takes them back when switched off', async () => {
    const { slot, release, counts } = heldSlot();
    expect(counts.loads).toBe(0);
    const shown = slot.set(true);
    release();
    await shown;
    await slot.set(true);
    expect(slot.shown()).toBe(true);
    expect(counts.made).toBe(1);
    await slot.set(false);
    expect(slot.shown()).toBe(false);
    expect(counts.disposed).toBe(1);
  });

  it('makes no panels when switched off or disposed while the module loads', async () => {
    const off = heldSlot();
    const shown = off.slot.set(true);
    const hidden = off.slot.set(false);
    off.release();
    await Promise.all([shown, hidden]);
    expect(off.counts.made).toBe(0);
    expect(off.slot.shown()).toBe(false);

    const gone = heldSlot();
    const pending = gone.slot.set(true);
    gone.slot.dispose();
    gone.release();
    await pending;
    expect(gone.counts.made).toBe(0);
  });

  it('makes one set of panels when switched on twice while the module loads', async () => {
    const { slot, release, counts } = heldSlot();
    const a = slot.set(true);
    const b = slot.set(true);
    release();
    await Promise.all([a, b]);
    expect(counts.made).toBe(1);
    expect(slot.shown()).toBe(true);
  });
});
