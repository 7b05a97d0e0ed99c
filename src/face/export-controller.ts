import { checkExportOptions, type GLTFExportOptions } from './gltf-export-options';
import { bakeGLTF } from './gltf-bake';
import type { FaceParts } from './face-parts';
import type { TimelineController } from './timeline-controller';
import { checkVideoOptions, type VideoOptions } from './video-options';

/** What the face writes out over time: videos of its timeline and glTF files of its expressions. */
export class ExportController {
  /** Whether `exportGLTF` is solving its targets (one export at a time: each moves the face). */
  private exporting = false;

  /**
   * `timeline` loads the timeline a recording asks for; `restorePreview` puts the editor's preview contraction back
   * after an export has moved the muscles.
   */
  constructor(
    private readonly parts: FaceParts,
    private readonly ready: Promise<void>,
    private readonly timeline: TimelineController,
    private readonly restorePreview: () => void,
  ) {}

  /**
   * Records the timeline frame by frame (see docs/video.md): a WebM video (VP9, else VP8) or a zip of PNG
   * frames of `width` x `height`, `fps` frames a second, for `seconds` or the timeline's duration. `timeline` loads
   * one first, as `setTimeline` does. The solver runs a fixed number of frames per video frame, so a slow machine
   * records the same video as a fast one; the eye simulation is off meanwhile. Bad options reject naming the option
   * and change nothing; aborting `signal` stops the recording, which then rejects with the signal's reason.
   */
  async recordVideo(options: VideoOptions = {}): Promise<Blob> {
    const o = checkVideoOptions(options);
    const player = this.parts.timeline();
    const recorder = this.parts.recorder;
    if (!recorder) throw new Error('recordVideo: the face is not ready yet: await face.ready first');
    if (recorder.recording()) throw new Error('recordVideo: a recording is already running');
    if (o.timeline === null && o.seconds === 0 && !player.timeline()) {
      throw new Error(
        'recordVideo: seconds: give a length in seconds, or a timeline to record (the timeline option, or setTimeline first)',
      );
    }
    o.signal?.throwIfAborted();
    if (o.timeline !== null) this.timeline.setTimeline(o.timeline, 'recordVideo: timeline');
    return recorder.record(o, o.seconds > 0 ? o.seconds : player.state().duration);
  }

  /** Whether a recording is running. */
  isRecording(): boolean {
    return this.parts.recorder?.recording() ?? false;
  }

  /**
   * Exports the head (skin, eyes, teeth) as glTF (see docs/gltf-export.md): each Action Unit and preset
   * asked for becomes a morph target named after it, holding the skin it gives on its own at 1 once settled, and the
   * timeline (the loaded one, unless `timeline` is false) becomes an animation of the morph weights. Every target is
   * solved from the neutral face in turn, so this takes a while (`onProgress`, `signal`); the face shows it, and gets
   * its expression back afterwards. Bad options reject naming the option, changing nothing.
   */
  async exportGLTF(options?: GLTFExportOptions): Promise<Blob> {
    const o = checkExportOptions(options);
    const parts = this.parts;
    parts.alive();
    await this.ready;
    const writer = parts.gltfWriter;
    if (!writer) throw new Error('exportGLTF: the face has no head to export yet');
    const expression = parts.expressed();
    return bakeGLTF(
      {
        expression,
        simulation: parts.running(),
        player: parts.timeline(),
        writer,
        eyes: parts.eyes,
        presets: expression.listPresets().map((p) => p.name),
        expressionChanged: () => parts.emit('expression'),
        restorePreview: this.restorePreview,
        alive: () => !parts.disposed,
        begin: () => {
          if (this.exporting) throw new Error('exportGLTF: another export is under way');
          this.exporting = true;
        },
        end: () => {
          this.exporting = false;
        },
      },
      o,
    );
  }
}

/** The handle's methods that ExportController answers. */
export const EXPORT_METHODS = ['recordVideo', 'isRecording', 'exportGLTF'] as const;
