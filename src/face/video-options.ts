/** The options of `face.recordVideo`, checked at the boundary. */
import { checkChoice, checkNumber, checkObject, refusal } from '../core/check';

/** What a recording is saved as: a WebM video (VP9, or VP8 where VP9 cannot be encoded) or a zip of PNG frames. */
export type VideoFormat = 'webm' | 'png-zip';

/** Options of `face.recordVideo`. */
export interface VideoOptions {
  /** Frames per second of the video, 1 to 120. */
  fps?: number;
  /** Width of the video in pixels: even, 16 to 4096. */
  width?: number;
  /** Height of the video in pixels: even, 16 to 4096. */
  height?: number;
  /** Length in seconds (up to 3600); 0 records the timeline's whole duration. */
  seconds?: number;
  /** A timeline document (JSON text or object) to load first, as `setTimeline` does; null records the loaded one. */
  timeline?: string | object | null;
  /** What the recording is saved as: `webm`, a WebM video, or `png-zip`, a zip of PNG frames (see `VideoFormat`). */
  format?: VideoFormat;
  /**
   * Solver frames between two video frames, 1 to 100: the skin reaches 2 % of a step's final shape in 44 to 63
   * frames (see docs/benchmark.md), so 6 lets it follow a 10 fps video about as it follows the live page, and a
   * 30 fps video more closely.
   */
  solverFramesPerVideoFrame?: number;
  /** Bits per second the WebM encoder aims at. */
  bitrate?: number;
  /** Aborting it stops the recording, which then rejects with the signal's reason. */
  signal?: AbortSignal | null;
  /** Told after each frame how much of the recording is done, 0 to 1. */
  onProgress?: ((fraction: number) => void) | null;
}

/** What `recordVideo` takes for each option left out: 640 x 480 pixels at 30 fps, WebM at 4 Mbit/s. */
export const VIDEO_DEFAULTS: Readonly<Required<VideoOptions>> = Object.freeze({
  fps: 30,
  width: 640,
  height: 480,
  seconds: 0,
  timeline: null,
  format: 'webm',
  solverFramesPerVideoFrame: 6,
  bitrate: 4_000_000,
  signal: null,
  onProgress: null,
});

/** The largest width or height a recording may have. */
const MAX_VIDEO_SIZE = 4096;
/** The longest recording, in seconds (as long as the longest timeline). */
const MAX_VIDEO_SECONDS = 3600;

const FORMATS: readonly VideoFormat[] = ['webm', 'png-zip'];

/** Fills in the defaults and checks every option; a bad one throws naming it (`recordVideo: fps: ...`). */
export function checkVideoOptions(options: VideoOptions): Required<VideoOptions> {
  for (const name of Object.keys(checkObject('recordVideo', options))) {
    if (!(name in VIDEO_DEFAULTS)) throw refusal('recordVideo', '', `one of the options ${Object.keys(VIDEO_DEFAULTS).join(', ')}`, name);
  }
  const o: Required<VideoOptions> = { ...VIDEO_DEFAULTS };
  for (const [name, value] of Object.entries(options)) if (value !== undefined) (o as Record<string, unknown>)[name] = value;
  checkNumber('recordVideo', 'fps', o.fps, [1, 120]);
  checkNumber('recordVideo', 'width', o.width, [16, MAX_VIDEO_SIZE], true);
  checkNumber('recordVideo', 'height', o.height, [16, MAX_VIDEO_SIZE], true);
  // The encoders take 4:2:0 pictures, whose colour planes are half the size each way.
  if (o.width % 2 !== 0) throw refusal('recordVideo', 'width', 'an even number', o.width);
  if (o.height % 2 !== 0) throw refusal('recordVideo', 'height', 'an even number', o.height);
  checkNumber('recordVideo', 'seconds', o.seconds, [0, MAX_VIDEO_SECONDS]);
  checkNumber('recordVideo', 'solverFramesPerVideoFrame', o.solverFramesPerVideoFrame, [1, 100], true);
  checkNumber('recordVideo', 'bitrate', o.bitrate, [10_000, 100_000_000]);
  checkChoice('recordVideo', 'format', o.format, FORMATS);
  if (o.timeline !== null && typeof o.timeline !== 'string' && typeof o.timeline !== 'object') {
    throw refusal('recordVideo', 'timeline', 'a timeline document (JSON text or object) or null', o.timeline);
  }
  if (o.signal !== null && !(typeof o.signal === 'object' && typeof (o.signal as AbortSignal).throwIfAborted === 'function')) {
    throw refusal('recordVideo', 'signal', 'an AbortSignal', o.signal);
  }
  if (o.onProgress !== null && typeof o.onProgress !== 'function') throw refusal('recordVideo', 'onProgress', 'a function', o.onProgress);
  return o;
}

/** Video frames a recording of `seconds` at `fps` has: the frame at each whole step of 1 / fps before the end. */
export function videoFrameCount(seconds: number, fps: number): number {
  // A hair under a whole step counts as one (2 s at 10 fps is 20 frames, not 19 for a float's rounding).
  return Math.max(1, Math.ceil(seconds * fps - 1e-9));
}
