/**
 * Starts the skin worker from a copy of its code inside this module, through a Blob URL (no eval): the library build
 * uses this in place of `spawn-skin-worker.ts`, so that a host serves no worker file of its own.
 */
import SkinWorker from '../thread/skin.worker.ts?worker&inline';

export function spawnSkinWorker(): Worker {
  return new SkinWorker({ name: 'softface skin solver' });
}
