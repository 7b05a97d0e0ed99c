/** The typed arrays a SkinSolver reads and writes, and what it reports of a frame (timings, constraint counts). */
import { KernelMemory } from './kernel-memory';
import { allocate, allocateCopy, type Memory } from './memory';
import type { SkinTopology } from './topology';

/** Typed arrays the solver reads and writes; pass them to place them in shared memory. */
export interface SolverBuffers {
  /** Current positions, xyz per simulation vertex. */
  positions: Float32Array;
  /** Current unit normals. */
  normals: Float32Array;
  /** Muscle target of each vertex, xyz. */
  targets: Float32Array;
  /** Muscle weight of each vertex along the skin's surface, 0..1 (0 on both: no muscle constraint). */
  weights: Float32Array;
  /**
   * Muscle weight of each vertex along its rest normal, 0..1. Muscles that slide skin over the face (linear,
   * sphincter) leave this low so compressed skin is free to fold; rotation muscles (jaw, lids) carry the skin
   * bodily and set it as high as the surface weight.
   */
  normalWeights: Float32Array;
  /**
   * The share of each vertex's hold that muscles carrying the skin bodily give (lids, jaw), 0..1: where the skin turns
   * with them, its triangles' bounds on turning over turn too (see CarriedFrames). 0 for targets set directly.
   */
  turnWeights: Float32Array;
  /**
   * Length each edge (topology order) may reach before it resists stretching: its rest length, or more where folded
   * skin unfolds (above a closing lid, see LidSlack). Read when the muscle inputs change.
   */
  unfoldedLengths: Float32Array;
}

/**
 * Allocates the solver's buffers for a topology, positions at rest (on shared memory if `memory` says so). With
 * `kernel` (the default), the positions, normals and muscle inputs lie in a KernelMemory where the WebAssembly kernels
 * can run, and a SkinSolver on these buffers runs its passes there (see useKernels); without, in JavaScript.
 */
export function createSolverBuffers(topology: SkinTopology, memory: Memory = 'local', kernel = true): SolverBuffers {
  const n = topology.vertexCount;
  const room = kernel ? KernelMemory.forSkin(topology, memory) : null;
  return {
    positions: allocateCopy(topology.rest, memory, room),
    normals: allocateCopy(topology.restNormals, memory, room),
    targets: allocateCopy(topology.rest, memory, room),
    weights: allocate(Float32Array, n, memory, room),
    normalWeights: allocate(Float32Array, n, memory, room),
    turnWeights: allocate(Float32Array, n, memory),
    unfoldedLengths: allocateCopy(topology.restLength, memory),
  };
}

/** Milliseconds spent in each phase of the last solved frame. */
export interface FrameTimings {
  /** Position and muscle constraints. */
  positions: number;
  lengths: number;
  bending: number;
  collisions: number;
  /** Orientation passes, within the outer iterations and at the frame's end. */
  orientation: number;
  normals: number;
  total: number;
}

/** Counts of each constraint type, as the app's outputs show them. */
export interface ConstraintCounts {
  /** Position constraints, which pull each skin vertex back toward its rest position: one per simulation vertex. */
  position: number;
  /** Length constraints, which keep each edge of the skin mesh near its rest length: one per edge. */
  length: number;
  /** Muscle constraints: the simulation vertices a muscle holds now (weight or normal weight above 0). */
  muscle: number;
  /** Bending constraints, which set the wrinkle spacing: one per simulation vertex, 0 when `wrinkleSpacing` is 0. */
  bending: number;
  /**
   * Collision constraints: skin vertices checked against a collider (eyes, teeth), one per vertex and collider near
   * it at rest.
   */
  collision: number;
}
