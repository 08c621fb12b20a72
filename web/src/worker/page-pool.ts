/// <reference lib="webworker" />
/**
 * The page's pool for stage 1, run by the geometry worker: separator workers (separator-worker.ts),
 * each with its own core, the mesh as the geometry worker opened it and the same options, computing
 * the sources lib/core/pool.ts hands them. The pool lives as long as its mesh and options (opening a
 * worker costs about what the geometry worker's own solver does); a worker that fails is dropped, and
 * the next run starts a new one.
 */
import { PooledWorker, startError, type PoolReady, type PoolReply, type PoolRequest, type PoolStart } from '../../../lib/core/pool-worker.ts';
import { CoreError } from '../../../lib/core/types.ts';

/** The owner's side of one separator worker (the page's ThreadWorker). */
export class WebSeparatorWorker extends PooledWorker {
  constructor(private readonly worker: Worker) {
    super();
    worker.addEventListener('message', (event: MessageEvent<PoolReply>) => this.receive(event.data));
    worker.addEventListener('error', (event) => {
      event.preventDefault(); // handled here, not an error of the geometry worker
      this.fail(new CoreError(`a separator worker failed: ${event.message || 'an uncaught error'}`, 'internal'));
    });
    worker.addEventListener('messageerror', () => this.fail(new CoreError('a separator worker sent a message that could not be read', 'internal')));
  }

  protected send(request: PoolRequest): void {
    this.worker.postMessage(request);
  }

  close(): void {
    this.worker.terminate();
    this.fail(new CoreError('a separator worker was stopped', 'internal'));
  }
}

/** Starts a separator worker; resolves once it has opened the mesh and its pipeline. */
function startWorker(start: PoolStart): Promise<WebSeparatorWorker> {
  const worker = new Worker(new URL('./separator-worker.ts', import.meta.url), { type: 'module', name: 'cscd-separator' });
  const starting = new AbortController();
  return new Promise<WebSeparatorWorker>((resolve, reject) => {
    const failed = (error: Error) => {
      worker.terminate();
      reject(error);
    };
    const { signal } = starting;
    worker.addEventListener('message', (event: MessageEvent<PoolReady>) => {
      const error = startError(event.data);
      if (error) failed(error);
      else resolve(new WebSeparatorWorker(worker));
    }, { once: true, signal });
    worker.addEventListener('error', (event) => {
      event.preventDefault();
      failed(new CoreError(`a separator worker could not start: ${event.message || 'its script did not load'}`, 'internal'));
    }, { signal });
    worker.postMessage(start);
  }).finally(() => starting.abort());
}

export class PagePool {
  private workers: WebSeparatorWorker[] = [];

  /** `start()`: what the next worker (a replacement too) is started with. */
  constructor(
    readonly owner: object,
    readonly optionsKey: string,
    private readonly start: () => PoolStart,
  ) {}

  /** Up to `count` ready workers, started as needed; `failures` says why any could not start. */
  async ready(count: number): Promise<{ workers: WebSeparatorWorker[]; failures: string[] }> {
    for (const worker of this.workers.filter((w) => w.failed)) this.drop(worker);
    const missing = Math.max(0, count - this.workers.length);
    const results = await Promise.allSettled(Array.from({ length: missing }, () => startWorker(this.start())));
    const failures: string[] = [];
    for (const result of results) {
      if (result.status === 'fulfilled') this.workers.push(result.value);
      else failures.push(result.reason instanceof Error ? result.reason.message : String(result.reason));
    }
    return { workers: this.workers.slice(0, count), failures };
  }

  /** Stops a worker that failed (it holds its memory, or is gone): the next run starts another. */
  drop(worker: WebSeparatorWorker): void {
    worker.close();
    this.workers = this.workers.filter((w) => w !== worker);
  }

  dispose(): void {
    for (const worker of this.workers) worker.close();
    this.workers = [];
  }
}
