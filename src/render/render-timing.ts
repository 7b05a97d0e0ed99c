import type { Camera, Scene, WebGLRenderer } from 'three';
import type { HairView } from './hair-view';

/** What `measureRender` reports: main-thread time of `renderer.render` and what the last frame drew. */
export interface RenderTiming {
  /** Frames timed, as asked (a frame rendered before them, to compile shaders and upload textures, is not counted). */
  frames: number;
  /** Mean main-thread milliseconds per frame spent in `renderer.render`. */
  meanMs: number;
  /** Median main-thread milliseconds per frame spent in `renderer.render`. */
  medianMs: number;
  /** Mean main-thread milliseconds per frame spent posing the brows and lashes on the skin (as at a new skin frame). */
  hairMeanMs: number;
  /** Median main-thread milliseconds per frame spent posing the brows and lashes on the skin. */
  hairMedianMs: number;
  /** Wall milliseconds per frame over the whole run, waiting at the end for the GPU to finish (pixel cost included). */
  finishedMs: number;
  /** Draw calls of the last frame (`renderer.info.render.calls`). */
  calls: number;
  /** Triangles the last frame drew (`renderer.info.render.triangles`). */
  triangles: number;
  /** Shader programs the renderer holds (`renderer.info.programs`). */
  programs: number;
  /** Textures the renderer holds on the GPU (`renderer.info.memory.textures`). */
  textures: number;
}
/**
 * Renders `frames` frames back to back, timing each `renderer.render` call with `performance.now()`, and the hair's
 * posing on the skin before it, as at every new skin frame (a benchmark: it blocks the page while it runs). The
 * caller renders one frame first, so that shader compilation and texture upload are not counted.
 */
export function timeRenders(
  renderer: WebGLRenderer,
  scene: Scene,
  camera: Camera,
  hair: HairView | undefined,
  frames: number,
): RenderTiming {
  const times: number[] = [];
  const gl = renderer.getContext();
  const pixel = new Uint8Array(4);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  const hairTimes: number[] = [];
  const start = performance.now();
  for (let i = 0; i < frames; i++) {
    // As at every new skin frame: the hair is posed on the skin, and its attributes go to the GPU in the render.
    const h0 = performance.now();
    hair?.skinChanged();
    hairTimes.push(performance.now() - h0);
    const t0 = performance.now();
    renderer.render(scene, camera);
    times.push(performance.now() - t0);
  }
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  const finishedMs = (performance.now() - start) / frames;
  times.sort((a, b) => a - b);
  hairTimes.sort((a, b) => a - b);
  const info = renderer.info;
  return {
    frames,
    meanMs: times.reduce((s, t) => s + t, 0) / frames,
    medianMs: times[Math.floor(frames / 2)],
    hairMeanMs: hairTimes.reduce((s, t) => s + t, 0) / frames,
    hairMedianMs: hairTimes[Math.floor(frames / 2)],
    finishedMs,
    calls: info.render.calls,
    triangles: info.render.triangles,
    programs: info.programs?.length ?? 0,
    textures: info.memory.textures,
  };
}
