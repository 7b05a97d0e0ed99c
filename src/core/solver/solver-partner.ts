import {
  BOARD_DONE,
  BOARD_JOB,
  BOARD_PART,
  BOARD_RESULT,
  BOARD_RUNNING,
  BOARD_SEQUENCE,
  JOB_BENDING,
  JOB_COLLISIONS,
  JOB_LENGTHS,
  JOB_NORMALS,
  JOB_ORIENTATION,
  JOB_POSITIONS,
  JOB_RELAX,
  JOB_SECOND_RING,
  JOB_START_FRAME,
  JOB_STEPS,
  JOB_STOP,
  waitWhile,
  type Board,
} from './partner-board';
import { PARTS } from './constraint-lists';
import { recordStepsPart, relaxPart, startFramePart } from './frame-kernels';
import { projectLengths } from './length-kernels';
import { projectSecondRingPart } from './second-ring';
import { projectOrientationPart } from './orientation-kernel';
import type { PartArrays } from './part-arrays';
import { projectBendingPart, projectCollisions, projectNormals, projectPositions } from './solver-kernels';

/** Which share of a job `runShare` runs: all of it (no partner), the leader's, or the partner's. */
export const ALONE = -1;
export const LEADER = 0;
const PARTNER = 1;

/**
 * Runs one thread's share of a job that splits the region's vertices, a collider's candidates or a length pass's
 * colours in two (every job but the orientation and bending passes, which go part by part): the leader's half, the
 * partner's, or, `ALONE`, all of it. `count` is the region's vertex count (the length passes for JOB_LENGTHS); `a`,
 * `b`, `c` the job's arguments; `words` the board's words when two threads share the job (the length and normal
 * passes meet at its barrier between colours), else null. Returns the largest squared move for JOB_STEPS, else 0.
 * The leader (SkinSolver) and the partner thread call this same function, so both split every job alike.
 */
export function runShare(
  arrays: PartArrays,
  job: number,
  count: number,
  a: number,
  b: number,
  c: number,
  side: number,
  words: Int32Array | null,
  direction: Float32Array,
): number {
  const from = side === PARTNER ? count >> 1 : 0;
  const to = side === LEADER ? count >> 1 : count;
  const thread = side === PARTNER ? 1 : 0;
  switch (job) {
    case JOB_LENGTHS:
      for (let pass = 0; pass < count; pass++) projectLengths(arrays, a, b, c, words, thread);
      return 0;
    case JOB_POSITIONS:
      projectPositions(arrays, a, b, c, from, to);
      return 0;
    case JOB_COLLISIONS:
      projectCollisions(arrays, thread, side === ALONE ? 1 : 2, direction);
      return 0;
    case JOB_NORMALS:
      projectNormals(arrays, count, words, thread);
      return 0;
    case JOB_SECOND_RING:
      projectSecondRingPart(arrays, from, to, words);
      return 0;
    case JOB_START_FRAME:
      startFramePart(arrays, a, b, from, to);
      return 0;
    case JOB_RELAX:
      relaxPart(arrays, a, from, to);
      return 0;
    case JOB_STEPS:
      return recordStepsPart(arrays, from, to);
    default:
      throw new Error(`runShare: job ${job} is not split by vertices`);
  }
}

/**
 * The partner thread's side of a two-thread solver: whenever the leader's SkinSolver posts a job on the board, it
 * takes the second half of each colour of a length pass, of the region's position and muscle constraints, of each
 * collider's candidates, of the normals or of the frame's start, relaxation or record of the moves, or the odd part of
 * an orientation or bending pass (see constraint-lists.ts), while the leader takes the rest. The arrays are the leader's own, on shared
 * memory (SkinSolver.partArrays).
 */
export class SolverPartner {
  private readonly direction = new Float32Array(3);

  constructor(
    private readonly arrays: PartArrays,
    private readonly board: Board,
  ) {}

  /** Runs jobs until told to stop; blocks the thread meanwhile (the thread does nothing else). */
  run(): void {
    const words = this.board.words;
    const args = this.board.args;
    let done = Atomics.load(words, BOARD_DONE);
    Atomics.store(words, BOARD_RUNNING, 1);
    for (;;) {
      waitWhile(words, BOARD_SEQUENCE, done);
      const sequence = Atomics.load(words, BOARD_SEQUENCE);
      const job = Atomics.load(words, BOARD_JOB);
      const part = Atomics.load(words, BOARD_PART);
      if (job === JOB_STOP) return;
      let result = 0;
      if (job === JOB_ORIENTATION) result = projectOrientationPart(this.arrays, part, args[0], args[1]) ? 1 : 0;
      else if (job === JOB_BENDING) projectBendingPart(this.arrays, Math.floor(part / PARTS), part % PARTS);
      else if (job === JOB_STEPS) this.board.value[0] = runShare(this.arrays, job, part, 0, 0, 0, PARTNER, words, this.direction);
      else runShare(this.arrays, job, part, args[0], args[1], args[2], PARTNER, words, this.direction);
      Atomics.store(words, BOARD_RESULT, result);
      done = sequence;
      Atomics.store(words, BOARD_DONE, done);
      Atomics.notify(words, BOARD_DONE);
    }
  }
}
