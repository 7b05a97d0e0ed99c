import type { HeadLevel } from '../../core/head/head-levels';
import type { Identity } from '../../core/head/identity';
import type { BuiltIdentityMessage, FromIdentityWorker, ToIdentityWorker } from '../shared/identity-protocol';

/** A person's head as the identity worker built it (see BuiltIdentityMessage). */
export type IdentityBuild = Omit<BuiltIdentityMessage, 'type' | 'id'>;

/**
 * Builds heads of people in a worker: `generate()` resolves to the head of an identity at a level. The identity
 * source (the base mesh's head and the macro targets, `models/identity-source.bin`) is fetched on the first call and
 * handed to the worker once; the worker starts then and stays for later calls until `dispose()`.
 */
export class IdentityBuilder {
  private worker: Worker | undefined;
  private disposed = false;
  private sent = false;
  private source: Promise<ArrayBuffer> | undefined;
  private nextId = 0;
  private readonly pending = new Map<number, { resolve: (b: IdentityBuild) => void; reject: (e: Error) => void }>();
  private readonly onMessage = (event: MessageEvent<FromIdentityWorker>): void => {
    const m = event.data;
    const waiting = this.pending.get(m.id);
    if (!waiting) return;
    this.pending.delete(m.id);
    if (m.type === 'built') waiting.resolve({ head: m.head, base: m.base, moved: m.moved, ms: m.ms });
    else waiting.reject(new Error(`the identity's head could not be built: ${m.message}`));
  };
  private readonly onError = (event: ErrorEvent): void => {
    event.preventDefault();
    this.stop(new Error(`the identity worker failed: ${event.message || 'it could not be loaded'}`));
  };

  /** `sourceUrl`: where the identity source is fetched from. */
  constructor(private readonly sourceUrl: string) {}

  /** Builds the head of `identity` (checked already) at `level`. */
  async generate(identity: Identity, level: HeadLevel): Promise<IdentityBuild> {
    this.source ??= this.fetchSource();
    let bytes: ArrayBuffer;
    try {
      bytes = await this.source;
    } catch (error) {
      // A failed fetch is tried again next time.
      this.source = undefined;
      throw error;
    }
    if (!this.worker) {
      // Imported on first use: the library's entry does not carry the builder's code (inlined in the library build).
      const { spawnIdentityWorker } = await import('./spawn-identity-worker');
      if (this.disposed) throw new Error('the identity builder was disposed');
      if (this.worker) return this.generate(identity, level);
      this.worker = spawnIdentityWorker();
      this.worker.addEventListener('message', this.onMessage);
      this.worker.addEventListener('error', this.onError);
      this.sent = false;
    }
    const id = ++this.nextId;
    const message: ToIdentityWorker = { type: 'build', id, identity, level };
    // The worker keeps the source: it is copied to it once (the page keeps its own copy for a worker started later).
    if (!this.sent) message.source = bytes.slice(0);
    this.sent = true;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject });
      this.worker?.postMessage(message, message.source ? [message.source] : []);
    });
  }

  /** Stops the worker; builds under way are rejected. */
  dispose(): void {
    this.disposed = true;
    this.stop(new Error('the identity builder was disposed'));
  }

  private async fetchSource(): Promise<ArrayBuffer> {
    let response: Response;
    try {
      response = await fetch(this.sourceUrl);
    } catch (error) {
      throw new Error(`${this.sourceUrl}: the identity source could not be fetched (${(error as Error).message})`);
    }
    if (!response.ok)
      throw new Error(`${this.sourceUrl}: the identity source could not be fetched (${response.status} ${response.statusText})`);
    return response.arrayBuffer();
  }

  private stop(reason: Error): void {
    if (this.worker) {
      this.worker.removeEventListener('message', this.onMessage);
      this.worker.removeEventListener('error', this.onError);
      this.worker.terminate();
      this.worker = undefined;
    }
    for (const { reject } of this.pending.values()) reject(reason);
    this.pending.clear();
  }
}
