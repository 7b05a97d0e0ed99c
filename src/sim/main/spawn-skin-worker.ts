/** Starts the skin worker from its own module file, beside this one. */
export function spawnSkinWorker(): Worker {
  return new Worker(new URL('../thread/skin.worker.ts', import.meta.url), { type: 'module', name: 'softface skin solver' });
}
