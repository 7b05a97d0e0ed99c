/**
 * An undo/redo history of whole states (rigs are small: the default one is about 20 kB), with transactions so that a
 * drag of many small edits counts as one step. Pure: it stores what it is given and never looks inside.
 */
export class EditHistory<T> {
  private readonly past: T[] = [];
  private readonly future: T[] = [];
  /** The state before the open transaction; undefined when none is open. */
  private opened: T | undefined;
  private depth = 0;
  /** Whether the open transaction recorded an edit. */
  private edited = false;

  /** `limit` is the most steps kept: the oldest are dropped past it. */
  constructor(readonly limit = 200) {
    if (!Number.isInteger(limit) || limit < 1) throw new Error(`EditHistory: limit must be a whole number of at least 1, got ${limit}`);
  }

  /** Records that `before` was replaced by an edit: one step, or part of the open transaction's step. Clears redo. */
  record(before: T): void {
    this.future.length = 0;
    if (this.depth > 0) {
      this.edited = true;
      return;
    }
    this.push(before);
  }

  /** Opens a transaction (they nest): the edits until the matching `end` make one step, whose undo goes back to `current`. */
  begin(current: T): void {
    if (this.depth++ === 0) {
      this.opened = current;
      this.edited = false;
    }
  }

  /** Closes a transaction; the outermost one becomes a step if it recorded any edit. */
  end(): void {
    if (this.depth === 0) throw new Error('EditHistory: end() without begin()');
    if (--this.depth > 0) return;
    if (this.edited) this.push(this.opened as T);
    this.opened = undefined;
    this.edited = false;
  }

  /** Whether a transaction is open. */
  get inTransaction(): boolean {
    return this.depth > 0;
  }

  get canUndo(): boolean {
    return this.depth === 0 && this.past.length > 0;
  }

  get canRedo(): boolean {
    return this.depth === 0 && this.future.length > 0;
  }

  /** Steps that can be undone and redone now. */
  get sizes(): { undo: number; redo: number } {
    return { undo: this.past.length, redo: this.future.length };
  }

  /** The state before the last step, given the state now (kept for redo); undefined if there is none. */
  undo(current: T): T | undefined {
    if (!this.canUndo) return undefined;
    this.future.push(current);
    return this.past.pop();
  }

  /** The state the last undo left, given the state now (kept for undo); undefined if there is none. */
  redo(current: T): T | undefined {
    if (!this.canRedo) return undefined;
    this.past.push(current);
    return this.future.pop();
  }

  /** Forgets every step (a new document). */
  clear(): void {
    this.past.length = 0;
    this.future.length = 0;
  }

  private push(before: T): void {
    this.past.push(before);
    if (this.past.length > this.limit) this.past.splice(0, this.past.length - this.limit);
  }
}
