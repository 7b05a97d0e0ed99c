import {
  BOARD_DONE,
  BOARD_JOB,
  BOARD_PART,
  BOARD_RESULT,
  BOARD_SEQUENCE,
  JOB_STOP,
  PARTNER_TIMEOUT_MS,
  waitWhile,
  type Board,
} from './partner-board';

/** The leader's side of the board (see partner-board.ts): posts a job to the partner thread and waits for its end. */
export class PartnerLink {
  private sequence = 0;

  /** `timeoutMs`: how long finish() waits for the partner before it throws a PartnerTimeoutError. */
  constructor(
    readonly board: Board,
    private readonly timeoutMs = PARTNER_TIMEOUT_MS,
  ) {}

  /** Posts a job on one part of the lists, with up to three arguments; the partner starts at once. */
  start(job: number, part = 0, a = 0, b = 0, c = 0): void {
    const { words, args } = this.board;
    args[0] = a;
    args[1] = b;
    args[2] = c;
    Atomics.store(words, BOARD_JOB, job);
    Atomics.store(words, BOARD_PART, part);
    // The sequence number's store publishes the job and its arguments.
    Atomics.store(words, BOARD_SEQUENCE, ++this.sequence);
    Atomics.notify(words, BOARD_SEQUENCE);
  }

  /** Waits until the posted job is done and returns its result; throws a PartnerTimeoutError if it never is. */
  finish(): number {
    const words = this.board.words;
    waitWhile(words, BOARD_DONE, this.sequence - 1, this.timeoutMs);
    return Atomics.load(words, BOARD_RESULT);
  }

  /** Tells the partner to leave its job loop (it does not wait for that). */
  stop(): void {
    this.start(JOB_STOP);
  }
}
