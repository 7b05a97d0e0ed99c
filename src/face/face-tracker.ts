import { LandmarkUnits, TRACKED_UNIT_IDS, type Landmark } from '../core/expression/landmark-units';

/** Where the tracker's pictures come from, and how it reads them. */
export interface TrackingOptions {
  /** A camera stream or a playing video; by default the page asks for the camera. */
  source?: MediaStream | HTMLVideoElement;
  /** Milliseconds of the first frames with a face averaged as the viewer's neutral face; default 1000. */
  calibrationMs?: number;
  /** Time constant of the smoothing, milliseconds; default 50. */
  smoothingMs?: number;
}

/** What the tracker is doing (`face.trackingState()`). */
export interface TrackingState {
  /** Whether it runs. */
  on: boolean;
  /** Frames it read in the last second. */
  fps: number;
  /** Frames it read since it started (a reader of its Action Units can tell a new frame by this). */
  frames: number;
  /** From a frame's capture to its Action Units in the overlay, milliseconds (smoothed; 0 before the first). */
  latencyMs: number;
  /**
   * When the camera frame the Action Units come from was captured, on the page's clock (`performance.now()`; the
   * time it was shown where the browser does not say): for matching them with what the camera saw.
   */
  capturedAt: number;
  /** The face mesh's own time per frame, from handing it the frame to its landmarks, milliseconds (smoothed). */
  processMs: number;
  /** Whether the viewer's neutral face is known. */
  calibrated: boolean;
  /** Whether the last frame had a face in it. */
  face: boolean;
  /** What went wrong last, or what to do ("no face in view"); empty when all is well. */
  message: string;
}

/** The part of MediaPipe Face Mesh's script API (`window.FaceMesh`) the tracker uses. */
interface FaceMeshSolution {
  setOptions(options: Record<string, unknown>): void;
  onResults(listener: (results: FaceMeshResults) => void): void;
  initialize(): Promise<void>;
  send(input: { image: HTMLVideoElement }): Promise<void>;
  close(): Promise<void>;
}
interface FaceMeshResults {
  image: { width: number; height: number };
  multiFaceLandmarks?: Landmark[][];
}
type FaceMeshConstructor = new (config: { locateFile: (file: string) => string }) => FaceMeshSolution;

/** Loads a classic script once per URL (MediaPipe's solutions define a global). */
const scripts = new Map<string, Promise<void>>();
function loadScript(url: string): Promise<void> {
  let loading = scripts.get(url);
  if (!loading) {
    loading = new Promise<void>((resolve, reject) => {
      const script = document.createElement('script');
      script.src = url;
      script.crossOrigin = 'anonymous';
      script.onload = () => resolve();
      script.onerror = () => reject(new Error(`the face tracker's script could not be loaded from ${url}`));
      document.head.append(script);
    });
    loading.catch(() => scripts.delete(url));
    scripts.set(url, loading);
  }
  return loading;
}

/**
 * Tracks the viewer's face with MediaPipe Face Mesh (its script, WebAssembly and model from the package's own files)
 * and turns each frame's landmarks into Action Units (landmark-units.ts), which it hands to `overlay` as the face's
 * overlay takes them. A frame is read as the video shows it (requestVideoFrameCallback), one at a time.
 */
export class FaceTracker {
  private readonly units: LandmarkUnits;
  private mesh: FaceMeshSolution | null = null;
  private video: HTMLVideoElement | null = null;
  /** A stream the tracker asked for itself, stopped with it. */
  private ownStream: MediaStream | null = null;
  private running = false;
  private frameAt = 0;
  /** When the frame being read was handed to the face mesh. */
  private sentAt = 0;
  /** Whether a camera frame is in the face mesh (from its send to its results). */
  private inFlight = false;
  /** Frames the face mesh answered since the face was drawn last, and when that was. */
  private answered = 0;
  private drawnAt = 0;
  private readonly times = new Float64Array(64);
  private timeCount = 0;
  private readonly status: TrackingState;
  private readonly zeros = new Float64Array(TRACKED_UNIT_IDS.length);

  constructor(
    private readonly overlay: (ids: readonly string[], values: ArrayLike<number>) => void,
    private readonly fileUrl: (name: string) => string,
    private readonly alive: () => boolean,
    idle: Readonly<TrackingState>,
    options: TrackingOptions = {},
  ) {
    this.status = { ...idle };
    this.units = new LandmarkUnits({ calibrationMs: options.calibrationMs, smoothingMs: options.smoothingMs });
  }

  /** The video the tracker reads (null until started): a panel may show it. */
  get preview(): HTMLVideoElement | null {
    return this.video;
  }

  /** Opens the source and the face mesh and starts reading frames; rejects, naming what failed, and changes nothing. */
  async start(source: TrackingOptions['source']): Promise<void> {
    let video: HTMLVideoElement;
    if (source instanceof HTMLVideoElement) video = source;
    else {
      let stream = source ?? null;
      if (!stream) {
        if (!navigator.mediaDevices?.getUserMedia) throw new Error('startTracking: this page has no camera access (it needs https)');
        try {
          stream = await navigator.mediaDevices.getUserMedia({ video: { width: 640, height: 480 }, audio: false });
        } catch (error) {
          const e = error as DOMException;
          throw new Error(`startTracking: the camera could not be opened (${e.name}: ${e.message})`);
        }
        this.ownStream = stream;
      }
      video = document.createElement('video');
      video.muted = true;
      video.playsInline = true;
      video.srcObject = stream;
      try {
        await video.play();
      } catch (error) {
        this.releaseStream();
        throw new Error(`startTracking: the camera's video did not play (${(error as Error).message})`);
      }
    }
    try {
      await loadScript(this.fileUrl('face_mesh.js'));
      const FaceMesh = (globalThis as unknown as { FaceMesh?: FaceMeshConstructor }).FaceMesh;
      if (!FaceMesh) throw new Error('startTracking: the face tracker did not load (no FaceMesh in its script)');
      const mesh = new FaceMesh({ locateFile: (file) => this.fileUrl(file) });
      // Inference on the CPU (WebAssembly SIMD), not in WebGL: the face's own drawing has the GPU, and where WebGL is
      // software (no GPU) the face mesh's GPU graph took 119 ms a frame against 15 ms on the CPU.
      // Its refined eyes and lips (the attention model): without them, closed eyes kept 70 % of their opening.
      mesh.setOptions({
        maxNumFaces: 1,
        refineLandmarks: true,
        useCpuInference: true,
        minDetectionConfidence: 0.5,
        minTrackingConfidence: 0.5,
      });
      mesh.onResults((results) => this.results(results));
      await mesh.initialize();
      this.mesh = mesh;
    } catch (error) {
      this.releaseStream();
      throw error;
    }
    this.video = video;
    this.running = true;
    this.status.on = true;
    this.status.message = 'calibrating: keep a neutral face';
    this.next();
  }

  /** Stops reading frames, lets go of a camera it opened, and takes its Action Units out of the overlay. */
  stop(): void {
    if (!this.running) return;
    this.running = false;
    this.inFlight = false;
    this.status.on = false;
    this.status.face = false;
    this.status.fps = 0;
    this.releaseStream();
    void this.mesh?.close();
    this.mesh = null;
    this.video = null;
    this.input.image = null;
    if (this.alive()) this.overlay(TRACKED_UNIT_IDS, this.zeros);
  }

  /** Forgets the viewer's neutral face: the next `calibrationMs` of frames with a face are taken as it again. */
  recalibrate(): void {
    this.units.reset();
    if (this.running) this.status.message = 'calibrating: keep a neutral face';
  }

  /**
   * Whether the face's drawing waits for the tracker at `now`: while a camera frame is in the face mesh, and until
   * the face mesh has answered a frame since the face was drawn last, so that the face is drawn about once a camera
   * frame. Where WebGL is software, a draw of the face takes both cores for tens of milliseconds and the face mesh,
   * whose input goes through WebGL too, waits behind it (its time per frame went from 22 ms to 120 ms with the face
   * drawn at will). Never longer than a quarter of a second: a camera or a face mesh that stalls does not stop the
   * face.
   */
  holdsDrawing(now: number): boolean {
    if (now - this.drawnAt >= 250) return false;
    return this.inFlight || this.answered === 0;
  }

  /** Notes that the face was drawn at `now` (see `holdsDrawing`). */
  drawn(now: number): void {
    this.drawnAt = now;
    this.answered = 0;
  }

  /** What the tracker is doing (a copy). */
  state(): TrackingState {
    const now = performance.now();
    let frames = 0;
    for (let i = 0; i < Math.min(this.timeCount, this.times.length); i++) if (now - this.times[i] <= 1000) frames++;
    return { ...this.status, fps: this.running ? frames : 0, calibrated: this.units.calibrated };
  }

  /** Waits for the video's next frame and reads it. */
  private next(): void {
    if (this.running && this.video) this.video.requestVideoFrameCallback(this.onFrame);
  }

  // The per-frame callbacks are made once (a camera frame is read 30 times a second); the input record is reused.
  private readonly input: { image: HTMLVideoElement | null } = { image: null };
  private readonly onFrame = (now: number, meta: VideoFrameCallbackMetadata): void => {
    const video = this.video;
    if (!this.running || !this.mesh || !video) return;
    if (!this.alive()) {
      this.stop();
      return;
    }
    // A camera frame's capture time where the browser gives it, else when it was shown.
    this.frameAt = meta.captureTime ?? now;
    this.sentAt = performance.now();
    this.input.image = video;
    this.inFlight = true;
    this.mesh.send(this.input as { image: HTMLVideoElement }).then(this.onSent, this.onFailed);
  };
  private readonly onSent = (): void => {
    this.inFlight = false;
    this.next();
  };
  private readonly onFailed = (error: unknown): void => {
    this.inFlight = false;
    this.status.message = `the face tracker failed: ${(error as Error).message}`;
    this.next();
  };

  private results(results: FaceMeshResults): void {
    this.inFlight = false;
    this.answered++;
    if (!this.running || !this.alive()) return;
    const now = performance.now();
    this.times[this.timeCount++ % this.times.length] = now;
    this.status.frames++;
    const landmarks = results.multiFaceLandmarks?.[0];
    this.status.face = landmarks !== undefined;
    if (!landmarks) {
      // The face keeps its expression until a face is back in view.
      this.status.message = 'no face in view';
      return;
    }
    const process = now - this.sentAt;
    this.status.processMs = this.status.processMs === 0 ? process : 0.8 * this.status.processMs + 0.2 * process;
    const ready = this.units.update(landmarks, results.image.width, results.image.height, this.frameAt);
    if (!ready) return;
    this.status.message = '';
    this.overlay(TRACKED_UNIT_IDS, this.units.values);
    this.status.capturedAt = this.frameAt;
    const latency = performance.now() - this.frameAt;
    this.status.latencyMs = this.status.latencyMs === 0 ? latency : 0.8 * this.status.latencyMs + 0.2 * latency;
  }

  private releaseStream(): void {
    for (const track of this.ownStream?.getTracks() ?? []) track.stop();
    this.ownStream = null;
  }
}
