import { describe, expect, it } from 'vitest';
import type { MorphShape } from '../src/render/gltf-export';
import type { FaceExpression } from '../src/face/face-expression';
import { bakeGLTF, type BakePorts } from '../src/face/gltf-bake';
import { checkExportOptions } from '../src/face/gltf-export-options';

/** Fake ports: the "skin" is one render vertex whose x is the number of Action Units and presets set to 1. */
function fakeFace() {
  const log: string[] = [];
  let current = { actionUnits: { AU4: 0.3 } as Record<string, number>, presets: { happiness: 0.5 } as Record<string, number> };
  let overlay: Record<string, number> = { AU43L: 0.2 };
  let eyesOn = true;
  let playing = true;
  let busy = false;
  let written: MorphShape[] = [];
  const expression = {
    getActionUnits: () => ({ ...current.actionUnits }),
    listPresets: () => [
      { name: 'happiness', weight: current.presets.happiness ?? 0 },
      { name: 'sadness', weight: current.presets.sadness ?? 0 },
    ],
    getOverlay: () => ({ ...overlay }),
    set: (e: typeof current) => {
      current = { actionUnits: { ...e.actionUnits }, presets: { ...e.presets } };
      log.push(`set ${[...Object.keys(e.actionUnits), ...Object.keys(e.presets)].join('+') || 'neutral'}`);
    },
    clearOverlay: () => {
      overlay = {};
    },
    setOverlay: (ids: string[], values: number[]) => {
      overlay = Object.fromEntries(ids.map((id, i) => [id, values[i]]));
    },
    setPreview: (index: number | null) => log.push(`preview ${index}`),
  } as unknown as FaceExpression;
  const ports: BakePorts = {
    expression,
    simulation: {
      settle: async () => {
        log.push('settle');
      },
      readRender: (p: Float32Array) => {
        p[0] =
          Object.values(current.actionUnits).filter((v) => v === 1).length + Object.values(current.presets).filter((v) => v === 1).length;
      },
    },
    player: {
      set: () => {},
      timeline: () => null,
      play: () => {
        playing = true;
      },
      pause: () => {
        playing = false;
      },
      seek: () => {},
      state: () => ({ loaded: false, playing, time: 0, duration: 0, loop: false }),
    },
    writer: {
      vertexCount: 1,
      jawPose: () => null,
      write: async (shapes) => {
        written = [...shapes];
        return new ArrayBuffer(4);
      },
    },
    eyes: {
      setEnabled: (on) => {
        eyesOn = on;
      },
      enabled: () => eyesOn,
      showGaze: () => {},
      stats: () => ({ on: eyesOn, blinks: 0, saccades: 0, blink: 0, time: 0, gaze: { yaw: 0, pitch: 0 } }),
    },
    presets: ['happiness', 'sadness'],
    expressionChanged: () => log.push('changed'),
    restorePreview: () => log.push('preview back'),
    alive: () => true,
    begin: () => {
      if (busy) throw new Error('exportGLTF: another export is under way');
      busy = true;
    },
    end: () => {
      busy = false;
    },
  };
  return { ports, log, state: () => ({ current, overlay, eyesOn, playing, busy }), written: () => written };
}

describe('bakeGLTF', () => {
  it('solves each target on its own from the neutral face, writes them, and gives the face back what it had', async () => {
    const f = fakeFace();
    const blob = await bakeGLTF(f.ports, checkExportOptions({ actionUnits: ['AU12'], presets: ['sadness'] }));
    expect(blob.type).toBe('model/gltf-binary');
    expect(f.written().map((s) => [s.name, s.positions[0]])).toEqual([
      ['AU12', 1],
      ['sadness', 1],
    ]);
    expect(f.log.filter((l) => l.startsWith('set '))).toEqual([
      'set neutral',
      'set AU12',
      'set neutral',
      'set sadness',
      'set neutral',
      'set AU4+happiness+sadness',
    ]);
    // Each shape is read after the skin settled on it.
    expect(f.log.indexOf('settle', f.log.indexOf('set AU12'))).toBeLessThan(f.log.indexOf('set neutral', f.log.indexOf('set AU12')));
    expect(f.state()).toEqual({
      current: { actionUnits: { AU4: 0.3 }, presets: { happiness: 0.5, sadness: 0 } },
      overlay: { AU43L: 0.2 },
      eyesOn: true,
      playing: true,
      busy: false,
    });
    expect(f.log).toContain('preview back');
  });

  it('refuses an unknown target before it moves the face, and one export while another runs', async () => {
    const f = fakeFace();
    await expect(bakeGLTF(f.ports, checkExportOptions({ actionUnits: ['AU99'] }))).rejects.toThrow('AU99');
    expect(f.log).toEqual([]);
    f.ports.begin();
    await expect(bakeGLTF(f.ports, checkExportOptions({ actionUnits: ['AU12'] }))).rejects.toThrow('another export is under way');
    expect(f.log).toEqual([]);
  });

  it('stops when aborted, and still gives the face back its expression, overlay, eyes and timeline', async () => {
    const f = fakeFace();
    const abort = new AbortController();
    f.ports.simulation.settle = async () => {
      f.log.push('settle');
      abort.abort();
    };
    await expect(bakeGLTF(f.ports, checkExportOptions({ actionUnits: ['AU12'], signal: abort.signal }))).rejects.toThrow();
    expect(f.written()).toEqual([]);
    expect(f.state()).toMatchObject({ overlay: { AU43L: 0.2 }, eyesOn: true, playing: true, busy: false });
    expect(f.state().current.actionUnits).toEqual({ AU4: 0.3 });
  });
});
