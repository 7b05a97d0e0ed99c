/**
 * Bending over the ring of vertices two edges out, where the ring of neighbours cannot bend stiffly enough: the fine
 * head's folds at the spacing the skin asks for instead of paper's crumpling (docs/solver-notes.md, "Bending two
 * rings out"). Like the first ring's bending (bending-setup.ts), it carries the wrinkle parameter thesis 3.1.2 wishes
 * for: one spacing of folds at every mesh resolution.
 */
import { BENDING_CALIBRATION } from './bending-setup';
import type { KernelMemory } from './kernel-memory';
import { allocate, allocateCopy, type Memory } from './memory';
import type { PartArrays } from './part-arrays';
import { meet } from './partner-board';
import type { SkinParameters } from './skin-parameters';
import type { SkinTopology } from './topology';
import { wasmKernels } from './wasm-kernels';

/**
 * The most bending share the second ring takes per outer iteration. Each vertex's first ring is already capped at a
 * whole share there, so together they bend the fine head about as stiffly as the head one subdivision coarser bends
 * with its capped first ring (a quarter of the vertices, each with a whole share): its folds' spacing and little
 * grain. At a whole share the fine head's crow's feet came out 12 mm apart and a fifth as deep as the coarser head's.
 */
const SECOND_RING_MAX_SHARE = 0.5;

/**
 * Real wrinkles lie at least this far apart (m). A head whose skin with a capped first ring folds shorter than this
 * at its median by the small-slope balance gets the second ring: the high head (4.7 mm), not the medium head (7.3 mm,
 * whose look, with crow's feet 7.6 mm apart, the rig's expressions were fitted to) nor the low one (8.8 mm).
 */
const SHORTEST_WRINKLES = 0.006;
/**
 * On such a head, the vertices whose capped first ring folds shorter than this by the balance (m) get the second. The
 * balance underrates the capped ring's folds (the medium head's crow's feet, 7.6 mm apart, are capped skin it puts at
 * 5 to 7 mm): at 6 mm the high head crumpled as before (crow's feet 4.3 mm apart), at 9 mm its folds matched the
 * medium head's (47,520 of its 68,277 vertices).
 */
const SHORTEST_FOLD = 0.009;
/**
 * A ring whose rest normals turn further than this from the vertex's (the cosine: 60 degrees) lies over a crease, a
 * lip's or a lid's margin, a nostril: there its mean height measures the surface's turn, not a fold, and the vertex
 * gets no second ring (408 of the high head's vertices). Given one there, the closing lids' edge-on fans at the inner
 * eye corners ended with more triangles turned over (AU43 20 against 3, AU46 33 against 10; docs/solver-notes.md).
 */
const CREASE_COSINE = 0.5;

/** The second-ring stencils (CSR) and what a frame's pass over them reads and writes (see projectSecondRingPart). */
export interface SecondRing {
  /** Each vertex's ring two edges out (not nearer), as xyz offsets: `offsets[start[v]..start[v + 1]]`. */
  start: Uint32Array;
  offsets: Uint32Array;
  /** 1 / the ring's size (0 for none). */
  inverse: Float32Array;
  /**
   * The ring's mean distance over the first ring's, at rest: the spacing the stencil bends at, over the vertex's; 0
   * for no ring or a ring over a crease (see CREASE_COSINE).
   */
  ratio: Float32Array;
  /** The constraint's value at rest, computed as a frame computes it, so that skin at rest stays exactly there. */
  rest: Float64Array;
  /** The step per unit of the constraint (share over the gradient's squared norm, 1 + 1 / ring size); 0 for none. */
  gain: Float32Array;
  /** 1 for a vertex that has a constraint or is in the ring of one that has: the vertices a pass moves. */
  reach: Uint8Array;
  /**
   * At each vertex's xyz offset, its constraint's move of each ring vertex in the current pass (against the vertex's
   * rest normal, the step over the ring's size); 0 outside the region and without a constraint.
   */
  ringMove: Float32Array;
  /** Each vertex's constraint's step in the current pass, which it takes along its rest normal; 0 likewise. */
  ownStep: Float32Array;
  /** Whether any vertex has a constraint: the frames skip the pass when none has (the low and medium heads). */
  active: boolean;
}

/** The second rings' stencils of a topology at rest, in plain memory: what createSecondRing copies. */
type RingStencils = Pick<SecondRing, 'start' | 'offsets' | 'inverse' | 'ratio' | 'rest'>;

/** Each topology's stencils, made once: the kernel memory's size (see KernelMemory) and each solver read them. */
const stencilsOf = new WeakMap<SkinTopology, RingStencils>();

/** The second rings of a topology at rest (made once per topology, about 50 ms for the high head). */
export function ringStencils(topology: SkinTopology): RingStencils {
  const known = stencilsOf.get(topology);
  if (known) return known;
  const made = makeStencils(topology);
  stencilsOf.set(topology, made);
  return made;
}

/**
 * The second rings of a topology at rest, their shares 0 until setSecondRingShares sets them; in `kernel` where it
 * has room (the bending kernel reads them there, see wasm-kernels.ts), else in `memory`.
 */
export function createSecondRing(topology: SkinTopology, memory: Memory, kernel: KernelMemory | null = null): SecondRing {
  const n = topology.vertexCount;
  const s = ringStencils(topology);
  const place = <T extends Float32Array | Float64Array | Uint32Array | Uint8Array>(array: T): T => allocateCopy(array, memory, kernel);
  return {
    start: place(s.start),
    offsets: place(s.offsets),
    inverse: place(s.inverse),
    ratio: s.ratio,
    rest: place(s.rest),
    gain: allocate(Float32Array, n, memory, kernel),
    reach: allocate(Uint8Array, n, memory, kernel),
    ringMove: allocate(Float32Array, 3 * n, memory, kernel),
    ownStep: allocate(Float32Array, n, memory, kernel),
    active: false,
  };
}

/** Finds each vertex's ring two edges out and what the constraint reads of it at rest (see ringStencils). */
function makeStencils(topology: SkinTopology): RingStencils {
  const n = topology.vertexCount;
  const X = topology.rest;
  const N = topology.restNormals;
  const start = topology.neighbourStart;
  const nb = topology.neighbours;
  const ringStart = new Uint32Array(n + 1);
  // At most the sum of the first ring's degrees, each vertex.
  let most = 0;
  for (let v = 0; v < n; v++) for (let j = start[v]; j < start[v + 1]; j++) most += start[nb[j] + 1] - start[nb[j]];
  const found = new Uint32Array(most);
  let count = 0;
  const ratio = new Float32Array(n);
  // Breadth-first two rings out; `mark` holds the last vertex whose search reached each vertex. The distances are
  // written out, not a closure's: the closure took a third of the fine head's stencils' time.
  const mark = new Int32Array(n).fill(-1);
  for (let v = 0; v < n; v++) {
    mark[v] = v;
    const x = X[3 * v];
    const y = X[3 * v + 1];
    const z = X[3 * v + 2];
    let first = 0;
    for (let j = start[v]; j < start[v + 1]; j++) {
      const u = nb[j];
      mark[u] = v;
      const dx = X[3 * u] - x;
      const dy = X[3 * u + 1] - y;
      const dz = X[3 * u + 2] - z;
      first += Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
    const from = count;
    let second = 0;
    let flat = true;
    for (let j = start[v]; j < start[v + 1]; j++) {
      const u = nb[j];
      for (let k = start[u]; k < start[u + 1]; k++) {
        const w = nb[k];
        if (mark[w] === v) continue;
        mark[w] = v;
        found[count++] = 3 * w;
        const dx = X[3 * w] - x;
        const dy = X[3 * w + 1] - y;
        const dz = X[3 * w + 2] - z;
        second += Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (N[3 * v] * N[3 * w] + N[3 * v + 1] * N[3 * w + 1] + N[3 * v + 2] * N[3 * w + 2] < CREASE_COSINE) flat = false;
      }
    }
    const degree1 = start[v + 1] - start[v];
    const degree2 = count - from;
    ratio[v] = flat && degree1 > 0 && degree2 > 0 && first > 0 ? second / degree2 / (first / degree1) : 0;
    ringStart[v + 1] = count;
  }
  const offsets = found.slice(0, count);
  const inverse = new Float32Array(n);
  for (let v = 0; v < n; v++) {
    const size = ringStart[v + 1] - ringStart[v];
    inverse[v] = size > 0 ? 1 / size : 0;
  }
  const rest = new Float64Array(n);
  for (let v = 0; v < n; v++) rest[v] = heightOverRing(X, N, ringStart, offsets, inverse, v, 0);
  return { start: ringStart, offsets, inverse, ratio, rest };
}

/**
 * The ring's mean height above vertex `v` along its rest normal, less `atRest`: the constraint's value. One function
 * for the rest value and the frames, so that both add the same single-precision numbers in the same order.
 */
function heightOverRing(
  x: Float32Array,
  N: Float32Array,
  start: Uint32Array,
  offsets: Uint32Array,
  inverse: Float32Array,
  v: number,
  atRest: number,
): number {
  const i = 3 * v;
  const nx = N[i];
  const ny = N[i + 1];
  const nz = N[i + 2];
  let mean = 0;
  for (let j = start[v]; j < start[v + 1]; j++) {
    const k = offsets[j];
    mean += x[k] * nx + x[k + 1] * ny + x[k + 2] * nz;
  }
  return mean * inverse[v] - (x[i] * nx + x[i + 1] * ny + x[i + 2] * nz) - atRest;
}

/**
 * Sets each vertex's second-ring share for the parameters `next`: on a head whose skin with a capped first ring folds
 * shorter than real wrinkles at its median (SHORTEST_WRINKLES), at each such vertex whose capped ring folds under
 * SHORTEST_FOLD, the share the second ring's spacing asks for, at most SECOND_RING_MAX_SHARE; none elsewhere. Skin at
 * a collider gets it too: there the first ring is capped lower still (COLLIDER_BENDING_STIFFNESS).
 */
export function setSecondRingShares(ring: SecondRing, topology: SkinTopology, next: SkinParameters): void {
  const n = topology.vertexCount;
  const twoPi = 2 * Math.PI;
  const { gain, reach, start, offsets } = ring;
  const c = BENDING_CALIBRATION * next.positionStiffness;
  // Capped at a whole share, the first ring folds at 2 pi h (C s_p)^(-1/4) by the small-slope balance.
  const cappedFold = (h: number): number => twoPi * h * c ** -0.25;
  const capped = (h: number): boolean => next.wrinkleSpacing > 0 && h > 0 && c * (next.wrinkleSpacing / (twoPi * h)) ** 4 > 1;
  // A typed array's numeric sort: a plain array's sort with a comparator took most of this function's time.
  const all = new Float64Array(n);
  let capCount = 0;
  for (let v = 0; v < n; v++) if (capped(topology.spacing[v])) all[capCount++] = cappedFold(topology.spacing[v]);
  const folds = all.subarray(0, capCount).sort();
  const fine = folds.length > 0 && folds[folds.length >> 1] < SHORTEST_WRINKLES;
  gain.fill(0);
  reach.fill(0);
  ring.active = fine;
  if (!fine) return;
  for (let v = 0; v < n; v++) {
    const h = topology.spacing[v];
    if (!capped(h) || ring.ratio[v] === 0 || cappedFold(h) >= SHORTEST_FOLD) continue;
    const second = c * (next.wrinkleSpacing / (twoPi * h * ring.ratio[v])) ** 4;
    gain[v] = Math.min(SECOND_RING_MAX_SHARE, second) / (1 + ring.inverse[v]);
    reach[v] = 1;
    for (let j = start[v]; j < start[v + 1]; j++) reach[offsets[j] / 3] = 1;
  }
}
/**
 * One pass of the second-ring constraints over the region's vertices `regionVertices[from..to]` (this thread's
 * half): each constraint asks for the ring's mean height over the vertex as at rest, moving the vertex along its rest
 * normal and the ring against it, as projectBendingPart does with the first ring. The rings overlap too much to split
 * into parts that share no vertex, so the pass is a Jacobi step in two halves: every constraint's step from the
 * positions as they are, then each vertex gathers its own move from its constraint and those of the rings it is in
 * (the ring relation is symmetric). With a `board`, the two threads meet between the halves; the result is the same
 * on one thread or two. Vertices outside the region are not moved; their steps are 0.
 */
export function projectSecondRingPart(a: PartArrays, from: number, to: number, board: Int32Array | null): void {
  const x = a.positions;
  const N = a.restNormals;
  const V = a.regionVertices;
  const { start, offsets, inverse, rest, gain, reach, ringMove, ownStep } = a.secondRing;
  const kernels = wasmKernels(a);
  if (kernels) {
    // Byte addresses, each read once (no array: this runs every outer iteration).
    const xp = x.byteOffset;
    const np = N.byteOffset;
    const vp = V.byteOffset;
    const sp = start.byteOffset;
    const op = offsets.byteOffset;
    const mp = ringMove.byteOffset;
    const tp = ownStep.byteOffset;
    kernels.ringSteps(xp, np, vp, sp, op, inverse.byteOffset, rest.byteOffset, gain.byteOffset, mp, tp, from, to);
    if (board) meet(board);
    kernels.ringGather(xp, np, vp, sp, op, reach.byteOffset, mp, tp, from, to);
    return;
  }
  for (let k = from; k < to; k++) {
    const v = V[k];
    const g = gain[v];
    const step = g === 0 ? 0 : g * heightOverRing(x, N, start, offsets, inverse, v, rest[v]);
    // Each ring vertex's move, made once here, so that the gather reads three numbers a ring vertex and no normal.
    const i = 3 * v;
    const q = step * inverse[v];
    ringMove[i] = q * N[i];
    ringMove[i + 1] = q * N[i + 1];
    ringMove[i + 2] = q * N[i + 2];
    ownStep[v] = step;
  }
  if (board) meet(board);
  for (let k = from; k < to; k++) {
    const u = V[k];
    if (reach[u] === 0) continue;
    const i = 3 * u;
    const own = ownStep[u];
    let dx = own * N[i];
    let dy = own * N[i + 1];
    let dz = own * N[i + 2];
    for (let j = start[u]; j < start[u + 1]; j++) {
      const o = offsets[j];
      dx -= ringMove[o];
      dy -= ringMove[o + 1];
      dz -= ringMove[o + 2];
    }
    x[i] += dx;
    x[i + 1] += dy;
    x[i + 2] += dz;
  }
}
