import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { FaceHandle } from '../face/face-handle';
import { VIDEO_DEFAULTS, type VideoFormat } from '../face/video-options';
import { downloadBlob, fileTimestamp } from './download';
import { note } from './note';
import { named } from './named';

/** The sizes offered, as `width x height`. */
const SIZES = ['320 x 240', '640 x 480', '1280 x 720', '1920 x 1080', '1080 x 1080'];
const RATES = [10, 15, 24, 25, 30, 60];
const FORMATS: Record<string, VideoFormat> = { 'WebM video': 'webm', 'PNG frames (zip)': 'png-zip' };
const EXTENSIONS: Record<VideoFormat, string> = { webm: 'webm', 'png-zip': 'zip' };

/**
 * The Video folder (inside Timeline): frame rate, size, length and format, a record button that renders the
 * timeline frame by frame (see `face.recordVideo`) and downloads the file, a progress bar and a cancel button.
 */
export class VideoPanel {
  readonly folder: GUI;
  private readonly state: {
    fps: number;
    size: string;
    seconds: number;
    format: VideoFormat;
    record: () => void;
    cancel: () => void;
  };
  private readonly recordButton: Controller;
  private readonly cancelButton: Controller;
  private readonly progress: HTMLProgressElement;
  private readonly message: HTMLDivElement;
  private abort: AbortController | undefined;
  private disposed = false;

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
  ) {
    this.state = {
      fps: VIDEO_DEFAULTS.fps,
      size: `${VIDEO_DEFAULTS.width} x ${VIDEO_DEFAULTS.height}`,
      seconds: 0,
      format: VIDEO_DEFAULTS.format,
      record: () => void this.record(),
      cancel: () => this.abort?.abort(new DOMException('the recording was cancelled', 'AbortError')),
    };
    const s = this.state;
    this.folder = parent.addFolder('Video');
    named(this.folder.add(s, 'fps', RATES), 'video-fps');
    named(this.folder.add(s, 'size', SIZES), 'video-size');
    named(this.folder.add(s, 'seconds', 0, 60, 0.1).name('seconds (0: timeline)'), 'video-seconds');
    named(this.folder.add(s, 'format', FORMATS), 'video-format');
    this.recordButton = named(this.folder.add(s, 'record'), 'video-record');
    this.progress = document.createElement('progress');
    this.progress.dataset.control = 'video-progress';
    this.progress.max = 1;
    this.progress.value = 0;
    Object.assign(this.progress.style, { display: 'block', width: 'calc(100% - 16px)', margin: '2px 8px 4px' });
    this.folder.$children.append(this.progress);
    this.cancelButton = named(this.folder.add(s, 'cancel'), 'video-cancel').disable();
    this.message = note('video-message', { whiteSpace: 'pre-wrap' });
    this.folder.$children.append(this.message);
  }

  /** Cancels a recording under way and removes the folder. */
  dispose(): void {
    this.disposed = true;
    this.abort?.abort(new DOMException('the panel was removed', 'AbortError'));
    this.folder.destroy();
  }

  /** Records with the folder's settings and downloads the file; a refusal or a cancel is shown in the folder. */
  private async record(): Promise<void> {
    if (this.abort) return;
    const s = this.state;
    const [width, height] = s.size.split(' x ').map(Number);
    const abort = new AbortController();
    this.abort = abort;
    this.recordButton.disable();
    this.cancelButton.enable();
    this.progress.value = 0;
    this.message.textContent = 'recording…';
    try {
      const blob = await this.face.recordVideo({
        fps: s.fps,
        width,
        height,
        seconds: s.seconds,
        format: s.format,
        signal: abort.signal,
        onProgress: (fraction) => (this.progress.value = fraction),
      });
      if (this.disposed) return;
      downloadBlob(blob, `softface-${fileTimestamp()}.${EXTENSIONS[s.format]}`);
      this.message.textContent = `recorded ${(blob.size / 1024).toFixed(0)} KB`;
    } catch (error) {
      if (this.disposed) return;
      this.message.textContent = abort.signal.aborted ? 'recording cancelled' : (error as Error).message;
    } finally {
      this.abort = undefined;
      if (!this.disposed) {
        this.recordButton.enable();
        this.cancelButton.disable();
      }
    }
  }
}
