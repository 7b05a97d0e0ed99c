/**
 * Starts the solver's partner worker from a copy of its code inside the skin worker, through a Blob URL (no eval):
 * the library build uses this in place of `spawn-partner-worker.ts`, as it does for the skin worker.
 */
import PartnerWorker from './partner.worker.ts?worker&inline';

export function spawnPartnerWorker(): Worker {
  return new PartnerWorker({ name: 'softface skin solver partner' });
}
