import { existsSync, readFileSync, renameSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test } from '@playwright/test';
import type { Stimulus } from './stimulus-list';

const out = process.env.STIMULI_OUT;
if (!out) throw new Error('STIMULI_OUT is not set: run stimuli through `npm run stimuli -- <list.json> <out folder>`');
const stimuli: Stimulus[] = JSON.parse(readFileSync(join(out, '.stimuli-plan.json'), 'utf8'));

for (const [index, s] of stimuli.entries()) {
  test(s.file, async ({ page }) => {
    const path = join(out, s.file);
    // Resumable: what a earlier run finished is there, whole (files are written under another name, then renamed).
    test.skip(existsSync(path), 'already rendered');
    await page.setViewportSize({ width: s.width, height: s.height });
    // The app builds the person a link's hash names as its first head.
    await page.goto(`/?resolution=${s.resolution}${s.identity ? `#identity=${encodeURIComponent(s.identity)}` : ''}`);
    await expect(page.locator('html')).toHaveAttribute('data-state', /ready|error/, { timeout: 120_000 });
    await expect(page.locator('html')).toHaveAttribute('data-state', 'ready');
    const base64 = await page.evaluate(async (s) => {
      const face = window.face;
      await face.ready;
      face.setLight(s.light);
      face.setCamera(s.camera);
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
