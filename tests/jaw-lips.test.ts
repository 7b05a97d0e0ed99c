import { describe, expect, it } from 'vitest';
import { STOCK_IDENTITIES } from '../src/core/head/identity';
import { findLipSlit } from '../src/core/head/lip-slit';
import { fitJawToLips } from '../src/core/rig/jaw-lips';
import { MuscleField } from '../src/core/rig/muscle-fields';
import type { JawMuscle, Rig, Vec3 } from '../src/core/rig/rig-types';
import { loadIdentitySimulation } from './fixtures/identity-simulation';
import { DEFAULT_LANDMARKS } from '../src/core/head/landmarks';
import { warpPoint } from '../src/core/head/thin-plate';

const JAW: JawMuscle = {
  name: 'jaw',
  side: 'mid',
  type: 'jaw',
  center: [0, 0.63, 0.12],
  rotation: [0, 0, 0],
  size: [0.13, 0.06, 0.11],
  joint: [0, 0.66, 0.07],
  maxAngle: 25,
  curve: 0,
  fade: 0.012,
  lipFade: 0.0006,
};

const rigOf = (jaw: JawMuscle): Rig =>
  ({ format: 'softface-rig', version: 1, muscles: [jaw], actionUnits: [], presets: [] }) as unknown as Rig;
const jawOf = (rig: Rig): JawMuscle => rig.muscles[0] as JawMuscle;
/** The box's top and bottom faces' heights along its local y axis (an unturned box: world y). */
const faces = (j: JawMuscle) => [j.center[1] + j.size[1] / 2, j.center[1] - j.size[1] / 2];

describe("the jaw's top face put between the lips", () => {
  it('moves the top face lipFade above the lower lip, keeping the bottom face and the hinge', () => {
    // The top face at 0.66 lies inside the lower lip, whose top is at 0.6612; the upper lip's underside is at 0.6622.
    const fitted = jawOf(fitJawToLips(rigOf(JAW), [0, 0.6622, 0.15], [0, 0.6612, 0.15]));
    const [top, bottom] = faces(fitted);
    expect(top).toBeCloseTo(0.6612 + 0.0006, 6);
    expect(bottom).toBeCloseTo(faces(JAW)[1], 6);
    expect(fitted.joint).toEqual(JAW.joint);
    expect(fitted.lipFade).toBe(0.0006);
    expect(fitted.center[0]).toBe(0);
    expect(fitted.center[2]).toBe(0.12);
  });

  it('in a gap narrower than the fade, sits at 0.8 of it with the fade shortened to match', () => {
    const fitted = jawOf(fitJawToLips(rigOf(JAW), [0, 0.6615, 0.15], [0, 0.661, 0.15]));
    expect(fitted.lipFade).toBeCloseTo(0.0004, 6);
    expect(faces(fitted)[0]).toBeCloseTo(0.6614, 6);
  });

  it("measures along a turned box's own axis", () => {
    const turned: JawMuscle = { ...JAW, rotation: [10, 0, 0] };
    const upper: Vec3 = [0, 0.6622, 0.15];
    const lower: Vec3 = [0, 0.6612, 0.15];
    const fitted = jawOf(fitJawToLips(rigOf(turned), upper, lower));
    const field = new MuscleField(fitted);
    const out = [0, 0, 0];
    // The lower lip's point turns whole, the upper lip's not at all.
    expect(field.displace(1, ...lower, out)).toBeCloseTo(1, 6);
    expect(field.displace(1, ...upper, out)).toBe(0);
  });

  it('leaves the rig as it is where the lips are pressed (no gap)', () => {
    const rig = rigOf(JAW);
    expect(fitJawToLips(rig, [0, 0.661, 0.15], [0, 0.6612, 0.15])).toEqual(rig);
  });
});

// On the stock identities the warp alone put the box's top face off the lips' gap: the lower lip's slit vertex lay
// outside the box on 16 of the 18 medium heads (it stayed behind as the jaw opened, and the lip stretched: its red 1.1
// to 3.9 times its height under AU27), and the upper lip's inside it on the other two (it opened with the jaw).
describe('the jaw carried to each stock identity (medium head)', () => {
  it.each(Object.keys(STOCK_IDENTITIES))('%s: the lower lip turns whole at the slit, the upper lip not at all', (name) => {
    const sim = loadIdentitySimulation(STOCK_IDENTITIES[name], 'medium');
    const rest = sim.host.topology.rest;
    const normals = sim.host.topology.restNormals;
    const mouth = (m: 'mouth-l' | 'mouth-r') => warpPoint(sim.warp, DEFAULT_LANDMARKS[m]);
    const slit = findLipSlit(rest, normals, mouth('mouth-l'), mouth('mouth-r'));
    expect(slit).not.toBeNull();
    const at = (v: number): Vec3 => [rest[3 * v], rest[3 * v + 1], rest[3 * v + 2]];
    const out = [0, 0, 0];
    const carried = new MuscleField(sim.rig.muscles.find((m) => m.type === 'jaw')!);
    expect(carried.displace(1, ...at(slit!.lower), out)).toBeCloseTo(1, 3);
    expect(carried.displace(1, ...at(slit!.upper), out)).toBe(0);
  });
});
