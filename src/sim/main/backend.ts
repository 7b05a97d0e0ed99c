import type { ChangedInputs } from './input-staging';
import type { FrameSlot } from '../shared/layout';
import type { RigEdit, SolverClock, SolverMode } from '../shared/protocol';

/** How SkinSimulation reaches a solver: where it runs, how inputs get there and how frames come back. */
export interface SolverBackend {
  readonly mode: SolverMode;
  /** The newest complete frame; the same object until a newer frame arrives. Allocates nothing. */
  latest(): FrameSlot;
  /** Delivers a published input batch (`transfer` mode sends it; the other modes read the control block). */
  publish(seq: number, changed: ChangedInputs): void;
  /** Hands a rig edit to the solver (a message to the worker; `main` mode applies it at once). */
  editRig(revision: number, edit: RigEdit): void;
  /** Solves on the calling thread for up to `budgetMs` (`main` mode); the worker modes do nothing here. */
  advance(budgetMs: number): void;
  /** Paces the solver: `free` solves while the skin is awake, `stepped` only the frames `run` asks for. */
  setClock(clock: SolverClock): void;
  /**
   * Once input batch `seq` is applied, solves `frames` frames (fewer if the skin falls asleep) and makes the last one
   * the newest; resolves to the frames solved since creation.
   */
  run(seq: number, frames: number): Promise<number>;
  /** Why the solver stopped, if it failed. */
  failure(): Error | undefined;
  dispose(): void;
}
