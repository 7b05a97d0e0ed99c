import { existsSync, readFileSync, renameSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import type { CameraOptions, LightOptions } from '../../src/embed/index';
import type { Stimulus } from './stimulus-list';

declare global {
  interface Window {
    /** The light and camera the page opened with (see below). */
    stimulusStart: { light: LightOptions; camera: CameraOptions };
  }
}

const out = process.env.STIMULI_OUT;
if (!out) throw new Error('STIMULI_OUT is not set: run stimuli through `npm run stimuli -- <list.json> <out folder>`');
const stimuli: Stimulus[] = JSON.parse(readFileSync(join(out, '.stimuli-plan.json'), 'utf8'));

/**
 * The page the last stimulus was rendered on, and what it was opened for (head and size): the next stimulus with the
 * same takes it over, from the neutral face at rest, instead of loading the app again (a second or more a stimulus in
 * software WebGL). One per Playwright worker.
 */
let kept: { page: Page; key: string } | null = null;

test.afterAll(async () => {
  await kept?.page.close();
  kept = null;
});

for (const [index, s] of stimuli.entries()) {
  test(s.file, async ({ browser }) => {
    const path = join(out, s.file);
    // Resumable: what a earlier run finished is there, whole (files are written under another name, then renamed).
    test.skip(existsSync(path), 'already rendered');
    const key = JSON.stringify([s.resolution, s.identity, s.width, s.height]);
    if (kept?.key !== key) {
      await kept?.page.close();
      const page = await browser.newPage({ viewport: { width: s.width, height: s.height } });
      kept = { page, key };
      // The app builds the person a link's hash names as its first head.
      await page.goto(`/?resolution=${s.resolution}${s.identity ? `#identity=${encodeURIComponent(s.identity)}` : ''}`);
      await expect(page.locator('html')).toHaveAttribute('data-state', /ready|error/, { timeout: 120_000 });
      await expect(page.locator('html')).toHaveAttribute('data-state', 'ready');
      await page.evaluate(async () => {
        await window.face.ready;
        // What the page started with: each stimulus's light and camera are these with its own over them.
        window.stimulusStart = { light: window.face.getLight(), camera: window.face.getCamera() };
      });
    }
    const base64 = await kept.page.evaluate(async (s) => {
      const face = window.face;
      // The neutral face at rest, as a new page shows it: the skin comes home exactly, so each picture is the one its
      // stimulus gives alone, whatever came before it on this page.
      face.clearTimeline();
      face.reset();
      await face.settle(240_000);
      face.setLight({ ...window.stimulusStart.light, ...s.light });
      face.setCamera({ ...window.stimulusStart.camera, ...s.camera });
      let blob: Blob;
      if (s.format === 'png') {
        face.setExpression(s.expression!);
        await face.settle(240_000);
        blob = await face.savePNG();
      } else {
        face.setTimeline(s.timeline!);
        blob = await face.recordVideo({ fps: s.fps, width: s.width, height: s.height, format: 'webm' });
      }
      const bytes = new Uint8Array(await blob.arrayBuffer());
      let text = '';
      for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      return btoa(text);
    }, s);
    writeFileSync(`${path}.part`, Buffer.from(base64, 'base64'));
    renameSync(`${path}.part`, path);
    console.log(`wrote ${s.file} (${index + 1} of ${stimuli.length})`);
  });
}
