import { ARKIT_BLENDSHAPES, BLENDSHAPE_UNIT_IDS, blendshapeUnits, readBlendshapes, type ARKitBlendshape } from '../core/expression/arkit';
import { refusal } from '../core/check';
import { openFaceTimeline } from '../core/timeline/openface';
import type { Timeline } from '../core/timeline/timeline';
import type { FaceParts } from './face-parts';
import { assetUrl } from './face-assets';
import type { PackageFile } from './package-assets';
import type { FaceTracker, TrackingOptions, TrackingState } from './face-tracker';
import type { TimelineController } from './timeline-controller';

/**
 * A tracker's state before it starts: kept here, in the library's entry, and handed to the tracker (which is loaded
 * only when tracking starts).
 */
const IDLE_TRACKING: Readonly<TrackingState> = Object.freeze({
  on: false,
  fps: 0,
  frames: 0,
  latencyMs: 0,
  processMs: 0,
  capturedAt: 0,
  calibrated: false,
  face: false,
  message: '',
});

/** Driving the face from trackers: ARKit blendshape streams and OpenFace files. */
export class LiveController {
  /** The 52 blendshape values last given, in Apple's order. */
  private readonly values = new Float64Array(ARKIT_BLENDSHAPES.length);
  /** The Action Unit sides they drive (BLENDSHAPE_UNIT_IDS' order), rewritten for every call. */
  private readonly units = new Float64Array(BLENDSHAPE_UNIT_IDS.length);
  /** The webcam tracker while it runs or starts. */
  private tracker: FaceTracker | null = null;
  /** Takes the tracker's hook out of the view's frames. */
  private unhook: (() => void) | null = null;

  constructor(
    private readonly parts: FaceParts,
    private readonly timeline: TimelineController,
  ) {}

  /**
   * Sets ARKit blendshape values (`{ mouthSmileLeft: 0.8, jawOpen: 0.3 }`; any of the 52 names, `Left` the subject's
   * left), each clamped to 0..1; names not given keep their last values. They drive the Action Units of the README's
   * blendshape table through the overlay (see `setOverlay`): they add to the sliders and presets without moving them,
   * and tell no listener, so a tracker may call this every frame. A name that is not one of the 52, or a value that
   * is not a finite number, throws naming it and changes nothing. Allocates nothing but what the caller passes.
   */
  setBlendshapes(values: Partial<Record<ARKitBlendshape, number>>): void {
    const expression = this.parts.expressed();
    readBlendshapes(values, this.values, 'setBlendshapes');
    expression.setOverlay(BLENDSHAPE_UNIT_IDS, blendshapeUnits(this.values, this.units));
  }

  /** The 52 blendshape values last set (0 for those never given), by name. */
  getBlendshapes(): Record<ARKitBlendshape, number> {
    this.parts.alive();
    return Object.fromEntries(ARKIT_BLENDSHAPES.map((name, i) => [name, this.values[i]])) as Record<ARKitBlendshape, number>;
  }

  /** Sets every blendshape back to 0, taking their Action Units out of the overlay. */
  clearBlendshapes(): void {
    const expression = this.parts.expressed();
    this.values.fill(0);
    expression.setOverlay(BLENDSHAPE_UNIT_IDS, blendshapeUnits(this.values, this.units));
  }

  /**
   * Tracks the viewer's face with MediaPipe Face Mesh and drives the face with it: brows, lids, lip corners, lips and
   * jaw (AU1, 2, 4, 5, 12, 15, 25, 26, 43 by side) relative to the viewer's neutral face, which the first second of
   * frames with a face calibrates (`options.calibrationMs`), smoothed (`smoothingMs`), through the overlay.
   * `options.source` is a camera stream or a playing video; by default the page asks for the camera. The face
   * mesh's files come from the package (its `mediapipe/face_mesh/` folder, under `assetBase` when given). Rejects,
   * naming what failed (the camera refused, the files missing), and the face keeps its expression; a frame with no
   * face keeps it too (`trackingState().message` says so).
   */
  async startTracking(options: TrackingOptions = {}): Promise<void> {
    this.parts.expressed();
    if (typeof options !== 'object' || options === null) throw refusal('startTracking', '', 'an object of options', options);
    const { source } = options;
    if (source !== undefined && !(source instanceof MediaStream) && !(source instanceof HTMLVideoElement)) {
      throw refusal('startTracking', 'source', 'a MediaStream or an HTMLVideoElement', source);
    }
    this.stopTracking();
    // Loaded on first use: the library's entry stays without it.
    const { FaceTracker } = await import('./face-tracker');
    const tracker = new FaceTracker(
      (ids, values) => this.parts.expression?.setOverlay(ids, values),
      (name) => assetUrl(`mediapipe/face_mesh/${name}` as PackageFile, this.parts.assetBase),
      () => !this.parts.disposed,
      IDLE_TRACKING,
      options,
    );
    this.tracker = tracker;
    try {
      await tracker.start(source);
    } catch (error) {
      if (this.tracker === tracker) this.tracker = null;
      throw error;
    }
    // The camera's frames go first: the face is drawn once the face mesh has answered (see holdsDrawing).
    if (this.tracker === tracker) {
      const view = this.parts.shown();
      const unhookFrame = view.onFrame((now) => (tracker.holdsDrawing(now) ? 'hold' : undefined));
      const unhookRender = view.onRender(() => tracker.drawn(performance.now()));
      this.unhook = () => {
        unhookFrame();
        unhookRender();
      };
    }
  }

  /**
   * Takes the viewer's neutral face again (keep still and neutral for the calibration time): the tracker's units hold
   * meanwhile. Throws unless the tracker runs.
   */
  calibrateTracking(): void {
    if (!this.tracker) throw new Error('calibrateTracking: the tracker is not running (startTracking first)');
    this.tracker.recalibrate();
  }

  /** Stops the webcam tracker (a camera it opened is let go) and takes its Action Units out of the overlay. */
  stopTracking(): void {
    this.unhook?.();
    this.unhook = null;
    this.tracker?.stop();
    this.tracker = null;
  }

  /** What the webcam tracker is doing: `{ on, fps, frames, latencyMs, processMs, capturedAt, calibrated, face, message }`. */
  trackingState(): TrackingState {
    this.parts.alive();
    return this.tracker?.state() ?? { ...IDLE_TRACKING };
  }

  /** The video the webcam tracker reads, for a preview (null while it does not run). */
  trackingPreview(): HTMLVideoElement | null {
    return this.tracker?.preview ?? null;
  }

  /**
   * Loads an OpenFace 2 CSV (FeatureExtraction's per-frame output) as the timeline, paused at its start, and returns
   * it: a keyframe track per Action Unit the file has and the face too (`AU12_r` over 5, 0 where `AU12_c` says
   * absent), timed by the `timestamp` column from the first tracked frame. A malformed file throws naming the line
   * and column (`importOpenFace: line 7, column 12: AU04_r: expected a number, got "x"`; `source`, such as the file's
   * name, replaces `importOpenFace` there) and changes nothing.
   */
  importOpenFace(csv: string, source = 'importOpenFace'): Timeline {
    if (typeof source !== 'string') throw refusal('importOpenFace', 'source', 'a string', source);
    const timeline = openFaceTimeline(csv, source);
    this.timeline.setTimeline(timeline, source);
    return structuredClone(timeline);
  }
}

/** The handle's methods that LiveController answers. */
export const LIVE_METHODS = [
  'setBlendshapes',
  'getBlendshapes',
  'clearBlendshapes',
  'importOpenFace',
  'startTracking',
  'stopTracking',
  'calibrateTracking',
  'trackingState',
  'trackingPreview',
] as const;
