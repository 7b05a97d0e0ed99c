/** Where a recording's pictures go: WebCodecs and mediabunny for WebM, fflate for a zip of PNGs. */
import { Zip, ZipPassThrough } from 'fflate';
import { BufferTarget, EncodedPacket, EncodedVideoPacketSource, Output, WebMOutputFormat } from 'mediabunny';
import type { VideoOptions } from './video-options';

/** VP9 profile 0, level 5.1 (up to 4096 x 2176), 8 bits; VP8 has no profiles to name. */
const CODECS = [
  { name: 'vp9', codec: 'vp09.00.51.08' },
  { name: 'vp8', codec: 'vp8' },
] as const;
/** The date the zip gives its files (the earliest a zip can hold). */
const ZIP_DATE = new Date(1980, 0, 1);
/** Frames the encoder may hold before the recorder waits for it. */
const ENCODE_QUEUE = 4;
/** A key frame every this many seconds, so that a player can seek. */
const KEY_FRAME_SECONDS = 2;

/** Where the pictures go: a WebM encoder and muxer, or a zip of PNGs. */
export interface FrameSink {
  add(canvas: HTMLCanvasElement, index: number, fps: number): Promise<void>;
  /** Adds the last picture added again, as frame `index` (a held expression: see HeldPicture). */
  repeat(index: number, fps: number): Promise<void>;
  finish(): Promise<Blob>;
  /** Frees what the sink holds after a failure or a cancel. */
  cancel(): void;
}

/** The first of VP9 and VP8 this browser encodes at the options' size, rate and bitrate. */
async function encoderConfig(o: Required<VideoOptions>): Promise<{ name: 'vp9' | 'vp8'; config: VideoEncoderConfig }> {
  if (typeof VideoEncoder === 'undefined')
    throw new Error('recordVideo: this browser has no WebCodecs VideoEncoder; record a PNG zip instead');
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
export async function webmSink(o: Required<VideoOptions>): Promise<FrameSink> {
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
      muxed = muxed
        .then(() => source.add(EncodedPacket.fromEncodedChunk(chunk), meta))
        .catch((error: unknown) => {
          failure ??= error instanceof Error ? error : new Error(String(error));
        });
    },
    error: (error) => (failure ??= error),
  });
  encoder.configure(config);
  const keyEvery = Math.max(1, Math.round(KEY_FRAME_SECONDS * o.fps));
  // The last picture, kept for `repeat`.
  let last: VideoFrame | undefined;
  const encode = async (source: HTMLCanvasElement | VideoFrame, index: number, fps: number): Promise<void> => {
    if (failure) throw failure;
    const frame = new VideoFrame(source, { timestamp: Math.round((index * 1e6) / fps), duration: Math.round(1e6 / fps) });
    encoder.encode(frame, { keyFrame: index % keyEvery === 0 });
    if (source === last) frame.close();
    else {
      last?.close();
      last = frame;
    }
    while (encoder.encodeQueueSize > ENCODE_QUEUE && !failure)
      await new Promise((resolve) => encoder.addEventListener('dequeue', resolve, { once: true }));
  };
  return {
    add: encode,
    async repeat(index, fps) {
      if (!last) throw new Error('recordVideo: no picture to repeat');
      await encode(last, index, fps);
    },
    async finish() {
      last?.close();
      await encoder.flush();
      encoder.close();
      await muxed;
      if (failure) throw failure;
      await output.finalize();
      return new Blob([output.target.buffer!], { type: 'video/webm' });
    },
    cancel() {
      last?.close();
      if (encoder.state !== 'closed') encoder.close();
      void output.cancel();
    },
  };
}

/** Encodes each picture as a PNG and stores it (PNGs are compressed already) in a zip, `frame-00000.png` on. */
export function pngZipSink(): FrameSink {
  const chunks: Uint8Array[] = [];
  let failure: Error | undefined;
  const zip = new Zip((error, chunk) => {
    if (error) failure ??= error;
    else chunks.push(chunk);
  });
  // The last picture's PNG, kept for `repeat`.
  let last: Uint8Array | undefined;
  const store = (png: Uint8Array, index: number): void => {
    const file = new ZipPassThrough(`frame-${String(index).padStart(5, '0')}.png`);
    // A fixed date: the same recording gives the same file.
    file.mtime = ZIP_DATE;
    zip.add(file);
    file.push(png, true);
  };
  return {
    async add(canvas, index) {
      if (failure) throw failure;
      const png = await new Promise<Blob>((resolve, reject) =>
        canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('recordVideo: a frame could not be encoded as a PNG'))), 'image/png'),
      );
      last = new Uint8Array(await png.arrayBuffer());
      store(last, index);
    },
    async repeat(index) {
      if (failure) throw failure;
      if (!last) throw new Error('recordVideo: no picture to repeat');
      store(last, index);
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
