/**
 * The arrays the solver's part loops (solver-kernels.ts and the files beside it) read and write: the leader thread's
 * SkinSolver and the partner thread's SolverPartner hold the same shared ones.
 */
import type { Collider } from './colliders';
import type { BendingLists, EdgeLists, TriangleLists } from './constraint-lists';
import type { SecondRing } from './second-ring';

/** What the part loops read and write: the solver's lists and positions, and the topology's fixed arrays. */
export interface PartArrays {
  /** Current positions, xyz per vertex. */
  positions: Float32Array;
  rest: Float32Array;
  restNormals: Float32Array;
  /** The muscle inputs (see SolverBuffers). */
  targets: Float32Array;
  weights: Float32Array;
  normalWeights: Float32Array;
  /** Current unit normals. */
  normals: Float32Array;
  /** The triangles with a corner in `shadedVertices`, part by part as the orientation's. */
  shadedTriangles: TriangleLists;
  /** The topology's neighbours (CSR), as xyz offsets (3 * vertex). */
  neighbourStart: Uint32Array;
  neighbourOffsets: Uint32Array;
  /** The topology's triangles of each vertex (CSR). */
  vertexTriangleStart: Uint32Array;
  vertexTriangles: Uint32Array;
  edges: EdgeLists;
  /**
   * The WebAssembly memory every array the kernels read and write lies in, where the solver's passes run as
   * WebAssembly (see wasm-kernels.ts, useKernels); null: the JavaScript loops.
   */
  kernelMemory: WebAssembly.Memory | null;
  /** The kernels' compiled module for that memory (a partner thread makes its instance from it); null without. */
  kernelModule: WebAssembly.Module | null;
  /**
   * Per vertex, at its xyz offset: the way a compressed held edge pushes it per unit of compression and of muscle
   * weight, its rest normal times its bulge seed (see SkinSolver).
   */
  bulgeDirections: Float32Array;
  triangles: TriangleLists;
  bending: BendingLists;
  /**
   * Per vertex: the bending constraint's value at rest, its step per unit of the constraint (its share per pass over
   * the gradient's squared norm, 1 + 1 / degree; 0 for none) and its passes (see SkinSolver), and 1 / its degree.
   */
  bendRest: Float64Array;
  bendGain: Float32Array;
  bendPasses: Uint8Array;
  inverseDegree: Float32Array;
  /** Bending over the ring two edges out (see second-ring.ts). */
  secondRing: SecondRing;
  /**
   * For orientation passes that follow one another (see projectOrientationPart): 1 for each listed triangle with a
   * corner moved since it was last checked; and each triangle's place in the list (-1 if not listed).
   */
  unchecked: Uint8Array;
  /** The same flags four at a time (`unchecked`'s buffer, whose length is a multiple of 4): a zero word skips four. */
  uncheckedWords: Uint32Array;
  /** 1 for each watched listed triangle (see ORIENT_WATCH), and the same flags four at a time. */
  watched: Uint8Array;
  watchedWords: Uint32Array;
  listedTriangle: Int32Array;
  /** The active region's vertices, ascending (see ActiveRegion). */
  regionVertices: Uint32Array;
  /** The vertices whose normals a frame computes: the region and its ring (see ActiveRegion.shadedVertices). */
  shadedVertices: Uint32Array;
  /** Each vertex's place at the frame's start and its last frame's move (xyz), for the frame's bookkeeping. */
  previous: Float32Array;
  lastStep: Float32Array;
  /** Share of its solved move each vertex takes this frame (see relaxPart). */
  relaxation: Float32Array;
  /** 1 for a vertex whose last move turned back on the one before: it carries no momentum into the next frame. */
  restart: Uint8Array;
  /** Frames since each vertex last turned back, up to 255 (see relaxPart). */
  calm: Uint8Array;
  /** Each vertex's way (the sum of its moves) since Relaxation.breakLoops last looked. */
  path: Float32Array;
  /**
   * The colliders, and their current shapes (`COLLIDER_SHAPE` values each), which the leader updates when an input
   * moves one; the collision loop reads only the shapes, so the partner's copies of the colliders need not follow.
   */
  colliders: Collider[];
  colliderShapes: Float64Array;
  /** Collision candidates: vertex, rest clearance and side of each (see collision-candidates.ts). */
  colliderVertices: Uint32Array;
  colliderClearance: Float32Array;
  colliderSide: Int8Array;
  /** The candidates a frame checks, collider by collider: `activeCandidates[activeCandidateStart[c]..[c + 1]]`. */
  activeCandidates: Uint32Array;
  activeCandidateStart: Uint32Array;
  /** Whether the collisions run as WebAssembly too: the candidates' arrays lie in the kernel memory (see useKernels). */
  collisionKernel: boolean;
}
