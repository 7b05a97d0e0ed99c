import { readFileSync } from 'node:fs';
import { describe, expect, it, vi } from 'vitest';
import { RigDocument } from '../src/core/rig/rig-document';
import { parseRigText } from '../src/core/rig/rig-schema';
import { EditorController } from '../src/face/editor-controller';
import { ExpressionController } from '../src/face/expression-controller';
import { EyesController } from '../src/face/eyes-controller';
import { ExportController } from '../src/face/export-controller';
import { FaceExpression } from '../src/face/face-expression';
import { FaceParts } from '../src/face/face-parts';
import type { FaceChange, FaceEyes, FaceMuscles, FaceTimeline, FaceView, TimelineState } from '../src/face/face-ports';
import { HeadController } from '../src/face/head-controller';
import { RigController } from '../src/face/rig-controller';
import { SkinController } from '../src/face/skin-controller';
import { TimelineController } from '../src/face/timeline-controller';
import { ViewController } from '../src/face/view-controller';
import type { SkinSimulation } from '../src/sim/main/skin-simulation';
import type { Timeline } from '../src/core/timeline/timeline';
import type { SkinParameters } from '../src/core/solver/skin-parameters';

const RIG = parseRigText(readFileSync(new URL('../public/rigs/default.json', import.meta.url), 'utf8'), 'default.json');

/** Parts with a real expression of the default rig and a fake simulation that keeps its parameters. */
function readyParts() {
  const parts = new FaceParts();
  let skin = { stiffness: 1 } as unknown as SkinParameters;
  parts.simulation = {
    rest: new Float32Array(3),
    parameters: () => skin,
    setParameters: (p: SkinParameters) => {
      skin = p;
    },
  } as unknown as SkinSimulation;
  parts.expression = new FaceExpression(RIG, () => {});
  const changes: FaceChange[] = [];
  parts.listen((c) => changes.push(c));
  return { parts, changes, skin: () => skin };
}

/** A timeline player that keeps what it is given. */
function fakePlayer(): FaceTimeline & { calls: string[] } {
  let loaded: Timeline | null = null;
  const calls: string[] = [];
  return {
    calls,
    set: (t) => {
      loaded = t;
      calls.push(t ? 'set' : 'clear');
    },
    timeline: () => loaded,
    play: () => calls.push('play'),
    pause: () => calls.push('pause'),
    seek: (s) => calls.push(`seek ${s}`),
    state: (): TimelineState => ({ loaded: !!loaded, playing: false, time: 0, duration: 1, loop: false }),
  };
}

describe('TimelineController', () => {
  it('loads a checked timeline and tells listeners; a bad one throws naming its path and changes nothing', () => {
    const { parts, changes } = readyParts();
    const player = fakePlayer();
    parts.player = player;
    const timeline = new TimelineController(parts);
    const good = {
      format: 'softface-timeline',
      tracks: {
        AU12L: {
          keys: [
            { time: 0, value: 0 },
            { time: 1, value: 1 },
          ],
        },
      },
    };
    const bad = { format: 'softface-timeline', tracks: { AU12L: { keys: [{ time: -1, value: 0 }] } } };
    expect(() => timeline.setTimeline(bad, 'smile.json')).toThrow(/^smile\.json: tracks\.AU12L\.keys\[0\]\.time/);
    expect(player.calls).toEqual([]);
    expect(changes).toEqual([]);
    timeline.setTimeline(good);
    expect(player.calls).toEqual(['set']);
    expect(changes).toEqual(['timeline']);
    expect(timeline.getTimeline()).not.toBe(player.timeline());
  });

  it('refuses play and seek without a timeline and a seek to a non-finite time', () => {
    const { parts, changes } = readyParts();
    parts.player = fakePlayer();
    const timeline = new TimelineController(parts);
    expect(() => timeline.play()).toThrow('play: no timeline is loaded (setTimeline first)');
    expect(() => timeline.seek(1)).toThrow('seek: no timeline is loaded');
    timeline.setTimeline({ format: 'softface-timeline', tracks: { AU12L: { keys: [{ time: 0, value: 0 }] } } });
    expect(() => timeline.seek(Number.POSITIVE_INFINITY)).toThrow('seek: expected a finite number, got Infinity');
    expect(changes).toEqual(['timeline']);
  });
});

describe('ViewController', () => {
  it('tells listeners after a change the view took, not after one it refused', () => {
    const { parts, changes } = readyParts();
    const view = {
      setLight: (p: { keyAzimuth?: number }) => {
        if (p.keyAzimuth !== undefined && p.keyAzimuth > 360) throw new Error('setLight: keyAzimuth: out of range');
      },
      measureRender: vi.fn(),
    };
    parts.view = view as unknown as FaceView;
    const controller = new ViewController(parts);
    expect(() => controller.setLight({ keyAzimuth: 400 })).toThrow('keyAzimuth');
    expect(changes).toEqual([]);
    controller.setLight({ keyAzimuth: 40 });
    expect(changes).toEqual(['light']);
    expect(() => controller.measureRender(0)).toThrow('measureRender: frames: expected an integer from 1 to 10000, got 0');
    expect(view.measureRender).not.toHaveBeenCalled();
  });
});

describe('EyesController', () => {
  it('refuses a bad option before the simulation is touched', () => {
    const { parts, changes } = readyParts();
    const eyes = { setEnabled: vi.fn(), enabled: () => false, stats: vi.fn() };
    parts.eyes = eyes as unknown as FaceEyes;
    const controller = new EyesController(parts);
    expect(() => controller.setEyeSimulation(true, { blinkHold: -1 })).toThrow(/^setEyeSimulation: blinkHold: /);
    expect(() => controller.setEyeSimulation('yes' as unknown as boolean)).toThrow('setEyeSimulation: expected true or false, got "yes"');
    expect(eyes.setEnabled).not.toHaveBeenCalled();
    controller.setEyeSimulation(true, { seed: 7 });
    expect(eyes.setEnabled).toHaveBeenCalledWith(true, { seed: 7 });
    expect(changes).toEqual(['eyes']);
  });
});

describe('HeadController', () => {
  it('carries the expression, skin and eyes to a new head; a preset the new rig lacks leaves it neutral with a warning', () => {
    const { parts, skin } = readyParts();
    let eyesOn = true;
    parts.eyes = { enabled: () => eyesOn, setEnabled: (on: boolean) => (eyesOn = on), stats: vi.fn() } as unknown as FaceEyes;
    const expression = new ExpressionController(parts);
    const head = new HeadController(parts, Promise.resolve(), expression);
    expression.setActionUnit('AU4', 0.6);
    const carried = head.carried();
    expect(carried.expression.actionUnits.AU4L).toBe(0.6);
    expect(carried.eyes).toBe(true);

    // The next head's rig has no presets: its expression cannot take `happiness`.
    parts.expression = new FaceExpression({ ...RIG, presets: [] }, () => {});
    eyesOn = false;
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    head.restore({ ...carried, expression: { actionUnits: {}, presets: { happiness: 1 } } });
    expect(warn).toHaveBeenCalledWith(expect.stringContaining('the expression was not carried over to the new head'));
    warn.mockRestore();
    expect(expression.getActionUnits().AU4L).toBe(0);
    expect(skin()).toBe(carried.skin);
    expect(eyesOn).toBe(true);
  });
});

describe('EditorController', () => {
  it('shows the muscles of the Action Units asked for, and all of them while the editor is on', () => {
    const { parts, changes } = readyParts();
    const seen: { visible: ReadonlySet<string> | 'all' | 'none' } = { visible: 'none' };
    parts.muscles = {
      setVisible: (v) => {
        seen.visible = v;
      },
      shown: () => [],
    } satisfies FaceMuscles;
    const editor = new EditorController(parts);
    editor.attachRig(new RigDocument(RIG), RIG, 'default');
    editor.setMuscleDisplay({ actionUnits: ['AU12'] });
    expect(seen.visible).toBeInstanceOf(Set);
    const names = [...(seen.visible as Set<string>)];
    expect(names.length).toBeGreaterThanOrEqual(2);
    expect(names.every((n) => RIG.muscles.some((m) => m.name === n))).toBe(true);
    expect(() => editor.setMuscleDisplay({ actionUnits: ['AU99'] })).toThrow(/AU99/);
    expect(editor.getMuscleDisplay()).toEqual({ all: false, actionUnits: ['AU12'] });
    editor.setEditor(true);
    expect(seen.visible).toBe('all');
    editor.setEditor(false);
    expect(seen.visible).toBeInstanceOf(Set);
    expect(changes).toEqual(['muscles', 'editor', 'editor']);
  });
});

describe('SkinController', () => {
  it('hands out copies of the skin, and tells listeners of new parameters only once the simulation took them', async () => {
    const parts = new FaceParts();
    const rest = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    let parameters = { stiffness: 1 } as unknown as SkinParameters;
    parts.simulation = {
      rest,
      triangles: new Uint32Array([0, 1, 2]),
      readSimulation: (p: Float32Array, n: Float32Array) => {
        p.set(rest);
        n.fill(0.5);
      },
      setParameters: (p: Partial<SkinParameters>) => {
        if ('bad' in p) throw new Error('skin parameters: expected one of the options ..., got "bad"');
        parameters = { ...parameters, ...p };
      },
      parameters: () => parameters,
      settle: async () => {},
    } as unknown as SkinSimulation;
    const changes: FaceChange[] = [];
    parts.listen((c) => changes.push(c));
    const skin = new SkinController(parts, Promise.resolve());
    const a = skin.getSkin();
    a.rest[0] = 9;
    a.positions[0] = 9;
    expect(skin.getSkin().rest[0]).toBe(0);
    expect(skin.getSkin().normals[2]).toBe(0.5);
    expect(() => skin.setSkinParameters({ bad: 1 } as never)).toThrow('skin parameters');
    expect(changes).toEqual([]);
    skin.setSkinParameters({ lengthIterations: 4 });
    expect(changes).toEqual(['skin']);
    await expect(skin.settle()).resolves.toBeUndefined();
  });
});

describe('RigController', () => {
  it('checks its source name, edits through the document, and tells listeners when an undo step closes', () => {
    const { parts, changes } = readyParts();
    const editor = new EditorController(parts);
    editor.attachRig(new RigDocument(RIG), RIG, 'default');
    const rig = new RigController(parts, editor.session);
    expect(() => rig.setRig(RIG, 3 as unknown as string)).toThrow('setRig: source: expected a string, got 3');
    const name = RIG.muscles[0].name;
    rig.beginEdit();
    rig.updateMuscle(name, { strength: 0.25 } as never);
    rig.endEdit();
    expect((rig.getRig().muscles[0] as { strength: number }).strength).toBe(0.25);
    expect(changes.filter((c) => c === 'editor')).toEqual(['editor']);
    expect(rig.undo()).toBe(true);
    expect((rig.getRig().muscles[0] as { strength: number }).strength).toBe((RIG.muscles[0] as { strength: number }).strength);
    expect(rig.getRig()).not.toBe(rig.getRig());
  });
});

describe('ExportController', () => {
  it('refuses a recording with nothing to record, or while one runs, before the recorder is asked', async () => {
    const { parts } = readyParts();
    parts.player = fakePlayer();
    let recordings = 0;
    let busy = false;
    parts.recorder = {
      record: async () => {
        recordings++;
        return new Blob();
      },
      recording: () => busy,
    };
    const timeline = new TimelineController(parts);
    const exporter = new ExportController(parts, Promise.resolve(), timeline, () => {});
    await expect(exporter.recordVideo({})).rejects.toThrow(/^recordVideo: seconds: give a length in seconds, or a timeline/);
    await expect(exporter.recordVideo({ fps: 0 })).rejects.toThrow('recordVideo: fps: expected a number from 1 to 120, got 0');
    busy = true;
    await expect(exporter.recordVideo({ seconds: 1 })).rejects.toThrow('recordVideo: a recording is already running');
    busy = false;
    await exporter.recordVideo({ seconds: 1 });
    expect(recordings).toBe(1);
    expect(exporter.isRecording()).toBe(false);
  });
});
