import { describe, expect, it } from 'vitest';
import { compressForehead } from './fixtures/forehead';

describe('forehead folds on the real head', () => {
  it('have a dominant wavelength within 25 % between the 17k and 68k heads', async () => {
    const medium = await compressForehead('medium', 0.12);
    const high = await compressForehead('high', 0.12);
    for (const r of [medium, high]) {
      expect(r.sleeping).toBe(true);
      // Folds, not a flat slide: 0.1 mm root mean square is far above float noise and about a tenth of a real crease.
      expect(r.amplitude).toBeGreaterThan(0.0001);
    }
    expect(Math.abs(medium.wavelength - high.wavelength) / Math.max(medium.wavelength, high.wavelength)).toBeLessThan(0.25);
  });
});
