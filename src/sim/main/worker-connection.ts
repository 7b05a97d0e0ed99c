import type { FromWorker, InitMessage, ReadyMessage, ToWorker } from '../shared/protocol';

/** The skin worker, started and initialised: its messages, its failure if any, and its end. */
export class WorkerConnection {
  /** Called with each frame buffer the worker sends (`transfer` mode). */
  onFrame: ((buffer: ArrayBuffer) => void) | undefined;
  private failed: Error | undefined;
  /** Runs asked for and not answered yet, by id. */
  private readonly runs = new Map<number, { resolve: (frames: number) => void; reject: (error: Error) => void }>();
  private runId = 0;
  private readonly onMessage = (event: MessageEvent<FromWorker>): void => {
    const m = event.data;
    if (m.type === 'frame') this.onFrame?.(m.buffer);
    else if (m.type === 'ran') {
      this.runs.get(m.id)?.resolve(m.frames);
      this.runs.delete(m.id);
    } else if (m.type === 'error') this.fail(new Error(`the skin solver failed: ${m.message}`));
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
  static async start(init: InitMessage): Promise<{ connection: WorkerConnection; ready: ReadyMessage }> {
    // Imported here, not at the top: in the library build the worker's code (inlined there) is a chunk of its own,
    // fetched beside the head, so that the entry carries only the page's side.
    const { spawnSkinWorker } = await import('./spawn-skin-worker');
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
        else if (m.type === 'error')
          finish(() => {
            worker.terminate();
            reject(new Error(`the skin solver could not start: ${m.message}`));
          });
      };
      const onError = (event: ErrorEvent): void => {
        event.preventDefault();
        finish(() => {
          worker.terminate();
          reject(new Error(`the skin worker could not start: ${event.message || 'it could not be loaded'}`));
        });
      };
      worker.addEventListener('message', onMessage);
      worker.addEventListener('error', onError);
      worker.postMessage(init);
    });
  }

  post(message: ToWorker, transfer: Transferable[] = []): void {
    this.worker.postMessage(message, { transfer });
  }

  /** Asks the worker for a run (see RunMessage); resolves to its frame count, rejects if the worker fails first. */
  run(seq: number, frames: number): Promise<number> {
    if (this.failed) return Promise.reject(this.failed);
    const id = ++this.runId;
    return new Promise((resolve, reject) => {
      this.runs.set(id, { resolve, reject });
      this.post({ type: 'run', id, seq, frames });
    });
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
    this.rejectRuns(new Error('the skin simulation was disposed'));
  }

  private fail(error: Error): void {
    if (this.failed) return;
    this.failed = error;
    console.error(error);
    this.rejectRuns(error);
  }

  private rejectRuns(error: Error): void {
    for (const run of this.runs.values()) run.reject(error);
    this.runs.clear();
  }
}
