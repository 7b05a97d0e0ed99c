import { describe, expect, it } from 'vitest';
import { checkVideoOptions, VIDEO_DEFAULTS, videoFrameCount } from '../src/face/video-options';

describe('recordVideo options', () => {
  it('fills in the defaults and keeps what is given', () => {
    expect(checkVideoOptions({})).toEqual(VIDEO_DEFAULTS);
    const onProgress = (): void => {};
    const o = checkVideoOptions({
      fps: 10,
      width: 320,
      height: 240,
      seconds: 2,
      format: 'png-zip',
      onProgress,
      solverFramesPerVideoFrame: undefined,
    });
    expect(o).toMatchObject({ fps: 10, width: 320, height: 240, seconds: 2, format: 'png-zip', solverFramesPerVideoFrame: 6 });
    expect(o.onProgress).toBe(onProgress);
  });

  it('refuses a bad option naming it', () => {
    const cases: [object, RegExp][] = [
      [{ fps: Number.NaN }, /^recordVideo: fps: .*got NaN$/],
      [{ fps: 0 }, /^recordVideo: fps: /],
      [{ width: 0 }, /^recordVideo: width: .*got 0$/],
      [{ width: 4098 }, /^recordVideo: width: .*16 to 4096, got 4098$/],
      [{ height: 240.5 }, /^recordVideo: height: expected an integer from 16 to \d+, got 240.5$/],
      [{ height: 241 }, /^recordVideo: height: expected an even number, got 241$/],
      [{ seconds: -1 }, /^recordVideo: seconds: /],
      [{ seconds: Infinity }, /^recordVideo: seconds: /],
      [{ solverFramesPerVideoFrame: 0 }, /^recordVideo: solverFramesPerVideoFrame: /],
      [{ format: 'mp4' }, /^recordVideo: format: expected one of "webm", "png-zip", got "mp4"$/],
      [{ timeline: 3 }, /^recordVideo: timeline: /],
      [{ signal: {} }, /^recordVideo: signal: /],
      [{ onProgress: 'yes' }, /^recordVideo: onProgress: /],
      [{ fsp: 30 }, /^recordVideo: expected one of the options .*, got "fsp"$/],
    ];
    for (const [options, message] of cases) expect(() => checkVideoOptions(options as never), JSON.stringify(options)).toThrow(message);
    expect(() => checkVideoOptions(null as never)).toThrow(/^recordVideo: expected an object of options/);
  });

  it('counts one frame per step of 1 / fps before the end', () => {
    expect(videoFrameCount(2, 10)).toBe(20);
    expect(videoFrameCount(0.3, 10)).toBe(3);
    expect(videoFrameCount(1, 30)).toBe(30);
    expect(videoFrameCount(0.05, 10)).toBe(1);
    expect(videoFrameCount(2.05, 10)).toBe(21);
  });
});
