import { execFileSync } from 'node:child_process';
import { describe, expect, it } from 'vitest';
import { mulberry32 } from '../src/core/random';
import { PARTS } from '../src/core/solver/constraint-lists';
import type { Collider } from '../src/core/solver/colliders';
import { KernelMemory } from '../src/core/solver/kernel-memory';
import { ORIENT_AGAIN, ORIENT_FULL, ORIENT_WATCHED, projectOrientationPart } from '../src/core/solver/orientation-kernel';
import { SkinSolver } from '../src/core/solver/solver';
import { createSolverBuffers } from '../src/core/solver/solver-buffers';
import { projectSecondRingPart } from '../src/core/solver/second-ring';
import { projectBendingPart, projectCollisions, projectNormals, projectPositions } from '../src/core/solver/solver-kernels';
import { buildTopology } from '../src/core/solver/topology';
import { recordStepsPart, relaxPart, startFramePart } from '../src/core/solver/frame-kernels';
import { triangleGrid } from './fixtures/grids';
import { loadHeadSimulation } from './fixtures/head-simulation';

type HeadSimulation = Awaited<ReturnType<typeof loadHeadSimulation>>;

// The WebAssembly kernels (wasm-kernels.ts) against the JavaScript loops they stand in for.
const grid = triangleGrid(0.03, 0.03, 0.0015);
const topology = buildTopology(grid.positions, grid.indices);

/** A solver on the patch, its edges projected by the kernel or not, after one frame from a seeded scramble. */
function oneFrame(kernel: boolean): { moved: number; positions: Float32Array; usesKernel: boolean } {
  const buffers = createSolverBuffers(topology, 'local', kernel);
  const random = mulberry32(5);
  // A muscle holds the left half, so that both kinds of edges (free and held) are projected; the patch is squeezed
  // to 0.8 of its width with a seeded relief, so that held edges are compressed and push along their bulge seeds.
  for (let v = 0; v < topology.vertexCount; v++) {
    if (topology.rest[3 * v] < 0) buffers.weights[v] = 0.5;
  }
  const x = buffers.positions;
  for (let i = 0; i < x.length; i++) x[i] = (i % 3 === 0 ? 0.8 : 1) * x[i] + (random() - 0.5) * 0.0003;
  const start = Float32Array.from(x);
  const s = new SkinSolver(topology, { buffers, activeRegion: false, parameters: { momentum: 0, startMomentum: 0, foldMomentum: 0 } });
  s.wake();
  s.step();
  let moved = 0;
  for (let i = 0; i < x.length; i++) moved = Math.max(moved, Math.abs(x[i] - start[i]));
  return { moved, positions: Float32Array.from(x), usesKernel: KernelMemory.of(x) !== null };
}

/** The largest move of the loop's result from `start`, and how many floats the kernel's result has otherwise. */
function compare(byKernel: Float32Array, byLoop: Float32Array, start: Float32Array): { moved: number; differ: number } {
  let moved = 0;
  let differ = 0;
  for (let i = 0; i < byLoop.length; i++) {
    moved = Math.max(moved, Math.abs(byLoop[i] - start[i]));
    if (byKernel[i] !== byLoop[i]) differ++;
  }
  return { moved, differ };
}

/** The high head three frames into happiness, on shared memory (loaded once for the tests that read it). */
let fine: Promise<HeadSimulation> | null = null;
function fineHappiness(): Promise<HeadSimulation> {
  fine ??= loadHeadSimulation('high', {}, { memory: 'shared' }).then((sim) => {
    sim.expression.applyPreset('happiness', 1);
    sim.apply();
    for (let f = 0; f < 3; f++) sim.host.step();
    return sim;
  });
  return fine;
}

describe('WebAssembly kernels', () => {
  it('runs in Node, where the solver keeps its positions in the kernel memory by default', () => {
    expect(oneFrame(true).usesKernel).toBe(true);
    expect(oneFrame(false).usesKernel).toBe(false);
  });

  it('project the edges as the JavaScript loops do, to within single-precision rounding', () => {
    const a = oneFrame(true);
    const b = oneFrame(false);
    let worst = 0;
    for (let i = 0; i < a.positions.length; i++) worst = Math.max(worst, Math.abs(a.positions[i] - b.positions[i]));
    // The frame moves the scrambled skin by a tenth of a millimetre or more; the two differ by float rounding only
    // (the kernel computes in single precision, the loops in double).
    expect(b.moved).toBeGreaterThan(1e-4);
    expect(worst).toBeLessThan(1e-5 * b.moved);
  });

  it('bend the skin as the JavaScript loop does, to the bit', () => {
    const buffers = createSolverBuffers(topology, 'shared');
    const random = mulberry32(9);
    const x = buffers.positions;
    // A seeded relief of a tenth of a millimetre: every vertex's bending constraint is off its rest value.
    for (let i = 2; i < x.length; i += 3) x[i] += (random() - 0.5) * 0.0002;
    const s = new SkinSolver(topology, { buffers, activeRegion: false, memory: 'shared' });
    const kernel = s.partArrays();
    // The same arrays without the kernel memory: projectBendingPart then takes its JavaScript loop.
    const loop = { ...kernel, kernelMemory: null };
    const start = Float32Array.from(x);
    const bend = (a: typeof kernel): Float32Array => {
      x.set(start);
      for (let pass = 0; pass < 3; pass++) for (let part = 0; part < PARTS; part++) projectBendingPart(a, pass, part);
      return Float32Array.from(x);
    };
    const byKernel = bend(kernel);
    const byLoop = bend(loop);
    const { moved, differ } = compare(byKernel, byLoop, start);
    expect(kernel.kernelMemory).not.toBeNull();
    expect(moved).toBeGreaterThan(1e-5);
    expect(differ).toBe(0);
  });

  it('bend the fine head two rings out as the JavaScript loop does, to the bit', async () => {
    const sim = await fineHappiness();
    const kernel = sim.host.solver.partArrays();
    const ring = kernel.secondRing;
    // The same arrays without the kernel memory: the pass then takes its JavaScript loop.
    const loop = { ...kernel, kernelMemory: null };
    const x = kernel.positions;
    const start = Float32Array.from(x);
    const count = sim.host.solver.activeVertexCount;
    const pass = (a: typeof kernel): Float32Array => {
      x.set(start);
      projectSecondRingPart(a, 0, count, null);
      return Float32Array.from(x);
    };
    const byKernel = pass(kernel);
    const byLoop = pass(loop);
    const { moved, differ } = compare(byKernel, byLoop, start);
    expect(ring.active).toBe(true);
    expect(kernel.kernelMemory).not.toBeNull();
    expect(moved).toBeGreaterThan(1e-6);
    expect(differ).toBe(0);
  });

  it('hold the triangles against turning over as the JavaScript loop does, to the bit, in every mode', () => {
    const buffers = createSolverBuffers(topology, 'shared');
    const random = mulberry32(13);
    const x = buffers.positions;
    // Squeezed to a third of its width and shaken: many triangles under their bound, some turned over.
    for (let i = 0; i < x.length; i++) x[i] = (i % 3 === 0 ? 0.33 : 1) * x[i] + (random() - 0.5) * 0.0008;
    const s = new SkinSolver(topology, { buffers, activeRegion: false, memory: 'shared' });
    const kernel = s.partArrays();
    // The same arrays without the kernel memory: the loop runs in JavaScript.
    const loop = { ...kernel, kernelMemory: null };
    const start = Float32Array.from(x);
    const flags = Uint8Array.from(kernel.unchecked);
    const watched = Uint8Array.from(kernel.watched);
    const orient = (a: typeof kernel): { x: Float32Array; unchecked: Uint8Array; watched: Uint8Array; corrected: boolean[] } => {
      x.set(start);
      a.unchecked.set(flags);
      a.watched.set(watched);
      const corrected: boolean[] = [];
      for (const mode of [ORIENT_FULL, ORIENT_AGAIN, ORIENT_WATCHED, ORIENT_AGAIN])
        for (let part = 0; part < PARTS; part++) corrected.push(projectOrientationPart(a, part, mode, 0.5 + 0.1 * part));
      return { x: Float32Array.from(x), unchecked: Uint8Array.from(a.unchecked), watched: Uint8Array.from(a.watched), corrected };
    };
    const byKernel = orient(kernel);
    const byLoop = orient(loop);
    const { moved, differ } = compare(byKernel.x, byLoop.x, start);
    expect(kernel.kernelMemory).not.toBeNull();
    expect(moved).toBeGreaterThan(1e-5);
    expect(byLoop.corrected).toContain(true);
    expect(differ).toBe(0);
    expect(byKernel.corrected).toEqual(byLoop.corrected);
    expect(byKernel.unchecked).toEqual(byLoop.unchecked);
    expect(byKernel.watched).toEqual(byLoop.watched);
  });

  it('pull the skin to rest and to the muscles as the JavaScript loop does, to the bit', () => {
    const buffers = createSolverBuffers(topology, 'shared');
    const random = mulberry32(17);
    const x = buffers.positions;
    // Skin shaken off its rest by up to half a millimetre, sunk in or lifted out; a muscle pulls half the patch.
    for (let i = 0; i < x.length; i++) x[i] += (random() - 0.5) * 0.001;
    for (let v = 0; v < topology.vertexCount; v++) {
      if (topology.rest[3 * v] < 0) continue;
      buffers.weights[v] = 0.6;
      buffers.normalWeights[v] = v % 2 === 0 ? 0.2 : 0;
      for (let k = 3 * v; k < 3 * v + 3; k++) buffers.targets[k] = topology.rest[k] + (random() - 0.5) * 0.002;
    }
    const s = new SkinSolver(topology, { buffers, activeRegion: false, memory: 'shared' });
    const kernel = s.partArrays();
    const loop = { ...kernel, kernelMemory: null };
    const start = Float32Array.from(x);
    const pull = (a: typeof kernel): Float32Array => {
      x.set(start);
      projectPositions(a, 0.05, 0.1, 0.5, 0, s.activeVertexCount);
      return Float32Array.from(x);
    };
    const byKernel = pull(kernel);
    const byLoop = pull(loop);
    const { moved, differ } = compare(byKernel, byLoop, start);
    expect(kernel.kernelMemory).not.toBeNull();
    expect(moved).toBeGreaterThan(1e-5);
    expect(differ).toBe(0);
  });

  it('push the skin out of spheres, capsules and slabs as the JavaScript loop does, to the bit', () => {
    const buffers = createSolverBuffers(topology, 'shared');
    const colliders: Collider[] = [
      { name: 'sphere', a: [-0.008, -0.008, -0.004], radius: 0.003 },
      { name: 'capsule', a: [-0.01, 0.006, -0.003], b: [0.01, 0.006, -0.003], radius: 0.002 },
      // A flat slab under the patch's right half, its face toward the skin: one-sided over its face.
      { name: 'slab', a: [0.002, -0.012, -0.003], b: [0.012, -0.012, -0.003], up: [0, 0.016, 0], radius: 0.001 },
    ];
    const s = new SkinSolver(topology, { buffers, activeRegion: false, memory: 'shared', colliders });
    const kernel = s.partArrays();
    const loop = { ...kernel, collisionKernel: false };
    const random = mulberry32(21);
    const x = buffers.positions;
    // The skin sunk by up to 6 mm and shaken sideways: candidates inside each collider, some through the slab.
    for (let v = 0; v < topology.vertexCount; v++) {
      x[3 * v] += (random() - 0.5) * 0.002;
      x[3 * v + 1] += (random() - 0.5) * 0.002;
      x[3 * v + 2] -= random() * 0.006;
    }
    const start = Float32Array.from(x);
    const direction = new Float32Array(3);
    const push = (a: typeof kernel): Float32Array => {
      x.set(start);
      projectCollisions(a, 0, 1, direction);
      return Float32Array.from(x);
    };
    const byKernel = push(kernel);
    const byLoop = push(loop);
    const { moved, differ } = compare(byKernel, byLoop, start);
    expect(kernel.collisionKernel).toBe(true);
    expect(kernel.activeCandidateStart[colliders.length]).toBeGreaterThan(100);
    expect(moved).toBeGreaterThan(1e-3);
    expect(differ).toBe(0);
  });

  it("add up the fine head's normals as the JavaScript loops do, to the bit", async () => {
    const sim = await fineHappiness();
    const kernel = sim.host.solver.partArrays();
    const loop = { ...kernel, kernelMemory: null };
    // The region's count of the shaded list (which also holds the ring around it): each of them made unit length.
    const count = sim.host.solver.activeVertexCount;
    const shade = (a: typeof kernel): Float32Array => {
      a.normals.fill(0);
      projectNormals(a, count, null, 0);
      return Float32Array.from(a.normals);
    };
    const byKernel = shade(kernel);
    const byLoop = shade(loop);
    const { moved, differ } = compare(byKernel, byLoop, new Float32Array(byLoop.length));
    expect(kernel.kernelMemory).not.toBeNull();
    expect(count).toBeGreaterThan(10_000);
    expect(moved).toBeCloseTo(1, 5);
    expect(differ).toBe(0);
  });

  it("keep the frame's books (momentum, relaxation, moves) as the JavaScript loops do, to the bit", () => {
    const buffers = createSolverBuffers(topology, 'shared');
    const s = new SkinSolver(topology, { buffers, activeRegion: false, memory: 'shared' });
    const kernel = s.partArrays();
    const loop = { ...kernel, kernelMemory: null };
    const random = mulberry32(29);
    const n = topology.vertexCount;
    // A frame's state mid-motion: moved skin, last moves that some of this frame's moves turn back on, shares halved
    // here and there, fresh turns and calm counts of every kind.
    const x = kernel.positions;
    for (let i = 0; i < 3 * n; i++) {
      x[i] += (random() - 0.5) * 0.001;
      kernel.lastStep[i] = (random() - 0.5) * 0.0004;
    }
    for (let v = 0; v < n; v++) {
      kernel.relaxation[v] = [1, 0.5, 0.25, 0.0625][Math.floor(random() * 4)];
      kernel.restart[v] = random() < 0.2 ? 1 : 0;
      kernel.calm[v] = [0, 1, 2, 255][Math.floor(random() * 4)];
      kernel.path[v] = random() * 0.01;
    }
    const arrays = (a: typeof kernel) => [a.positions, a.previous, a.lastStep, a.relaxation, a.restart, a.calm, a.path];
    const start = arrays(kernel).map((array) => array.slice());
    const frame = (a: typeof kernel): { state: ArrayLike<number>[]; largest: number } => {
      arrays(a).forEach((array, k) => array.set(start[k] as never));
      startFramePart(a, 0.6, 0.8, 0, n);
      // The frame's projections move the skin: some vertices back against their last move, which the relaxation sees.
      for (let i = 0; i < 3 * n; i++) x[i] -= 2.5 * a.lastStep[i] * (i % 7 === 0 ? 1 : -0.2);
      relaxPart(a, 0.75, 0, n);
      const largest = recordStepsPart(a, 0, n);
      return { state: arrays(a).map((array) => array.slice()), largest };
    };
    const byKernel = frame(kernel);
    const byLoop = frame(loop);
    expect(kernel.kernelMemory).not.toBeNull();
    expect(byLoop.largest).toBeGreaterThan(1e-8);
    expect(byKernel.largest).toBe(byLoop.largest);
    const moved = compare(byKernel.state[0] as Float32Array, byLoop.state[0] as Float32Array, start[0] as Float32Array).moved;
    expect(moved).toBeGreaterThan(1e-5);
    byLoop.state.forEach((state, k) => expect(Array.from(byKernel.state[k]), `array ${k}`).toEqual(Array.from(state)));
  });

  it('are built from the text in scripts/build-kernels.mjs', () => {
    expect(() => execFileSync(process.execPath, ['scripts/build-kernels.mjs', '--check'], { stdio: 'pipe' })).not.toThrow();
  });
});
