/**
 * The board two solver threads share (on a SharedArrayBuffer): the leader posts a job, both threads project their
 * part of the lists (see constraint-lists.ts), and the leader waits until the partner is done (PartnerLink on the
 * leader's side, SolverPartner on the partner's). A job is a few hundred microseconds of work, so each side spins on
 * the board for a while before it sleeps on it.
 */

/**
 * Int32 words: the number of the job posted last (leader), of the job finished last (partner), the job, the part of
 * the lists it is for (for a length job: how many passes), its result; then the barrier's count of arrived threads and its generation (see
 * `meet`); then 1 once the partner takes jobs (see `partnerRunning`).
 */
export const BOARD_SEQUENCE = 0;
export const BOARD_DONE = 1;
export const BOARD_JOB = 2;
export const BOARD_PART = 3;
export const BOARD_RESULT = 4;
const BARRIER_COUNT = 5;
const BARRIER_GENERATION = 6;
export const BOARD_RUNNING = 7;
const BOARD_WORDS = 8;
/** Float64 arguments after the words; after them one Float64 the partner hands back (see Board.value). */
const BOARD_ARGUMENTS = 3;

/**
 * Jobs: length passes (each thread projects half of each colour, and they meet after each colour), a part of the
 * orientation or bending constraints, the second half of the position or collision constraints or of the normals; or
 * leave the job loop.
 */
export const JOB_LENGTHS = 1;
export const JOB_ORIENTATION = 2;
export const JOB_POSITIONS = 3;
export const JOB_COLLISIONS = 4;
export const JOB_STOP = 5;
/** A part of a bending pass: the board's part is the part plus PARTS times the pass. */
export const JOB_BENDING = 6;
/** Half of the normals (see projectNormals): the board's part is the shaded vertices' count. */
export const JOB_NORMALS = 7;
/** The second half of the region's frame start, relaxation or move record: the board's part is the region's count. */
export const JOB_START_FRAME = 8;
export const JOB_RELAX = 9;
/** The move record's result, the largest squared move of the partner's half, goes to the board's value. */
export const JOB_STEPS = 10;
/** Half of a second-ring bending pass (see projectSecondRingPart): the board's part is the region's count. */
export const JOB_SECOND_RING = 11;

/** Board checks before sleeping: about 20 to 50 microseconds of spinning, longer than a part's projection. */
const SPIN_LIMIT = 2000;

/**
 * How long a thread waits for the other within a job before it gives up, in ms. A job takes well under 100 ms even on
 * the densest head, so a thread that has not answered in this time has died (or its worker was ended), and waiting
 * on would hang the solver for good.
 */
export const PARTNER_TIMEOUT_MS = 3000;

/** Thrown when the other solver thread did not answer within a job (see PARTNER_TIMEOUT_MS). */
export class PartnerTimeoutError extends Error {
  constructor(timeoutMs: number) {
    super(`the solver's partner thread did not answer within ${timeoutMs} ms`);
    this.name = 'PartnerTimeoutError';
  }
}

/** The board's views: its words, the job's arguments, and a value the partner hands back. */
export interface Board {
  words: Int32Array;
  args: Float64Array;
  value: Float64Array;
}

/** A new, zeroed board. */
export function createBoard(): Board {
  return boardViews(new SharedArrayBuffer(4 * BOARD_WORDS + 8 * (BOARD_ARGUMENTS + 1)));
}

/** The views of a board's buffer (as received by the partner thread). */
export function boardViews(buffer: SharedArrayBuffer): Board {
  const floats = 4 * BOARD_WORDS;
  return {
    words: new Int32Array(buffer, 0, BOARD_WORDS),
    args: new Float64Array(buffer, floats, BOARD_ARGUMENTS),
    value: new Float64Array(buffer, floats + 8 * BOARD_ARGUMENTS, 1),
  };
}

/** Whether a partner thread takes the board's jobs yet (SolverPartner.run says so as it starts). */
export function partnerRunning(board: Board): boolean {
  return Atomics.load(board.words, BOARD_RUNNING) === 1;
}

/**
 * Returns once `words[index]` is no longer `value`: spins a while, then sleeps until notified; throws a
 * PartnerTimeoutError after `timeoutMs` (by default it waits for good, as an idle partner waits for its next job).
 */
export function waitWhile(words: Int32Array, index: number, value: number, timeoutMs = Infinity): void {
  for (let spin = 0; Atomics.load(words, index) === value; spin++) {
    if (spin < SPIN_LIMIT) continue;
    if (timeoutMs === Infinity) {
      Atomics.wait(words, index, value);
      continue;
    }
    const deadline = performance.now() + timeoutMs;
    while (Atomics.load(words, index) === value) {
      const left = deadline - performance.now();
      if (left <= 0) throw new PartnerTimeoutError(timeoutMs);
      Atomics.wait(words, index, value, left);
    }
    return;
  }
}

/**
 * A barrier for the two threads: returns once both have called it. The second to arrive opens it by bumping the
 * generation, which the first waits on, for at most `timeoutMs` (see waitWhile).
 */
export function meet(words: Int32Array, timeoutMs = PARTNER_TIMEOUT_MS): void {
  const generation = Atomics.load(words, BARRIER_GENERATION);
  if (Atomics.add(words, BARRIER_COUNT, 1) === 1) {
    Atomics.store(words, BARRIER_COUNT, 0);
    Atomics.add(words, BARRIER_GENERATION, 1);
    Atomics.notify(words, BARRIER_GENERATION);
  } else waitWhile(words, BARRIER_GENERATION, generation, timeoutMs);
}
