import type { HeadView, ViewCapture } from '../render/head-view';
import type { SkinView } from '../render/skin-view';
import type { SkinSimulation } from '../sim/main/skin-simulation';
import type { FaceEyes } from './face-ports';
import type { FaceHandle } from './face-handle';
import { HeldPicture } from './held-picture';
import { videoFrameCount, type VideoOptions } from './video-options';

/** What a recorder works with: the face's handle, its skin solver and view, and the skin mesh's updater. */
export interface VideoRecorderParts {
  handle: FaceHandle;
  simulation: SkinSimulation;
  view: HeadView;
  skin: SkinView;
  /** The eyes, turned to the expression's gaze before each picture. */
  eyes: FaceEyes;
}

/**
 * Solver frames the start may take to settle on the timeline's first values (the default rig's expressions sleep
 * within 282 frames; the safety net stops any drift by about 1,000).
 */
const START_FRAMES = 2000;
/** How long the skin may take to come back to rest before a recording, in ms. */
const REST_TIMEOUT_MS = 60_000;

/**
 * Records a face frame by frame on a video clock: for video frame i it sets the timeline's values at i / fps, has
 * the solver run exactly `solverFramesPerVideoFrame` frames (its clock is stepped meanwhile, so it never runs
 * ahead), shows that skin, renders at the video's size and encodes the picture with timestamp i / fps. Nothing
 * depends on how fast the machine is, so the same timeline gives the same pictures.
 */
export class VideoRecorder {
  private busy = false;

  constructor(private readonly parts: VideoRecorderParts) {}

  /** Whether a recording is running. */
  recording(): boolean {
    return this.busy;
  }

  /** Records `seconds` of the loaded timeline (or of the face as it is, without one) as options `o` ask. */
  async record(o: Required<VideoOptions>, seconds: number): Promise<Blob> {
    if (this.busy) throw new Error('recordVideo: a recording is already running');
    this.busy = true;
    const { handle, simulation, view } = this.parts;
    const before = handle.timelineState();
    const eyes = handle.getEyeSimulation();
    let capture: ViewCapture | undefined;
    // A picture the last one shows already (a held expression, a still lead-in) is not drawn again: the sink repeats it.
    const held = new HeldPicture();
    const stopWatching = handle.onChange((change) => {
      if (change !== 'expression' && change !== 'timeline') held.invalidate();
    });
    try {
      // The encoders load with the first recording (a page that never records does not fetch them); a browser that
      // cannot encode refuses before the face is touched.
      const { webmSink, pngZipSink } = await import('./video-sinks');
      const sink = o.format === 'webm' ? await webmSink(o) : pngZipSink();
      try {
        if (before.loaded) handle.pause();
        // Blinks and saccades are random and on the page's clock: they stay out of the video.
        if (eyes) handle.setEyeSimulation(false);
        capture = view.capture(o.width, o.height);
        await this.start(before.loaded);
        const frames = videoFrameCount(seconds, o.fps);
        for (let i = 0; i < frames; i++) {
          o.signal?.throwIfAborted();
          if (before.loaded) handle.seek(i / o.fps);
          const solved = await simulation.runFrames(o.solverFramesPerVideoFrame);
          if (held.same(solved, handle.getEffectiveActionUnits())) await sink.repeat(i, o.fps);
          else {
            this.parts.skin.update();
            // The render loop holds while recording: the eye positions a timeline sets turn the eyes here.
            this.parts.eyes.showGaze();
            capture.render();
            await sink.add(capture.canvas, i, o.fps);
          }
          o.onProgress?.((i + 1) / frames);
        }
        o.signal?.throwIfAborted();
        return await sink.finish();
      } catch (error) {
        sink.cancel();
        throw error;
      }
    } finally {
      stopWatching();
      this.busy = false;
      if (!handle.isDisposed()) {
        // A head loaded meanwhile took this simulation away with the old head; the new one runs free already.
        if (!simulation.isDisposed()) simulation.setClock('free');
        capture?.dispose();
        if (eyes) handle.setEyeSimulation(true);
        if (before.loaded) {
          handle.seek(before.time);
          if (before.playing) handle.play();
        }
      }
    }
  }

  /**
   * Brings the skin to the recording's first frame from the same state every time: the neutral face at rest
   * (where the solver leaves every vertex exactly at rest), then the timeline's values at 0 on the stepped clock
   * until the skin sleeps. A skin that merely settled from wherever it was would differ by up to the sleep tolerance.
   */
  private async start(timeline: boolean): Promise<void> {
    const { handle, simulation } = this.parts;
    const entries: Record<string, number> = handle.getActionUnits();
    for (const { name, weight } of handle.listPresets()) if (weight !== 0) entries[`preset:${name}`] = weight;
    const overlay = handle.getOverlay();
    handle.reset();
    handle.clearOverlay();
    await simulation.settle(REST_TIMEOUT_MS);
    simulation.setClock('stepped');
    handle.setExpression(entries);
    const ids = Object.keys(overlay);
    if (ids.length > 0) handle.setOverlay(ids, Object.values(overlay));
    if (timeline) handle.seek(0);
    await simulation.runFrames(START_FRAMES);
  }
}
