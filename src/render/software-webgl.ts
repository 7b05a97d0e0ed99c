/** Cached: the answer does not change within a page, and each probe costs a WebGL context. */
let software: boolean | undefined;

/** Software rasterisers by the names browsers give them (Chromium's SwiftShader, Mesa's llvmpipe and softpipe). */
const SOFTWARE_RENDERERS = /swiftshader|llvmpipe|softpipe|software/i;

/**
 * Whether this page's WebGL runs in software: a renderer named as one, or a context that must not carry a major
 * performance caveat cannot be made (a browser that hides the renderer's name). There a multisampled canvas costs
 * more than the rest of a draw together (the medium head: 279 ms a frame with it, 134 ms without, in SwiftShader at
 * 900 x 900).
 */
export function softwareWebGL(): boolean {
  if (software === undefined) {
    const gl = document.createElement('canvas').getContext('webgl2', { failIfMajorPerformanceCaveat: true });
    const info = gl?.getExtension('WEBGL_debug_renderer_info');
    software = gl === null || (info ? SOFTWARE_RENDERERS.test(String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL))) : false);
    // Given back at once: the browser keeps at most 16 contexts alive and drops the oldest past that.
    gl?.getExtension('WEBGL_lose_context')?.loseContext();
  }
  return software;
}
