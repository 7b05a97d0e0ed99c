import { describe, expect, it } from 'vitest';
import { SKIN_DEFAULTS } from '../src/core/solver/skin-parameters';
import { InputStaging } from '../src/sim/main/input-staging';
import { controlLayout, controlViews, initControl } from '../src/sim/shared/layout';

/** A staging over a fresh control block of two vertices, and the batches it publishes. */
function staging(): { staging: InputStaging; published: number[] } {
  const rest = new Float32Array(6);
  const layout = controlLayout(2);
  const views = controlViews(new ArrayBuffer(layout.byteLength), layout);
  initControl(views, rest, { ...SKIN_DEFAULTS });
  const published: number[] = [];
  return { staging: new InputStaging(views, rest, (seq) => published.push(seq)), published };
}

describe('InputStaging.setParameters', () => {
  it('takes the given parameters over the current ones', () => {
    const { staging: s } = staging();
    s.setParameters({ lengthIterations: 0, bulge: 10 });
    expect(s.parameters()).toEqual({ ...SKIN_DEFAULTS, lengthIterations: 0, bulge: 10 });
  });

  it('refuses a bad one by name in the check.ts format, changing nothing and publishing nothing', () => {
    const { staging: s, published } = staging();
    expect(() => s.setParameters({ bulge: 1, lengthIterations: 65 })).toThrow(
      'skin parameters: lengthIterations: expected an integer from 0 to 64, got 65',
    );
    expect(() => s.setParameters({ positionIterations: 2.5 })).toThrow(
      'skin parameters: positionIterations: expected an integer from 1 to 64, got 2.5',
    );
    expect(() => s.setParameters({ momentum: 0.95 })).toThrow('skin parameters: momentum: expected a number from 0 to 0.9, got 0.95');
    expect(() => s.setParameters({ stiffness: 1 } as never)).toThrow(
      'skin parameters: expected one of the options positionIterations, lengthIterations, positionStiffness, lengthStiffness, ' +
        'muscleStiffness, wrinkleSpacing, inwardResistance, bulge, sleepTolerance, momentum, startMomentum, foldMomentum, ' +
        'pretension, got "stiffness"',
    );
    expect(() => s.setParameters(null as never)).toThrow('skin parameters: expected an object of options, got null');
    expect(s.parameters()).toEqual(SKIN_DEFAULTS);
    s.flush();
    expect(published).toEqual([]);
  });
});
