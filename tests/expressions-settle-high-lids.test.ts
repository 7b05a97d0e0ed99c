import { beforeAll, describe, expect, it } from 'vitest';
import { LATE_MOTION } from '../src/core/solver/solver-schedule';
import { loadHeadSimulation, MAX_SETTLE_FRAMES, settleExpression } from './fixtures/head-simulation';

// The closing lids on the high head, solved as the worker solves it. A closing lid rolls its margin's skin past
// edge-on at the eye's corners; with each triangle's bound on turning over taken about its rest normal, that skin
// pulled against the lid until the safety net: AU43 and AU45 ran 1,001 frames and ended with 3 triangles turned over,
// the wink AU46 1,249 with 10. With the bounds turned as the lid turns the skin (src/core/solver/carried-frames.ts)
// they sleep after 124, 124 and 103 (docs/solver-notes.md, "Orientation frames carried with the lids"). AU45's
// muscles are AU43's, so AU43 stands for both.
describe('the closing lids on the high head', () => {
  let sim: Awaited<ReturnType<typeof loadHeadSimulation>>;
  beforeAll(async () => {
    sim = await loadHeadSimulation('high');
  });

  it.each(['AU43', 'AU46'])('%s comes to rest by converging, with no triangle turned over', (item) => {
    const r = settleExpression(sim, item, MAX_SETTLE_FRAMES);
    expect(r).toMatchObject({ sleeping: true, nonFinite: 0, inverted: 0 });
    // Converged, not stopped by the safety net.
    expect(r.frames).toBeLessThan(LATE_MOTION);
  });
});
