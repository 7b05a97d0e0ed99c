import { readFileSync } from 'node:fs';
import { openFace } from './face';
import { expect, test } from './fixtures';
import { control, openFolder } from './panels';

/**
 * A loaded head gets brows and lashes too, placed from its own eye corners: brow roots over each eye between a third
 * of an eye width and one eye width above the corners, lashes within 0.3 eye widths of the corners' line (the lid
 * margins of the default head are 0.23 above it and 0.11 below at most).
 */
test.describe.configure({ timeout: 300_000 });

for (const file of ['wide-jaw.glb', 'long-face.obj']) {
  test(`${file} gets brows over its own eyes and lashes on its lids`, async ({ page }) => {
    await openFace(page, '/?resolution=low');
    await openFolder(page, 'Head');
    await control(page, 'head-file').setInputFiles({
      name: file,
      mimeType: 'application/octet-stream',
      buffer: readFileSync(new URL(`./assets/${file}`, import.meta.url)),
    });
    await expect(control(page, 'head-message')).toContainText(`loaded ${file}`, { timeout: 60_000 });
    const r = await page.evaluate(() => {
      const face = window.face;
      const { landmarks: L } = face.describeHead();
      const hair = face.getHair();
      const roots = (p: typeof hair.brows): number[][] =>
        Array.from({ length: p.count }, (_, h) =>
          [0, 1, 2].map((k) => (p.positions[3 * h * p.verticesPerHair + k] + p.positions[3 * (h * p.verticesPerHair + 1) + k]) / 2),
        );
      const side = (r: number[]): 'l' | 'r' => (r[0] > 0 ? 'l' : 'r');
      const above = (r: number[]): number => {
        const s = side(r);
        const inner = L[`eye-inner-${s}`],
          outer = L[`eye-outer-${s}`];
        return (r[1] - (inner[1] + outer[1]) / 2) / Math.hypot(outer[0] - inner[0], outer[1] - inner[1]);
      };
      const brows = roots(hair.brows).map(above);
      const lashes = roots(hair.lashes).map((r) => Math.abs(above(r)));
      return {
        brows: brows.length,
        browsLow: Math.min(...brows),
        browsHigh: Math.max(...brows),
        lashes: lashes.length,
        lashesFar: Math.max(...lashes),
      };
    });
    expect(r.brows).toBeGreaterThan(800);
    expect(r.browsLow).toBeGreaterThan(0.33);
    expect(r.browsHigh).toBeLessThan(1);
    expect(r.lashes).toBeGreaterThan(100);
    expect(r.lashesFar).toBeLessThan(0.3);
  });
}
