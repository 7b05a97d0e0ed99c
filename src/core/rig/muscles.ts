/**
 * Muscles (thesis 3.2 and 4.4): the combination of the rig's muscle fields (muscle-fields.ts: Waters' linear and
 * sphincter muscles, the thesis's lid and jaw rotation muscles) into the skin solver's muscle inputs, a target and two
 * weights per vertex (`SolverBuffers.targets/weights/normalWeights`). Pure: no three.js, no DOM.
 */
import type { MuscleInputs } from '../solver/muscle-inputs';
import { brushed, displaceAtFalloff, displaceVertex, reaches, sphereWeight, type TurnCache } from './muscle-fields';
import { JAW, LID, NORMAL_SHARE, packMuscle, STRIDE, TYPE } from './muscle-packing';
import { validateMuscle } from './muscle-validation';
import type { Muscle } from './rig-types';

/** Copies contractions into `out` clamped to 0..1; throws, naming the muscle and changing nothing, if one is not finite. */
function clampContractions(muscles: readonly Muscle[], contractions: ArrayLike<number>, out: Float64Array | Float32Array | number[]): void {
  if (contractions.length !== muscles.length) {
    throw new Error(`contractions: the rig has ${muscles.length} muscles, got ${contractions.length} contractions`);
  }
  for (let m = 0; m < muscles.length; m++) {
    const c = contractions[m];
    if (typeof c !== 'number' || !Number.isFinite(c))
      throw new Error(`muscle ${muscles[m].name}: contraction must be a finite number, got ${String(c)}`);
  }
  for (let m = 0; m < muscles.length; m++) {
    const c = contractions[m];
    out[m] = c < 0 ? 0 : c > 1 ? 1 : c;
  }
}

export interface MuscleRigOptions {
  /** Substeps of the combined contraction (the 2003 improvement the thesis cites); default 8. */
  substeps?: number;
  /**
   * How far outside a muscle's zone (metres) rest vertices still count as its candidates; default 0.005. It changes
   * only the speed: skin that slides farther than this from rest is checked against every active muscle.
   */
  margin?: number;
  /**
   * Contraction over which a muscle's hold on its skin grows from none to its full falloff; default 0.1, 0 holds fully
   * as soon as it contracts. Without it a muscle starting to contract would, in one frame, pin skin that other muscles
   * were moving to a target near rest: the solved skin would jump though no target does.
   */
  holdFadeIn?: number;
}

const MUSCLE_RIG_DEFAULTS: Readonly<Required<MuscleRigOptions>> = { substeps: 8, margin: 0.005, holdFadeIn: 0.1 };

/** How many rest vertices each muscle may move, as the editor and the app's outputs show them. */
export interface MuscleCandidates {
  name: string;
  type: Muscle['type'];
  candidates: number;
}

/**
 * A rig's muscles over one skin: candidates chosen once from rest geometry (so one rig works at every mesh
 * resolution), then `compute()` turns contractions into the solver's targets and weights, allocating nothing.
 */
export class MuscleRig {
  readonly vertexCount: number;
  readonly substeps: number;
  readonly margin: number;
  readonly holdFadeIn: number;
  /** Candidate vertices per muscle, in the rig's muscle order. */
  readonly candidateCounts: Uint32Array;
  /** Muscles with a contraction above 0 in the last compute(). */
  lastActive = 0;
  /** Vertices the last compute() integrated (candidates of an active muscle). */
  lastReached = 0;
  /** Vertices the last compute() gave a muscle constraint (weight above 0). */
  lastHeld = 0;
  /** Farthest any target of the last compute() lies from rest (metres). */
  lastLargestMove = 0;
  private readonly rest: Float32Array;
  private readonly muscleList: Muscle[];
  private readonly packed: Float64Array;
  private readonly candidateLists: Uint32Array[];
  /**
   * Per muscle, per candidate (in candidate order): the falloff its brush's add spheres give at least, and the share
   * of its hold its remove spheres leave; null for a muscle without a brush.
   */
  private readonly brushAdd: (Float32Array | null)[];
  private readonly brushKeep: (Float32Array | null)[];
  /** The same, in the order of `vertexMuscles` (0 and 1 where no brush reaches). */
  private rowAdd: Float32Array = new Float32Array(0);
  private rowKeep: Float32Array = new Float32Array(0);
  /** 1 for a vertex some brush reaches (an add or keep in its row that is not 0 or 1). */
  private rowBrushed: Uint8Array = new Uint8Array(0);
  /** Muscles of vertex v (those it is a candidate of) are `vertexMuscles[vertexMuscleStart[v]..vertexMuscleStart[v+1]]`. */
  private readonly vertexMuscleStart: Uint32Array;
  private vertexMuscles: Uint32Array;
  // Scratch for compute(), allocated once.
  private readonly contraction: Float64Array;
  private readonly stepContraction: Float64Array;
  private readonly holdScale: Float64Array;
  private readonly active: Uint32Array;
  private readonly marked: Uint8Array;
  private readonly reached: Uint32Array;
  private readonly step = new Float64Array(3);
  private readonly turns: TurnCache;
  /** Scratch for place(): one skin's worth of vertex indices. */
  private candidateScratch = new Uint32Array(0);

  /** Throws if the rest positions, a muscle (naming it) or an option is not valid. */
  constructor(rest: Float32Array, muscles: readonly Muscle[], options: MuscleRigOptions = {}) {
    if (rest.length % 3 !== 0) throw new Error(`rest positions: ${rest.length} numbers is not a whole number of xyz triples`);
    for (let i = 0; i < rest.length; i++) {
      if (!Number.isFinite(rest[i]))
        throw new Error(`rest positions: vertex ${Math.floor(i / 3)} has a non-finite coordinate (${rest[i]})`);
    }
    const o = { ...MUSCLE_RIG_DEFAULTS, ...options };
    if (!Number.isInteger(o.substeps) || o.substeps < 1 || o.substeps > 64)
      throw new Error(`substeps must be a whole number from 1 to 64, got ${o.substeps}`);
    if (!Number.isFinite(o.margin) || o.margin < 0)
      throw new Error(`margin must be a finite number of metres, at least 0, got ${o.margin}`);
    if (!Number.isFinite(o.holdFadeIn) || o.holdFadeIn < 0 || o.holdFadeIn > 1)
      throw new Error(`holdFadeIn must be a number from 0 to 1, got ${o.holdFadeIn}`);
    for (const m of muscles) validateMuscle(m);
    this.substeps = o.substeps;
    this.margin = o.margin;
    this.holdFadeIn = o.holdFadeIn;
    this.rest = Float32Array.from(rest);
    const n = rest.length / 3;
    const count = muscles.length;
    this.vertexCount = n;
    this.muscleList = [...muscles];
    this.packed = new Float64Array(count * STRIDE);
    this.candidateLists = new Array<Uint32Array>(count);
    this.brushAdd = new Array<Float32Array | null>(count).fill(null);
    this.brushKeep = new Array<Float32Array | null>(count).fill(null);
    this.candidateCounts = new Uint32Array(count);
    for (let m = 0; m < count; m++) this.place(m, muscles[m]);
    this.vertexMuscleStart = new Uint32Array(n + 1);
    this.vertexMuscles = new Uint32Array(0);
    this.indexByVertex();
    this.contraction = new Float64Array(count);
    this.stepContraction = new Float64Array(count);
    this.holdScale = new Float64Array(count);
    this.active = new Uint32Array(count);
    this.marked = new Uint8Array(n);
    this.reached = new Uint32Array(n);
    this.turns = { vertex: new Int32Array(count), falloff: new Float64Array(count), turn: new Float64Array(2 * count) };
  }

  /** The rig's muscles, in the order contractions are given. */
  get muscles(): readonly Muscle[] {
    return this.muscleList;
  }

  /** Candidate vertices of muscle `index` (a view; do not change it). */
  candidates(index: number): Uint32Array {
    return this.candidateLists[index];
  }

  /** Per-muscle candidate counts with names, for display. */
  candidateReport(): MuscleCandidates[] {
    return this.muscleList.map((m, i) => ({ name: m.name, type: m.type, candidates: this.candidateCounts[i] }));
  }

  /** Replaces muscle `index` (an editor dragging it) and re-chooses its candidates; throws, changing nothing, if invalid. */
  setMuscle(index: number, muscle: Muscle): void {
    if (!Number.isInteger(index) || index < 0 || index >= this.muscleList.length)
      throw new Error(`muscle index ${index} is not one of the ${this.muscleList.length} muscles`);
    validateMuscle(muscle);
    this.place(index, muscle);
    this.indexByVertex();
  }

  /**
   * Writes the solver's muscle inputs for per-muscle contractions (clamped to 0..1; a non-finite one throws, naming
   * its muscle, before anything is written). Returns how many vertices are held. Allocates nothing.
   *
   * The 2003 improvement the thesis cites (Waters muscles acting together): instead of each muscle's full contraction
   * on top of the others, every active muscle moves the skin a 1/substeps share at a time, its field evaluated where
   * the skin is now, so skin that slides out of one zone (or into another) is pulled less (or more) from then on, and
   * gradually. A vertex's weight is the sum of the active muscles' falloffs at rest (capped at 1; each scaled by
   * contraction / holdFadeIn below holdFadeIn); its normal weight sums each falloff times the muscle's normalWeight (1
   * for lid and jaw, which carry the skin bodily). Vertices no active muscle reaches keep weight 0 and target = rest.
   * With `turnWeights` in `out`, each vertex's share of the hold from the lid and jaw muscles goes there too (capped at
   * 1; see SolverBuffers.turnWeights).
   *
   * A vertex is integrated through the muscles it is a candidate of (those within `margin` of it at rest) while it is
   * within `margin` of its rest position, where it cannot be in any other zone, and through every active muscle once
   * it has slid farther: the result is that of asking every muscle everywhere, only faster.
   */
  compute(contractions: ArrayLike<number>, out: MuscleInputs & { turnWeights?: Float32Array }): number {
    const n = this.vertexCount;
    const { targets, weights, normalWeights } = out;
    const turnWeights = out.turnWeights?.length === n ? out.turnWeights : null;
    if (targets.length !== 3 * n || weights.length !== n || normalWeights.length !== n) {
      throw new Error(
        `muscle outputs must hold ${n} vertices (targets ${3 * n}, weights ${n}, ` +
          `normalWeights ${n}), got ${targets.length}, ${weights.length}, ${normalWeights.length}`,
      );
    }
    clampContractions(this.muscleList, contractions, this.contraction);
    const turns = this.turns;
    // The turns found in the last compute were for its contractions.
    turns.vertex.fill(-1);
    const rest = this.rest;
    targets.set(rest);
    weights.fill(0);
    normalWeights.fill(0);
    turnWeights?.fill(0);

    const P = this.packed;
    const S = this.substeps;
    const fadeIn = this.holdFadeIn;
    const stepContraction = this.stepContraction;
    const holdScale = this.holdScale;
    let activeCount = 0;
    for (let m = 0; m < this.muscleList.length; m++) {
      const c = this.contraction[m];
      // A contraction of c / S is a 1/S share of the pull, and of the turn, of the linear and rotation fields alike;
      // 0 marks a muscle that takes no part.
      stepContraction[m] = c / S;
      holdScale[m] = fadeIn > 0 && c < fadeIn ? c / fadeIn : 1;
      if (c > 0) this.active[activeCount++] = m;
    }

    // The vertices some active muscle reaches at rest; no other vertex can move.
    let reachedCount = 0;
    const marked = this.marked;
    const reached = this.reached;
    for (let a = 0; a < activeCount; a++) {
      const list = this.candidateLists[this.active[a]];
      for (let j = 0; j < list.length; j++) {
        const v = list[j];
        if (marked[v] === 0) {
          marked[v] = 1;
          reached[reachedCount++] = v;
        }
      }
    }

    const rowStart = this.vertexMuscleStart;
    const row = this.vertexMuscles;
    const rowAdd = this.rowAdd;
    const rowKeep = this.rowKeep;
    const rowBrushed = this.rowBrushed;
    const step = this.step;
    const marginSquared = this.margin * this.margin;
    let held = 0;
    let largestMoveSquared = 0;
    for (let r = 0; r < reachedCount; r++) {
      const v = reached[r];
      marked[v] = 0;
      const i = 3 * v;
      const j0 = rowStart[v];
      const j1 = rowStart[v + 1];
      let x = rest[i];
      let y = rest[i + 1];
      let z = rest[i + 2];
      let weight = 0;
      let normalWeight = 0;
      // The rotation muscles' share of the hold: the skin they carry bodily (see SolverBuffers.turnWeights).
      let turnWeight = 0;
      for (let k = 0; k < S; k++) {
        let sx = 0;
        let sy = 0;
        let sz = 0;
        const moved = (x - rest[i]) ** 2 + (y - rest[i + 1]) ** 2 + (z - rest[i + 2]) ** 2;
        if (moved <= marginSquared) {
          // Within `margin` of its rest position the skin can only be in the zones of muscles it is a candidate of.
          for (let j = j0; j < j1; j++) {
            const m = row[j];
            const c = stepContraction[m];
            if (c === 0) continue;
            const o = m * STRIDE;
            let falloff = displaceVertex(P, o, m, v, c, x, y, z, step, rest[i], rest[i + 1], rest[i + 2], turns);
            if (rowAdd[j] !== 0 || rowKeep[j] !== 1) {
              falloff = brushed(falloff, rowAdd[j], rowKeep[j]);
              displaceAtFalloff(P, o, c * falloff, x, y, z, step, rest[i], rest[i + 1], rest[i + 2]);
            }
            if (k === 0 && falloff > 0) {
              const hold = falloff * holdScale[m];
              weight += hold;
              normalWeight += hold * P[o + NORMAL_SHARE];
              if (P[o + TYPE] === LID || P[o + TYPE] === JAW) turnWeight += hold;
            }
            sx += step[0];
            sy += step[1];
            sz += step[2];
          }
        } else {
          // Slid farther: it may have entered any zone, so every active muscle is asked (most reject at their bound).
          const anyBrush = rowBrushed[v] === 1;
          for (let a = 0; a < activeCount; a++) {
            const m = this.active[a];
            const falloff = displaceVertex(
              P,
              m * STRIDE,
              m,
              v,
              stepContraction[m],
              x,
              y,
              z,
              step,
              rest[i],
              rest[i + 1],
              rest[i + 2],
              turns,
            );
            // A brush on this vertex for this muscle (found in its row; rows are short) sets the falloff here too.
            for (let j = anyBrush ? j0 : j1; j < j1; j++) {
              if (row[j] !== m) continue;
              if (rowAdd[j] !== 0 || rowKeep[j] !== 1)
                displaceAtFalloff(
                  P,
                  m * STRIDE,
                  stepContraction[m] * brushed(falloff, rowAdd[j], rowKeep[j]),
                  x,
                  y,
                  z,
                  step,
                  rest[i],
                  rest[i + 1],
                  rest[i + 2],
                );
              break;
            }
            sx += step[0];
            sy += step[1];
            sz += step[2];
          }
        }
        // Outside every active zone at rest: nothing moves it, now or later.
        if (k === 0 && weight === 0) break;
        x += sx;
        y += sy;
        z += sz;
      }
      if (weight === 0) continue;
      held++;
      targets[i] = x;
      targets[i + 1] = y;
      targets[i + 2] = z;
      weights[v] = weight < 1 ? weight : 1;
      normalWeights[v] = normalWeight < 1 ? normalWeight : 1;
      if (turnWeights) turnWeights[v] = turnWeight < 1 ? turnWeight : 1;
      const moveSquared = (x - rest[i]) ** 2 + (y - rest[i + 1]) ** 2 + (z - rest[i + 2]) ** 2;
      if (moveSquared > largestMoveSquared) largestMoveSquared = moveSquared;
    }
    this.lastActive = activeCount;
    this.lastReached = reachedCount;
    this.lastHeld = held;
    this.lastLargestMove = Math.sqrt(largestMoveSquared);
    return held;
  }

  /** Lists, per vertex, the muscles it is a candidate of (CSR), so compute() visits only those. */
  private indexByVertex(): void {
    const n = this.vertexCount;
    const start = this.vertexMuscleStart;
    start.fill(0);
    for (const list of this.candidateLists) for (let j = 0; j < list.length; j++) start[list[j] + 1]++;
    for (let v = 0; v < n; v++) start[v + 1] += start[v];
    const muscles = new Uint32Array(start[n]);
    const add = new Float32Array(start[n]);
    const keep = new Float32Array(start[n]).fill(1);
    const fill = start.slice(0, n);
    for (let m = 0; m < this.candidateLists.length; m++) {
      const list = this.candidateLists[m];
      const a = this.brushAdd[m];
      const k = this.brushKeep[m];
      for (let j = 0; j < list.length; j++) {
        const at = fill[list[j]]++;
        muscles[at] = m;
        if (a && k) {
          add[at] = a[j];
          keep[at] = k[j];
        }
      }
    }
    const brushed = new Uint8Array(n);
    for (let v = 0; v < n; v++) for (let j = start[v]; j < start[v + 1]; j++) if (add[j] !== 0 || keep[j] !== 1) brushed[v] = 1;
    this.vertexMuscles = muscles;
    this.rowAdd = add;
    this.rowKeep = keep;
    this.rowBrushed = brushed;
  }

  /** Packs muscle `m` and chooses its candidates from the rest positions. */
  private place(m: number, muscle: Muscle): void {
    const P = this.packed;
    const o = m * STRIDE;
    packMuscle(muscle, P, o);
    const X = this.rest;
    const n = X.length / 3;
    const add = muscle.brush?.add ?? [];
    const remove = muscle.brush?.remove ?? [];
    // Skin in an add sphere is a candidate wherever the muscle's zone is.
    const painted = (x: number, y: number, z: number): number => {
      let w = 0;
      for (const s of add) w = Math.max(w, sphereWeight(s, x, y, z));
      return w;
    };
    const candidate = (v: number): boolean =>
      reaches(P, o, this.margin, X[3 * v], X[3 * v + 1], X[3 * v + 2]) ||
      (add.length > 0 && painted(X[3 * v], X[3 * v + 1], X[3 * v + 2]) > 0);
    // One pass over the skin into scratch, then copied: the test is what costs (the high head's 55 muscles took a
    // quarter of a second when every vertex was tested twice, to count and to list).
    if (this.candidateScratch.length < n) this.candidateScratch = new Uint32Array(n);
    const scratch = this.candidateScratch;
    let count = 0;
    for (let v = 0; v < n; v++) if (candidate(v)) scratch[count++] = v;
    const list = scratch.slice(0, count);
    this.candidateLists[m] = list;
    this.candidateCounts[m] = count;
    this.muscleList[m] = muscle;
    if (add.length === 0 && remove.length === 0) {
      this.brushAdd[m] = null;
      this.brushKeep[m] = null;
      return;
    }
    const a = new Float32Array(count);
    const k = new Float32Array(count).fill(1);
    for (let j = 0; j < count; j++) {
      const v = list[j];
      const [x, y, z] = [X[3 * v], X[3 * v + 1], X[3 * v + 2]];
      if (add.length > 0) a[j] = painted(x, y, z);
      for (const s of remove) k[j] = Math.min(k[j], 1 - sphereWeight(s, x, y, z));
    }
    this.brushAdd[m] = a;
    this.brushKeep[m] = k;
  }
}

/**
 * One-shot form of MuscleRig: builds the rig and computes once (use a MuscleRig to compute every frame). Returns how
 * many vertices are held.
 */
export function computeMuscleTargets(
  rest: Float32Array,
  muscles: readonly Muscle[],
  contractions: ArrayLike<number>,
  out: MuscleInputs,
  options: MuscleRigOptions = {},
): number {
  return new MuscleRig(rest, muscles, options).compute(contractions, out);
}
