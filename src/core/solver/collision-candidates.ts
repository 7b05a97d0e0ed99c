/**
 * Which skin vertices are checked against which collider (eyes, teeth): chosen once from the rest shape, then listed
 * each time the active region changes, and joined to the region when a moved collider reaches them.
 */
import type { ActiveRegion } from './active-region';
import { COLLIDER_SHAPE, shapeDistance, slabSide, writeColliderShape, type Collider } from './colliders';
import { allocate, allocateCopy, type Memory, type Room } from './memory';
import type { PartArrays } from './part-arrays';
import type { SkinTopology } from './topology';

/** The collision loop's arrays among the part arrays. */
type CandidateArrays =
  | 'colliders'
  | 'colliderShapes'
  | 'colliderVertices'
  | 'colliderClearance'
  | 'colliderSide'
  | 'activeCandidates'
  | 'activeCandidateStart';

/**
 * Skin closer than this to a collider at rest (metres) is checked against it: the lids over the eyes, the lips over
 * the teeth. Farther skin does not reach it in an expression, and checking it would only cost time.
 */
const COLLISION_BAND = 0.006;

/** The collision candidates of a SkinSolver's colliders, and the ones its frames check. */
export class CollisionCandidates {
  readonly colliders: Collider[];
  /** Candidates collider by collider: `colliderVertices[colliderStart[c]..colliderStart[c + 1]]`. */
  readonly colliderStart: Uint32Array;
  readonly colliderVertices: Uint32Array;
  readonly colliderClearance: Float32Array;
  /** Per collision candidate: the side of its slab it lies on at rest (+1 or -1), 0 for spheres and capsules. */
  readonly colliderSide: Int8Array;
  /**
   * The candidates a frame checks, as indices into the lists above, collider by collider (`activeCandidates[
   * activeCandidateStart[c]..activeCandidateStart[c + 1]]`): those in or next to the active region (all without it),
   * as of the last listCandidates. The others are at rest, where no collider reaches them (see joinReachedCandidates).
   */
  readonly activeCandidates: Uint32Array;
  readonly activeCandidateStart: Uint32Array;
  /** Each collider's shape (a, b, up, radius) when the candidates were last checked against it. */
  readonly colliderShapes: Float64Array;
  /** Scratch: candidates a moved collider reaches. */
  private readonly reached: Uint32Array;
  private readonly direction = new Float32Array(3);

  /** The lists a frame's collision loop reads go in `room` while it has room (the kernel memory), else in `memory`. */
  constructor(topology: SkinTopology, colliders: Collider[], memory: Memory, room: Room | null = null) {
    this.colliders = colliders;
    const c = collisionCandidates(topology, colliders);
    this.colliderStart = c.start;
    this.colliderVertices = allocateCopy(c.vertices, memory, room);
    this.colliderClearance = allocateCopy(c.clearance, memory, room);
    this.colliderSide = allocateCopy(c.side, memory, room);
    this.activeCandidates = allocate(Uint32Array, c.vertices.length, memory, room);
    this.activeCandidateStart = allocate(Uint32Array, colliders.length + 1, memory);
    this.reached = new Uint32Array(c.vertices.length);
    this.colliderShapes = allocate(Float64Array, COLLIDER_SHAPE * colliders.length, memory, room);
    for (let k = 0; k < colliders.length; k++) writeColliderShape(colliders[k], this.colliderShapes, k);
  }

  /** The arrays the collision loop reads (see PartArrays). */
  partArrays(): Pick<PartArrays, CandidateArrays> {
    const { colliders, colliderShapes, colliderVertices, colliderClearance, colliderSide, activeCandidates, activeCandidateStart } = this;
    return { colliders, colliderShapes, colliderVertices, colliderClearance, colliderSide, activeCandidates, activeCandidateStart };
  }

  /** Lists the collision candidates a frame checks: those in or next to the region (all of them without it). */
  listCandidates(r: ActiveRegion): void {
    const near = r.shaded;
    const V = this.colliderVertices;
    const list = this.activeCandidates;
    const start = this.activeCandidateStart;
    let count = 0;
    for (let c = 0; c < this.colliders.length; c++) {
      for (let j = this.colliderStart[c]; j < this.colliderStart[c + 1]; j++) if (!r.enabled || near[V[j]] === 1) list[count++] = j;
      start[c + 1] = count;
    }
  }

  /**
   * When the inputs change, a collider may have moved (the lower teeth turn with the jaw; colliders move only with an
   * input change): the candidates outside the region that one which moved now pushes farther than the region's
   * tolerance (`tolerance`) join it, as they would had the frame pushed them (see ActiveRegion.grow). Skin outside
   * the region is at rest, which no collider reaches as long as it is where it was at rest, so the frames check only candidates in
   * or next to the region.
   */
  joinReachedCandidates(r: ActiveRegion, x: Float32Array, tolerance: number): void {
    const dir = this.direction;
    let count = 0;
    for (let c = 0; c < this.colliders.length; c++) {
      const collider = this.colliders[c];
      if (!writeColliderShape(collider, this.colliderShapes, c) || !r.enabled) continue;
      for (let j = this.colliderStart[c]; j < this.colliderStart[c + 1]; j++) {
        const v = this.colliderVertices[j];
        if (r.inside[v] === 1) continue;
        const i = 3 * v;
        const d = shapeDistance(this.colliderShapes, COLLIDER_SHAPE * c, x[i], x[i + 1], x[i + 2], dir, this.colliderSide[j]);
        if (this.colliderClearance[j] - d > tolerance) this.reached[count++] = v;
      }
    }
    r.join(this.reached, count);
  }
}

/**
 * Each vertex within COLLISION_BAND of a collider at rest, outside it, is checked against the nearest one, on the
 * side of it where it lies at rest (a lip in front of the teeth stays in front).
 */
function collisionCandidates(
  topology: SkinTopology,
  colliders: Collider[],
): {
  start: Uint32Array;
  vertices: Uint32Array;
  clearance: Float32Array;
  side: Int8Array;
} {
  const X = topology.rest;
  const n = topology.vertexCount;
  const nearest = new Int32Array(n).fill(-1);
  const distance = new Float32Array(n).fill(Infinity);
  const dir = new Float32Array(3);
  // Each collider's shape written once, not once a vertex as colliderDistance does (a tenth of a second on the fine head).
  const shape = new Float64Array(COLLIDER_SHAPE);
  const box = new Float64Array(6);
  colliders.forEach((c, ci) => {
    writeColliderShape(c, shape, 0);
    // Skin outside the box of the collider's core, widened by its radius and the band, is farther than the band from
    // it, and so no candidate of it whichever collider is nearest: only the skin in the box is measured.
    colliderBox(c, c.radius + COLLISION_BAND, box);
    for (let v = 0; v < n; v++) {
      const x = X[3 * v];
      const y = X[3 * v + 1];
      const z = X[3 * v + 2];
      if (x < box[0] || y < box[1] || z < box[2] || x > box[3] || y > box[4] || z > box[5]) continue;
      const d = shapeDistance(shape, 0, x, y, z, dir, 0);
      if (d < distance[v]) {
        distance[v] = d;
        nearest[v] = ci;
      }
    }
  });
  const start = new Uint32Array(colliders.length + 1);
  const vertices: number[] = [];
  const clearance: number[] = [];
  const side: number[] = [];
  for (let ci = 0; ci < colliders.length; ci++) {
    for (let v = 0; v < n; v++) {
      // Skin inside a collider at rest (the eye socket's lining behind the eyeball) is left alone.
      if (nearest[v] === ci && distance[v] >= 0 && distance[v] < COLLISION_BAND) {
        vertices.push(v);
        clearance.push(Math.min(distance[v], 0.001));
        side.push(slabSide(colliders[ci], X[3 * v], X[3 * v + 1], X[3 * v + 2]));
      }
    }
    start[ci + 1] = vertices.length;
  }
  return { start, vertices: Uint32Array.from(vertices), clearance: Float32Array.from(clearance), side: Int8Array.from(side) };
}

/**
 * The box (min xyz, max xyz) around a collider's core, its point, segment or rectangle, widened by `margin` on every
 * side.
 */
function colliderBox(c: Collider, margin: number, out: Float64Array): void {
  for (let k = 0; k < 3; k++) {
    let lo = c.a[k];
    let hi = lo;
    const corners = [c.b ? c.b[k] : lo, c.up ? c.a[k] + c.up[k] : lo, c.b && c.up ? c.b[k] + c.up[k] : lo];
    for (const value of corners) {
      lo = Math.min(lo, value);
      hi = Math.max(hi, value);
    }
    out[k] = lo - margin;
    out[k + 3] = hi + margin;
  }
}
