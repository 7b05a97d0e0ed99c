/// <reference lib="webworker" />
/**
 * The identity worker: reads the identity source once, then builds the head of each person asked for (MakeHuman's
 * macro targets on the base mesh, cut, subdivided, with eyes and teeth: src/core/head/build/), off the page's thread.
 */
import { buildIdentityHead, identitySkinPositions } from '../../core/head/build/identity-head';
import { readIdentitySource, type IdentitySource } from '../../core/head/build/identity-source';
import { builtHeadBuffers, type FromIdentityWorker, type ToIdentityWorker } from '../shared/identity-protocol';

const scope = self as unknown as DedicatedWorkerGlobalScope;
let source: IdentitySource | undefined;
let base: Float64Array | undefined;

scope.onmessage = (event: MessageEvent<ToIdentityWorker>) => {
  const m = event.data;
  const started = performance.now();
  try {
    if (m.source) {
      source = readIdentitySource(new Uint8Array(m.source));
      base = identitySkinPositions(source, null);
    }
    if (!source || !base) throw new Error('the identity source was not sent');
    const head = buildIdentityHead(source, m.identity, m.level);
    const moved = identitySkinPositions(source, m.identity);
    const reply: FromIdentityWorker = { type: 'built', id: m.id, head, base: base.slice(), moved, ms: performance.now() - started };
    scope.postMessage(reply, { transfer: [...builtHeadBuffers(head), reply.base.buffer, moved.buffer] });
  } catch (error) {
    scope.postMessage({
      type: 'failed',
      id: m.id,
      message: error instanceof Error ? error.message : String(error),
    } satisfies FromIdentityWorker);
  }
};
