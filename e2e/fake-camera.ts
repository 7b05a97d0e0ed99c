import { chromium, type Browser } from '@playwright/test';
import { BROWSER_ARGS } from '../scripts/browser.mjs';
import { chromiumPath } from '../scripts/chromium-path.mjs';

/**
 * A Chromium of its own whose camera is fake and granted without asking: Chromium's test pattern, or the frames of a
 * YUV4MPEG2 `file` (looping). Close it when done.
 */
export function launchWithFakeCamera(file?: string): Promise<Browser> {
  return chromium.launch({
    executablePath: chromiumPath(),
    args: [
      ...BROWSER_ARGS,
      '--use-fake-ui-for-media-stream',
      '--use-fake-device-for-media-stream',
      ...(file ? [`--use-file-for-fake-video-capture=${file}`] : []),
    ],
  });
}
