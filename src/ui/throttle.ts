/**
 * Runs a refresh at once, or, while `busy` says changes stream in (a timeline playing), at most once per `ms` and
 * once more after the last: a panel that follows a playing timeline redraws a few times a second instead of every
 * frame, reading the face that often, and still ends up showing the last state.
 */
export class Throttle {
  private last = -Infinity;
  private timer: ReturnType<typeof setTimeout> | undefined;
  private readonly later = (): void => {
    this.timer = undefined;
    this.last = performance.now();
    this.run();
  };

  constructor(
    private readonly run: () => void,
    private readonly busy: () => boolean,
    private readonly ms = 100,
  ) {}

  /** Asks for a refresh: now unless busy and the last was less than `ms` ago, else once that time is up. */
  call(): void {
    if (this.timer !== undefined) return;
    const wait = this.last + this.ms - performance.now();
    if (wait > 0 && this.busy()) {
      this.timer = setTimeout(this.later, wait);
      return;
    }
    this.last = performance.now();
    this.run();
  }

  /** Drops a refresh still waiting. */
  dispose(): void {
    clearTimeout(this.timer);
    this.timer = undefined;
  }
}
