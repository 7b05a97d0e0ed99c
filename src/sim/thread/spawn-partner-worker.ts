/** Starts the solver's partner worker from its own module file, beside this one (the skin worker calls it). */
export function spawnPartnerWorker(): Worker {
  return new Worker(new URL('./partner.worker.ts', import.meta.url), { type: 'module', name: 'softface skin solver partner' });
}
