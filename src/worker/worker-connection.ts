import type { FromWorker, InitMessage, ReadyMessage, ToWorker } from './protocol';
import { spawnSkinWorker } from './spawn-skin-worker';

/** The skin worker, started and initialised: its messages, its failure if any, and its end. */
export class WorkerConnection {
  /** Called with each frame buffer the worker sends (`transfer` mode). */
  onFrame: ((buffer: ArrayBuffer) => void) | undefined;
  private failed: Error | undefined;
  private readonly onMessage = (event: MessageEvent<FromWorker>): void => {
    const m = event.data;
    if (m.type === 'frame') this.onFrame?.(m.buffer);
    else if (m.type === 'error') this.fail(new Error(`the skin solver failed: ${m.message}`));
  };
  private readonly onError = (event: ErrorEvent): void => {
    event.preventDefault();
    this.fail(new Error(`the skin worker failed: ${event.message || 'it could not be loaded'}`));
  };

  private constructor(private readonly worker: Worker) {
    worker.addEventListener('message', this.onMessage);
    worker.addEventListener('error', this.onError);
  }

  /** Starts a worker and resolves once it has built the skin and written its first frame. */
  static start(init: InitMessage): Promise<{ connection: WorkerConnection; ready: ReadyMessage }> {
    const worker = spawnSkinWorker();
    return new Promise((resolve, reject) => {
      const finish = (outcome: () => void): void => {
        worker.removeEventListener('message', onMessage);
        worker.removeEventListener('error', onError);
        outcome();
      };
      const onMessage = (event: MessageEvent<FromWorker>): void => {
        const m = event.data;
        if (m.type === 'ready') finish(() => resolve({ connection: new WorkerConnection(worker), ready: m }));
        else if (m.type === 'error') finish(() => (worker.terminate(), reject(new Error(`the skin solver could not start: ${m.message}`))));
      };
      const onError = (event: ErrorEvent): void => {
        event.preventDefault();
        finish(() => (worker.terminate(), reject(new Error(`the skin worker could not start: ${event.message || 'it could not be loaded'}`))));
      };
      worker.addEventListener('message', onMessage);
      worker.addEventListener('error', onError);
      worker.postMessage(init);
    });
  }

  post(message: ToWorker, transfer: Transferable[] = []): void {
    this.worker.postMessage(message, { transfer });
  }

  failure(): Error | undefined {
    return this.failed;
  }

  /** Stops the worker and removes every listener. */
  dispose(): void {
    this.worker.removeEventListener('message', this.onMessage);
    this.worker.removeEventListener('error', this.onError);
    this.onFrame = undefined;
    this.worker.terminate();
  }

  private fail(error: Error): void {
    if (this.failed) return;
    this.failed = error;
    console.error(error);
  }
}
