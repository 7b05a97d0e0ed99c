import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { FaceHandle } from '../face/face-handle';
import { named } from './named';
import { note } from './note';

/** How often the status line is rewritten while the tracker runs, milliseconds. */
const STATUS_MS = 500;

/**
 * The Tracking folder: starts and stops the webcam tracker (`face.startTracking()`), shows what it does (frames a
 * second, latency, calibration, a face in view, or why it stopped) and a mirrored preview of the camera.
 */
export class TrackingPanel {
  readonly folder: GUI;
  private readonly button: Controller;
  private readonly status: HTMLDivElement;
  private readonly preview: HTMLDivElement;
  private timer: ReturnType<typeof setInterval> | undefined;
  private readonly actions = {
    toggle: () => void this.toggle(),
    calibrate: () => {
      if (this.face.trackingState().on) this.face.calibrateTracking();
      this.show();
    },
  };

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
  ) {
    this.folder = parent.addFolder('Tracking');
    this.button = named(this.folder.add(this.actions, 'toggle').name('start camera tracking'), 'tracking-toggle');
    named(this.folder.add(this.actions, 'calibrate').name('take my neutral face again'), 'tracking-calibrate');
    this.status = note('tracking-status', { color: '#c8c8c8' });
    this.status.textContent = 'off: the face follows yours after a neutral second';
    this.preview = document.createElement('div');
    this.preview.dataset.control = 'tracking-preview';
    this.button.domElement.after(this.status, this.preview);
  }

  /** Stops its timer and the tracker (unless the face went first, which stops it), and removes the folder. */
  dispose(): void {
    this.stopTimer();
    if (!this.face.isDisposed() && this.face.trackingState().on) this.face.stopTracking();
    this.folder.destroy();
  }

  private async toggle(): Promise<void> {
    if (this.face.trackingState().on) {
      this.face.stopTracking();
      this.stopTimer();
      this.show();
      return;
    }
    this.button.disable();
    this.status.textContent = 'starting: allow the camera';
    try {
      await this.face.startTracking();
      this.timer = setInterval(() => this.show(), STATUS_MS);
    } catch (error) {
      this.status.textContent = (error as Error).message;
    } finally {
      this.button.enable();
    }
    this.show();
  }

  /** The button's label, the status line and the preview, as the tracker is now. */
  private show(): void {
    const s = this.face.trackingState();
    this.button.name(s.on ? 'stop camera tracking' : 'start camera tracking');
    const video = this.face.trackingPreview();
    if (video && video.parentElement !== this.preview) {
      Object.assign(video.style, { width: '100%', transform: 'scaleX(-1)', display: 'block' });
      this.preview.replaceChildren(video);
    } else if (!video) this.preview.replaceChildren();
    if (!s.on) {
      this.stopTimer();
      if (!this.status.textContent?.startsWith('startTracking')) this.status.textContent = 'off';
      return;
    }
    const state = s.message || (s.calibrated ? 'tracking' : 'calibrating');
    this.status.textContent = `${state} · ${s.fps} frames/s · ${Math.round(s.latencyMs)} ms from camera to face`;
  }

  private stopTimer(): void {
    clearInterval(this.timer);
    this.timer = undefined;
  }
}
