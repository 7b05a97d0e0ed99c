import { beforeAll, describe, expect, it } from 'vitest';
import { ACTION_UNITS } from '../src/core/expression/facs';
import { STOCK_IDENTITIES } from '../src/core/head/identity';
import { LATE_MOTION } from '../src/core/solver/solver-schedule';
import { MAX_SETTLE_FRAMES, returnToRest, settleExpression } from './fixtures/head-simulation';
import { loadIdentitySimulation } from './fixtures/identity-simulation';

// A person's head with the default rig carried over (as the page builds it, src/face/identity-head.ts) expresses as
// the default head does: every Action Unit and preset at full intensity settles by converging, with no NaN and no
// triangle turned over, and the skin comes home exactly after a reset. The old African woman: of the stock set, the
// head whose shape moves farthest from the default head's.
describe('every Action Unit and preset on a stock identity, medium head', () => {
  let sim: ReturnType<typeof loadIdentitySimulation>;
  beforeAll(() => {
    sim = loadIdentitySimulation(STOCK_IDENTITIES['old-african-woman'], 'medium');
  });

  const items = [...ACTION_UNITS.map((au) => au.id), 'happiness', 'sadness', 'surprise', 'fear', 'anger', 'disgust', 'contempt'];
  it.each(items)('%s comes to rest with no NaN and no triangle turned over, and goes back to rest after a reset', (item) => {
    const r = settleExpression(sim, item, MAX_SETTLE_FRAMES);
    expect(r).toMatchObject({ sleeping: true, nonFinite: 0, inverted: 0 });
    expect(r.frames).toBeLessThan(LATE_MOTION);
    expect(returnToRest(sim)).toMatchObject({ sleeping: true, offRest: 0, farthest: 0, activeVertices: 0 });
  });
});
