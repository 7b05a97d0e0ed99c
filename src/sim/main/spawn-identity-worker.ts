/** Starts the identity worker from its own module file. */
export function spawnIdentityWorker(): Worker {
  return new Worker(new URL('../thread/identity.worker.ts', import.meta.url), { type: 'module', name: 'softface identity builder' });
}
