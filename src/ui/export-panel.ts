import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { FaceHandle } from '../face/face-handle';
import { downloadBlob } from './download';
import { note } from './note';
import { named } from './named';

/** The file the export downloads as. */
const GLTF_FILE_NAME = 'softface.glb';

/**
 * The Export folder: which Action Units and presets become morph targets (comma-separated lists), whether the loaded
 * timeline goes along as an animation and at what frame rate, and a button that solves them and downloads
 * `softface.glb` (pressed again while it runs, it cancels). Progress and refusals show under it.
 */
export class ExportPanel {
  readonly folder: GUI;
  private readonly state = { actionUnits: 'AU12, AU26', presets: '', timeline: true, fps: 30, run: () => this.run() };
  private readonly button: Controller;
  private readonly message: HTMLDivElement;
  /** The export under way, to cancel it. */
  private running: AbortController | null = null;
  private disposed = false;

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
  ) {
    this.folder = parent.addFolder('Export');
    const s = this.state;
    named(this.folder.add(s, 'actionUnits').name('action units'), 'gltf-action-units').domElement.title =
      'Action Unit ids, comma-separated (AU12, AU12L, AU17)';
    named(this.folder.add(s, 'presets').name('presets'), 'gltf-presets').domElement.title = `preset names, comma-separated (${face
      .listPresets()
      .map((p) => p.name)
      .join(', ')})`;
    named(this.folder.add(s, 'timeline').name('timeline animation'), 'gltf-timeline');
    named(this.folder.add(s, 'fps', 1, 60, 1).name('animation fps'), 'gltf-fps');
    this.button = named(this.folder.add(s, 'run').name(`export ${GLTF_FILE_NAME}`), 'gltf-export');
    this.message = note('gltf-message', { whiteSpace: 'pre-wrap' });
    this.folder.$children.append(this.message);
  }

  /** Cancels an export under way and removes the folder. */
  dispose(): void {
    this.disposed = true;
    this.running?.abort();
    this.folder.destroy();
  }

  /** Starts an export with the folder's choices, or cancels the one under way. */
  private async run(): Promise<void> {
    if (this.running) {
      this.running.abort();
      return;
    }
    const s = this.state;
    const controller = new AbortController();
    this.running = controller;
    this.button.name('cancel export');
    this.show('');
    try {
      const blob = await this.face.exportGLTF({
        actionUnits: list(s.actionUnits),
        presets: list(s.presets),
        // Only a loaded timeline can go along; unticked or without one, the file has no animation.
        timeline: s.timeline && this.face.timelineState().loaded,
        fps: s.fps,
        signal: controller.signal,
        onProgress: (p) => this.show(p.target === null ? 'writing the file' : `solving ${p.target} (${p.done + 1} of ${p.total})`),
      });
      if (this.disposed) return;
      downloadBlob(blob, GLTF_FILE_NAME);
      this.show(`exported ${GLTF_FILE_NAME} (${Math.round(blob.size / 1024)} KB)`);
    } catch (error) {
      if (this.disposed) return;
      this.show(controller.signal.aborted ? 'export cancelled' : (error as Error).message, true);
    } finally {
      this.running = null;
      if (!this.disposed) this.button.name(`export ${GLTF_FILE_NAME}`);
    }
  }

  private show(text: string, failed = false): void {
    this.message.textContent = text;
    this.message.style.color = failed ? '#ff8a80' : '';
  }
}

/** The entries of a comma-separated list, trimmed, without empty ones. */
function list(text: string): string[] {
  return text
    .split(',')
    .map((x) => x.trim())
    .filter((x) => x !== '');
}
