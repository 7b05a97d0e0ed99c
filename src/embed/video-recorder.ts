import { Zip, ZipPassThrough } from 'fflate';
import { BufferTarget, EncodedPacket, EncodedVideoPacketSource, Output, WebMOutputFormat } from 'mediabunny';
import type { HeadView, ViewCapture } from '../render/head-view';
import type { SkinView } from '../render/skin-view';
import type { SkinSimulation } from '../worker/skin-simulation';
import type { FaceHandle } from './face-handle';
import { videoFrameCount, type VideoOptions } from './video-options';

/** What a recorder works with: the face's handle, its skin solver and view, and the skin mesh's updater. */
export interface VideoRecorderParts {
  handle: FaceHandle;
  simulation: SkinSimulation;
  view: HeadView;
  skin: SkinView;
}

/**
 * Solver frames the start may take to settle on the timeline's first values (the default rig's expressions sleep
 * within 282 frames; the safety net stops any drift by about 1,000).
 */
const START_FRAMES = 2000;
/** How long the skin may take to come back to rest before a recording, in ms. */
const REST_TIMEOUT_MS = 60_000;
/** A key frame every this many seconds, so that a player can seek. */
const KEY_FRAME_SECONDS = 2;
/** Frames the encoder may hold before the recorder waits for it. */
const ENCODE_QUEUE = 4;
/** The date the zip gives its files (the earliest a zip can hold). */
const ZIP_DATE = new Date(1980, 0, 1);
/** VP9 profile 0, level 5.1 (up to 4096 x 2176), 8 bits; VP8 has no profiles to name. */
const CODECS = [
  { name: 'vp9', codec: 'vp09.00.51.08' },
  { name: 'vp8', codec: 'vp8' },
] as const;

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
    let stepped = false;
    try {
      if (before.loaded) handle.pause();
      // Blinks and saccades are random and on the page's clock: they stay out of the video.
      if (eyes) handle.setEyeSimulation(false);
      capture = view.capture(o.width, o.height);
      await this.start(before.loaded);
      stepped = true;
      const frames = videoFrameCount(seconds, o.fps);
      const sink = o.format === 'webm' ? await webmSink(o) : pngZipSink();
      try {
        for (let i = 0; i < frames; i++) {
          o.signal?.throwIfAborted();
          if (before.loaded) handle.seek(i / o.fps);
          await simulation.runFrames(o.solverFramesPerVideoFrame);
          this.parts.skin.update();
          capture.render();
          await sink.add(capture.canvas, i, o.fps);
          o.onProgress?.((i + 1) / frames);
        }
        o.signal?.throwIfAborted();
        return await sink.finish();
      } catch (error) {
        sink.cancel();
        throw error;
      }
    } finally {
      this.busy = false;
      if (!handle.isDisposed()) {
        if (stepped) simulation.setClock('free');
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
    const expression = handle.carriedState().expression;
    const overlay = handle.getOverlay();
    handle.reset();
    handle.clearOverlay();
    await simulation.settle(REST_TIMEOUT_MS);
    simulation.setClock('stepped');
    const entries: Record<string, number> = { ...expression.actionUnits };
    for (const [name, weight] of Object.entries(expression.presets)) if (weight !== 0) entries[`preset:${name}`] = weight;
    handle.setExpression(entries);
    const ids = Object.keys(overlay);
    if (ids.length > 0) handle.setOverlay(ids, Object.values(overlay));
    if (timeline) handle.seek(0);
    await simulation.runFrames(START_FRAMES);
  }
}

/** Where the pictures go: a WebM encoder and muxer, or a zip of PNGs. */
interface FrameSink {
  add(canvas: HTMLCanvasElement, index: number, fps: number): Promise<void>;
  finish(): Promise<Blob>;
  /** Frees what the sink holds after a failure or a cancel. */
  cancel(): void;
}

/** The first of VP9 and VP8 this browser encodes at the options' size, rate and bitrate. */
async function encoderConfig(o: Required<VideoOptions>): Promise<{ name: 'vp9' | 'vp8'; config: VideoEncoderConfig }> {
  if (typeof VideoEncoder === 'undefined') throw new Error('recordVideo: this browser has no WebCodecs VideoEncoder; record a PNG zip instead');
  for (const { name, codec } of CODECS) {
    const config: VideoEncoderConfig = {
      codec,
      width: o.width,
      height: o.height,
      bitrate: o.bitrate,
      framerate: o.fps,
      hardwareAcceleration: 'no-preference',
      latencyMode: 'quality',
    };
    const support = await VideoEncoder.isConfigSupported(config);
    if (support.supported) return { name, config };
  }
  throw new Error(`recordVideo: this browser cannot encode VP9 or VP8 at ${o.width} x ${o.height}; record a PNG zip instead`);
}

/** Encodes with WebCodecs and muxes the packets into a WebM file in memory. */
async function webmSink(o: Required<VideoOptions>): Promise<FrameSink> {
  const { name, config } = await encoderConfig(o);
  const output = new Output({ format: new WebMOutputFormat(), target: new BufferTarget() });
  const source = new EncodedVideoPacketSource(name);
  output.addVideoTrack(source, { frameRate: o.fps });
  await output.start();
  let failure: Error | undefined;
  // The muxer takes packets one at a time, in order.
  let muxed = Promise.resolve();
  const encoder = new VideoEncoder({
    output: (chunk, meta) => {
      muxed = muxed.then(() => source.add(EncodedPacket.fromEncodedChunk(chunk), meta)).catch((error: unknown) => {
        failure ??= error instanceof Error ? error : new Error(String(error));
      });
    },
    error: (error) => (failure ??= error),
  });
  encoder.configure(config);
  const keyEvery = Math.max(1, Math.round(KEY_FRAME_SECONDS * o.fps));
  return {
    async add(canvas, index, fps) {
      if (failure) throw failure;
      const frame = new VideoFrame(canvas, { timestamp: Math.round((index * 1e6) / fps), duration: Math.round(1e6 / fps) });
      encoder.encode(frame, { keyFrame: index % keyEvery === 0 });
      frame.close();
      while (encoder.encodeQueueSize > ENCODE_QUEUE && !failure) await new Promise((resolve) => encoder.addEventListener('dequeue', resolve, { once: true }));
    },
    async finish() {
      await encoder.flush();
      encoder.close();
      await muxed;
      if (failure) throw failure;
      await output.finalize();
      return new Blob([output.target.buffer!], { type: 'video/webm' });
    },
    cancel() {
      if (encoder.state !== 'closed') encoder.close();
      void output.cancel();
    },
  };
}

/** Encodes each picture as a PNG and stores it (PNGs are compressed already) in a zip, `frame-00000.png` on. */
function pngZipSink(): FrameSink {
  const chunks: Uint8Array[] = [];
  let failure: Error | undefined;
  const zip = new Zip((error, chunk) => {
    if (error) failure ??= error;
    else chunks.push(chunk);
  });
  return {
    async add(canvas, index) {
      if (failure) throw failure;
      const png = await new Promise<Blob>((resolve, reject) => canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('recordVideo: a frame could not be encoded as a PNG'))), 'image/png'));
      const file = new ZipPassThrough(`frame-${String(index).padStart(5, '0')}.png`);
      // A fixed date: the same recording gives the same file.
      file.mtime = ZIP_DATE;
      zip.add(file);
      file.push(new Uint8Array(await png.arrayBuffer()), true);
    },
    async finish() {
      zip.end();
      if (failure) throw failure;
      return new Blob(chunks as BlobPart[], { type: 'application/zip' });
    },
    cancel() {
      zip.terminate();
    },
  };
}
