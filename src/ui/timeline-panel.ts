import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import { emptyTimeline, PRESET_TARGET_PREFIX, type Timeline } from '../core/timeline/timeline';
import type { FaceChange, FaceHandle } from '../face/face-handle';
import { downloadBlob } from './download';
import { FileImport } from './file-import';
import { note } from './note';

/** Where the panel's edits and imports say they came from in a refusal's message. */
const PANEL_SOURCE = 'Timeline panel';

/**
 * The Timeline folder: play / pause, a time slider that seeks, the loop flag, adding an onset / apex / offset action
 * for an Action Unit or preset at the current time, clearing, export and import of timeline files, and a list of the
 * timeline's keys and actions. A refused import or edit shows its path-named message here and changes nothing.
 */
export class TimelinePanel {
  readonly folder: GUI;
  private readonly state: {
    play: () => void;
    time: number;
    loop: boolean;
    target: string;
    intensity: number;
    onset: number;
    apex: number;
    offset: number;
    add: () => void;
    clear: () => void;
    exportTimeline: () => void;
    importTimeline: () => void;
  };
  private readonly controllers: Controller[] = [];
  private readonly playButton: Controller;
  private playLabel = 'play';
  private readonly timeSlider: Controller;
  private readonly list: HTMLDivElement;
  /** Timeline files picked, and the message line. */
  private readonly files: FileImport;
  private readonly unsubscribe: () => void;

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
  ) {
    this.state = {
      play: () => this.files.attempt(() => (face.timelineState().playing ? face.pause() : face.play())),
      time: 0,
      loop: false,
      target: 'AU12',
      intensity: 0.8,
      onset: 0.5,
      apex: 1,
      offset: 0.8,
      add: () => this.addAction(),
      clear: () => this.files.attempt(() => face.clearTimeline()),
      exportTimeline: () => this.exportTimeline(),
      importTimeline: () => this.files.pick(),
    };
    const s = this.state;
    this.folder = parent.addFolder('Timeline');
    this.playButton = this.add(this.folder.add(s, 'play'), 'timeline-play');
    this.timeSlider = this.add(
      this.folder
        .add(s, 'time', 0, 1, 0.01)
        .name('time (s)')
        .onChange((t: number) => this.files.attempt(() => face.timelineState().loaded && face.seek(t))),
      'timeline-time',
    );
    this.add(
      this.folder.add(s, 'loop').onChange((on: boolean) => this.edit((t) => (t.loop = on))),
      'timeline-loop',
    );
    this.list = note('timeline-keys', { opacity: '0.85', whiteSpace: 'pre-wrap', fontFamily: 'monospace' });
    this.folder.$children.append(this.list);
    const targets = [
      ...face.listActionUnits().flatMap((au) => (au.sides.length === 2 ? [au.id, `${au.id}L`, `${au.id}R`] : [au.id])),
      ...face.listPresets().map((p) => `${PRESET_TARGET_PREFIX}${p.name}`),
    ];
    this.add(this.folder.add(s, 'target', targets).name('action on'), 'timeline-target');
    this.add(this.folder.add(s, 'intensity', 0, 1, 0.01), 'timeline-intensity');
    this.add(this.folder.add(s, 'onset', 0.05, 5, 0.05).name('onset (s)'), 'timeline-onset');
    this.add(this.folder.add(s, 'apex', 0, 10, 0.05).name('apex (s)'), 'timeline-apex');
    this.add(this.folder.add(s, 'offset', 0.05, 5, 0.05).name('offset (s)'), 'timeline-offset');
    this.add(this.folder.add(s, 'add').name('add onset/apex/offset action at the time'), 'timeline-add-action');
    this.add(this.folder.add(s, 'clear').name('clear timeline'), 'timeline-clear');
    this.add(this.folder.add(s, 'exportTimeline').name('export timeline'), 'timeline-export');
    this.add(this.folder.add(s, 'importTimeline').name('import timeline or OpenFace CSV'), 'timeline-import');
    this.files = new FileImport(this.folder, 'timeline-file', 'timeline-message', { color: '#ff8a80' })
      .accept('.json,.csv,application/json,text/csv')
      .onText(
        // A .csv is an OpenFace file (its Action Unit columns become tracks); anything else a timeline document.
        (text, file) => (/\.csv$/i.test(file.name) ? face.importOpenFace(text, file.name) : face.setTimeline(text, file.name)),
        (file) => `imported ${file.name}`,
      );
    this.refresh(true);
    this.unsubscribe = face.onChange((change) => this.changed(change));
  }

  /** Removes the folder and stops following the face. */
  dispose(): void {
    this.files.dispose();
    this.unsubscribe();
    this.folder.destroy();
  }

  private changed(change: FaceChange): void {
    if (change === 'timeline') this.refresh(false);
    else if (change === 'rig') this.refresh(true);
  }

  /**
   * Shows the clock and the play button's state, and unless the timeline plays (or with `all`) the loop flag, the
   * slider's range and the list: while it plays only the clock moves, and a new timeline comes paused.
   */
  private refresh(all: boolean): void {
    const state = this.face.timelineState();
    this.state.time = state.time;
    this.timeSlider.updateDisplay();
    const label = state.playing ? 'pause' : 'play';
    if (label !== this.playLabel) {
      this.playLabel = label;
      this.playButton.name(label);
    }
    if (state.playing && !all) return;
    this.state.loop = state.loop;
    this.timeSlider.max(Math.max(state.duration, 0.01));
    for (const c of this.controllers) c.updateDisplay();
    this.list.textContent = describeTimeline(this.face.getTimeline(), state.duration);
  }

  /** Adds the chosen onset / apex / offset action, starting at the timeline's current time. */
  private addAction(): void {
    const s = this.state;
    const start = Math.round(this.face.timelineState().time * 100) / 100;
    this.edit((t) => t.actions.push({ target: s.target, start, intensity: s.intensity, onset: s.onset, apex: s.apex, offset: s.offset }));
  }

  /** Changes a copy of the timeline (an empty one if none is loaded) and loads it, keeping its clock and playing. */
  private edit(change: (t: Timeline) => void): void {
    this.files.attempt(() => {
      const before = this.face.timelineState();
      const t = this.face.getTimeline() ?? emptyTimeline();
      change(t);
      this.face.setTimeline(t, PANEL_SOURCE);
      if (before.loaded) this.face.seek(before.time);
      if (before.playing) this.face.play();
    });
  }

  /** Downloads the timeline as `timeline.json`. */
  private exportTimeline(): void {
    const t = this.face.getTimeline();
    if (!t) {
      this.files.message.textContent = 'no timeline to export: add an action or import one';
      return;
    }
    downloadBlob(new Blob([JSON.stringify(t, null, 2)], { type: 'application/json' }), 'timeline.json');
  }

  private add(controller: Controller, name: string): Controller {
    controller.domElement.dataset.control = name;
    this.controllers.push(controller);
    return controller;
  }
}

/** The timeline as lines of text: its length and loop, each track's keys, each action's phases. */
function describeTimeline(t: Timeline | null, duration: number): string {
  if (!t) return 'no timeline';
  const lines = [`${seconds(duration)}${t.loop ? ', looping' : ''}`];
  for (const [target, track] of Object.entries(t.tracks)) {
    const key = (k: (typeof track.keys)[number]): string =>
      `${seconds(k.time)} ${round(k.value)}${k.easing && k.easing !== 'linear' ? ` ${k.easing}` : ''}`;
    lines.push(`${target}: ${track.keys.map(key).join(' → ')}`);
  }
  for (const a of t.actions) {
    lines.push(
      `${a.target} ${round(a.intensity)} at ${seconds(a.start)}: onset ` +
        `${seconds(a.onset)}, apex ${seconds(a.apex)}, offset ${seconds(a.offset)}`,
    );
  }
  if (lines.length === 1) lines.push('no keys or actions yet');
  return lines.join('\n');
}

function seconds(x: number): string {
  return `${round(x)} s`;
}

function round(x: number): number {
  return Math.round(x * 1000) / 1000;
}
