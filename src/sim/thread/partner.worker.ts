/**
 * The skin solver's partner worker (`shared` mode with two workers): started by the skin worker, it projects the
 * second half of each position, length, orientation, bending and collision pass while the skin worker projects the
 * first (see SolverPartner). It takes one solver's arrays after another: the warm-up's throwaway solver first (see
 * SolverHost.warmUp), then the host's; after each it answers with the init's `id` once it waits for jobs.
 */
import { boardViews } from '../../core/solver/partner-board';
import type { PartArrays } from '../../core/solver/part-arrays';
import { SolverPartner } from '../../core/solver/solver-partner';

/** Skin worker to partner worker: which solver, its shared arrays and the board. */
export interface PartnerInit {
  id: 'warm-up' | 'solver';
  arrays: PartArrays;
  board: SharedArrayBuffer;
}

const scope = self as unknown as DedicatedWorkerGlobalScope;

// run() blocks until its solver sends the stop job; the next init waits in the queue until then.
scope.addEventListener('message', (event: MessageEvent<PartnerInit>) => {
  const partner = new SolverPartner(event.data.arrays, boardViews(event.data.board));
  scope.postMessage(event.data.id);
  partner.run();
});
