import { describe, expect, it } from 'vitest';
import { PARTS } from '../src/core/solver/constraint-lists';
import { SkinSolver } from '../src/core/solver/solver';
import { ORIENT_FULL, ORIENT_WATCH, ORIENT_WATCHED, projectOrientationPart } from '../src/core/solver/orientation-kernel';
import type { PartArrays } from '../src/core/solver/part-arrays';
import { buildTopology } from '../src/core/solver/topology';
import { triangleGrid } from './fixtures/grids';

/** A 1 x 1 cm sheet at 1 mm spacing, every triangle listed; its orientation arrays as the passes see them. */
function sheet(): { parts: PartArrays; listed: number; rest: Float32Array } {
  const g = triangleGrid(0.01, 0.01, 0.001);
  const t = buildTopology(g.positions, g.indices);
  const solver = new SkinSolver(t, { activeRegion: false, memory: 'shared' });
  const parts = solver.partArrays();
  return { parts, listed: parts.triangles.parts[PARTS], rest: t.rest };
}

/** Twice the listed triangle's area along its rest normal, over its bound (1: at the bound). */
function boundShare(a: PartArrays, t: number): number {
  const x = a.positions;
  const [i, j, k] = a.triangles.corners.subarray(3 * t, 3 * t + 3);
  const F = a.triangles.frames;
  const u = [x[j] - x[i], x[j + 1] - x[i + 1], x[j + 2] - x[i + 2]];
  const v = [x[k] - x[i], x[k + 1] - x[i + 1], x[k + 2] - x[i + 2]];
  const area =
    F[4 * t] * (u[1] * v[2] - u[2] * v[1]) + F[4 * t + 1] * (u[2] * v[0] - u[0] * v[2]) + F[4 * t + 2] * (u[0] * v[1] - u[1] * v[0]);
  return area / F[4 * t + 3];
}

/** Slides the vertex nearest (x, y) by dx along the sheet, squeezing the triangles on that side. */
function squeeze(a: PartArrays, rest: Float32Array, x: number, y: number, dx: number): number {
  let best = 0;
  for (let v = 1; v < rest.length / 3; v++) {
    if (Math.hypot(rest[3 * v] - x, rest[3 * v + 1] - y) < Math.hypot(rest[3 * best] - x, rest[3 * best + 1] - y)) best = v;
  }
  a.positions[3 * best] += dx;
  return best;
}

/** The listed triangles with a corner at vertex v. */
function trianglesOf(a: PartArrays, listed: number, v: number): number[] {
  const out: number[] = [];
  for (let t = 0; t < listed; t++) if ([0, 1, 2].some((c) => a.triangles.corners[3 * t + c] === 3 * v)) out.push(t);
  return out;
}

function passAll(a: PartArrays, mode: number): void {
  for (let p = 0; p < PARTS; p++) projectOrientationPart(a, p, mode);
}

describe('watched orientation passes', () => {
  it('a full pass watches the triangles under ORIENT_WATCH times their bound, and only those', () => {
    const { parts, listed, rest } = sheet();
    // One vertex slid 0.8 mm squeezes its triangles under their bound, one 0.7 mm only near it (1.2 times it).
    squeeze(parts, rest, -0.003, 0, 0.0008);
    squeeze(parts, rest, 0.003, 0, 0.0007);
    const expected: number[] = [];
    for (let t = 0; t < listed; t++) if (boundShare(parts, t) < ORIENT_WATCH) expected.push(t);
    expect(expected.some((t) => boundShare(parts, t) < 1)).toBe(true);
    expect(expected.some((t) => boundShare(parts, t) >= 1)).toBe(true);
    parts.watched.fill(0);
    passAll(parts, ORIENT_FULL);
    const watched: number[] = [];
    for (let t = 0; t < listed; t++) if (parts.watched[t] === 1) watched.push(t);
    expect(watched).toEqual(expected);
  });

  it('a watched pass corrects the watched triangles and leaves the others as they are', () => {
    const { parts, listed, rest } = sheet();
    // Two squeezed vertices 6 mm apart: correcting one's triangles moves nothing of the other's.
    const a = squeeze(parts, rest, -0.003, 0, 0.0009);
    const b = squeeze(parts, rest, 0.003, 0, 0.0009);
    const underA = trianglesOf(parts, listed, a).filter((t) => boundShare(parts, t) < 0.99);
    const underB = trianglesOf(parts, listed, b).filter((t) => boundShare(parts, t) < 0.99);
    expect(underA.length).toBeGreaterThan(0);
    expect(underB.length).toBeGreaterThan(0);
    parts.watched.fill(0);
    for (const t of underA) parts.watched[t] = 1;
    const before = underB.map((t) => boundShare(parts, t));
    passAll(parts, ORIENT_WATCHED);
    for (const t of underA) expect(boundShare(parts, t)).toBeGreaterThan(0.99);
    expect(underB.map((t) => boundShare(parts, t))).toEqual(before);
  });
});

describe('the watched set across inputs', () => {
  /**
   * A sheet whose left half (x <= 0) is pulled toward its right part (x >= 1 mm), which is held at rest: the strip
   * between is squeezed toward its orientation bound. `pull(dx)` sets the left half's targets dx along x.
   */
  function pulled(): { solver: SkinSolver; parts: PartArrays; pull: (dx: number) => void } {
    const g = triangleGrid(0.01, 0.01, 0.001);
    const t = buildTopology(g.positions, g.indices);
    const solver = new SkinSolver(t, { activeRegion: false, memory: 'shared' });
    const all = [...Array(t.vertexCount).keys()];
    const at = (vertices: number[], dx: number): number[] =>
      vertices.flatMap((v) => [t.rest[3 * v] + dx, t.rest[3 * v + 1], t.rest[3 * v + 2]]);
    const left = all.filter((v) => t.rest[3 * v] < 1e-5);
    const right = all.filter((v) => t.rest[3 * v] > 0.001 - 1e-5);
    solver.setMuscleTargets(right, at(right, 0), 1);
    const pull = (dx: number): void => solver.setMuscleTargets(left, at(left, dx), 1);
    return { solver, parts: solver.partArrays(), pull };
  }
  const count = (flags: Uint8Array): number => flags.reduce((n, f) => n + f, 0);

  it('an input while the skin moves (a slider dragged) keeps the watched triangles', () => {
    const { solver, parts, pull } = pulled();
    pull(0.0015);
    for (let f = 0; f < 3; f++) solver.step();
    expect(solver.sleeping).toBe(false);
    const watched = Uint8Array.from(parts.watched);
    expect(count(watched)).toBeGreaterThan(0);
    pull(0.0016);
    expect(Array.from(parts.watched)).toEqual(Array.from(watched));
    solver.step();
    // The set only grows within the drag.
    for (let t = 0; t < watched.length; t++) if (watched[t] === 1) expect(parts.watched[t]).toBe(1);
  });

  it('an input once the skin sleeps watches anew', () => {
    const { solver, parts, pull } = pulled();
    pull(0.0015);
    for (let f = 0; f < 2000 && !solver.sleeping; f++) solver.step();
    expect(solver.sleeping).toBe(true);
    expect(count(parts.watched)).toBeGreaterThan(0);
    pull(0.0016);
    expect(count(parts.watched)).toBe(0);
  });
});
