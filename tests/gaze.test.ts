import { describe, expect, it } from 'vitest';
import { ExpressionState } from '../src/core/expression/facs';
import { actionUnitGaze, GAZE_AT_E, type Gaze } from '../src/core/expression/gaze';

describe('the eye positions AU61 to AU66 as a gaze', () => {
  const gaze = (units: Record<string, number>): Gaze => {
    const s = new ExpressionState();
    for (const [id, v] of Object.entries(units)) s.setActionUnit(id, v);
    return actionUnitGaze((id) => s.effectiveOf(id), { yaw: 0, pitch: 0, vergence: 0 });
  };

  it('turn the eyes by the thesis gaze range at E: 30 degrees to either side, 25 up, 20 down', () => {
    expect(GAZE_AT_E).toEqual({ left: 30, right: 30, up: 25, down: 20, out: 15, in: 15 });
    expect(gaze({ AU61: 1 })).toEqual({ yaw: 30, pitch: 0, vergence: 0 });
    expect(gaze({ AU62: 1 })).toEqual({ yaw: -30, pitch: 0, vergence: 0 });
    expect(gaze({ AU63: 1 })).toEqual({ yaw: 0, pitch: 25, vergence: 0 });
    expect(gaze({ AU64: 1 })).toEqual({ yaw: 0, pitch: -20, vergence: 0 });
    // Walleye turns each eye out, cross-eye in (toward the nose).
    expect(gaze({ AU65: 1 })).toEqual({ yaw: 0, pitch: 0, vergence: -15 });
    expect(gaze({ AU66: 1 })).toEqual({ yaw: 0, pitch: 0, vergence: 15 });
  });

  it('grow with intensity, combine, and cancel when opposed', () => {
    expect(gaze({ AU61: 0.5, AU64: 0.5 })).toEqual({ yaw: 15, pitch: -10, vergence: 0 });
    expect(gaze({ AU61: 1, AU62: 1 }).yaw).toBe(0);
    expect(gaze({})).toEqual({ yaw: 0, pitch: 0, vergence: 0 });
    expect(gaze({ AU65: 1, AU66: 1 }).vergence).toBe(0);
  });

  it('read effective intensities without building a record, refusing a bilateral unit without its side', () => {
    const s = new ExpressionState();
    s.setActionUnit('AU12L', 0.4);
    expect(s.effectiveOf('AU12L')).toBe(0.4);
    expect(() => s.effectiveOf('AU12')).toThrow(/^effectiveOf: expected an Action Unit side or midline unit/);
  });
});
