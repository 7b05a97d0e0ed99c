import {
  BOARD_DONE,
  BOARD_JOB,
  BOARD_PART,
  BOARD_RESULT,
  BOARD_SEQUENCE,
  JOB_BENDING,
  JOB_COLLISIONS,
  JOB_LENGTHS,
  JOB_NORMALS,
  JOB_ORIENTATION,
  JOB_POSITIONS,
  JOB_RELAX,
  JOB_START_FRAME,
  JOB_STEPS,
  JOB_STOP,
  waitWhile,
  type Board,
} from './partner-board';
import { PARTS } from './constraint-lists';
import {
  projectBendingPart,
  projectCollisions,
  projectLengths,
  projectNormals,
  projectOrientationPart,
  projectPositions,
  recordStepsPart,
  relaxPart,
  startFramePart,
  type PartArrays,
} from './solver-kernels';

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
    for (;;) {
      waitWhile(words, BOARD_SEQUENCE, done);
      const sequence = Atomics.load(words, BOARD_SEQUENCE);
      const job = Atomics.load(words, BOARD_JOB);
      const part = Atomics.load(words, BOARD_PART);
      if (job === JOB_STOP) return;
      let result = 0;
      if (job === JOB_LENGTHS) for (let pass = 0; pass < part; pass++) projectLengths(this.arrays, args[0], args[1], words, 1);
      else if (job === JOB_ORIENTATION) result = projectOrientationPart(this.arrays, part, args[0], args[1]) ? 1 : 0;
      else if (job === JOB_POSITIONS) projectPositions(this.arrays, args[0], args[1], args[2], part >> 1, part);
      else if (job === JOB_COLLISIONS) projectCollisions(this.arrays, 1, 2, this.direction);
      else if (job === JOB_BENDING) projectBendingPart(this.arrays, Math.floor(part / PARTS), part % PARTS);
      else if (job === JOB_NORMALS) projectNormals(this.arrays, part, words, 1);
      else if (job === JOB_START_FRAME) startFramePart(this.arrays, args[0], args[1], part >> 1, part);
      else if (job === JOB_RELAX) relaxPart(this.arrays, args[0], part >> 1, part);
      else if (job === JOB_STEPS) this.board.value[0] = recordStepsPart(this.arrays, part >> 1, part);
      Atomics.store(words, BOARD_RESULT, result);
      done = sequence;
      Atomics.store(words, BOARD_DONE, done);
      Atomics.notify(words, BOARD_DONE);
    }
  }
}
