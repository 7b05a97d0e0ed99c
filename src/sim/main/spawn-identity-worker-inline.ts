/**
 * Starts the identity worker from a copy of its code inside this module, through a Blob URL (no eval): the library
 * build uses this in place of `spawn-identity-worker.ts`, as it does for the skin worker.
 */
import IdentityWorker from '../thread/identity.worker.ts?worker&inline';

export function spawnIdentityWorker(): Worker {
  return new IdentityWorker({ name: 'softface identity builder' });
}
