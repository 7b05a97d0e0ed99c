/**
 * The skin solver's partner worker (`shared` mode with two workers): started by the skin worker, it projects the
 * second half of each position, length, orientation, bending and collision pass while the skin worker projects the
 * first (see SolverPartner). It says `running` once it waits for jobs; the skin worker hands it work only from then on.
 */
import { boardViews } from '../../core/solver/partner-board';
import type { PartArrays } from '../../core/solver/part-arrays';
import { SolverPartner } from '../../core/solver/solver-partner';

/** Skin worker to partner worker: the solver's shared arrays and the board. */
export interface PartnerInit {
  arrays: PartArrays;
  board: SharedArrayBuffer;
}

const scope = self as unknown as DedicatedWorkerGlobalScope;

scope.addEventListener('message', (event: MessageEvent<PartnerInit>) => {
  const partner = new SolverPartner(event.data.arrays, boardViews(event.data.board));
  scope.postMessage('running');
  partner.run();
});
