/**
 * Page-side handle on the geometry worker: typed requests returning promises, and crash recovery.
 *
 * When the worker dies or reports a crash (WASM abort), every pending request is rejected with a
 * WorkerError of kind `crash`, the worker is replaced and the last successfully opened mesh is re-opened in
 * the new one from what is kept here (the file's bytes, or the decimated mesh's arrays); re-opening
 * is cheap, since the geodesic solver is only opened when a request needs it. Requests made meanwhile
 * queue behind that re-open. After an out-of-memory error (kind `memory`) the worker is replaced the
 * same way, since WebAssembly memory never shrinks.
 *
 * Every computing request can be cancelled (`cancelRunning`, or a job's `cancel`): the worker stops it
 * at its next step; when it has not answered within CANCEL_GRACE_MS (a step that takes long, such as
 * opening the geodesic solver, or hangs), the worker is replaced the same way, without counting as a crash.
 */
import type { RunSettings } from '../../../lib/core/options.ts';
import type { Options, Refinement } from '../../../lib/core/types.ts';
import {
  type DecimatedReply,
  type ErrorKind,
  type OpenChoice,
  type PipelineNews,
  type ProgressEvent,
  type ReplyFor,
  type WorkerMessage,
  type WorkerRequest,
  type WriteRequest,
} from './protocol.ts';

/** An error reported by the worker for one request; `kind` says whether the worker survived it. */
export class WorkerError extends Error {
  override name = 'WorkerError';
  constructor(
    readonly kind: ErrorKind,
    message: string,
  ) {
    super(message);
  }
}

export interface ClientHooks {
  /** Progress of any request. */
  onProgress?(event: ProgressEvent): void;
  /** The worker died: `message` says why; `restored` settles when the new worker has the mesh again. */
  onCrash?(message: string, restored: Promise<ReplyFor['open'] | null>): void;
  /**
   * The worker was replaced without a crash: to stop a cancelled job that did not stop in time, or
   * to get its memory back after an out-of-memory error (which the request that hit it reports).
   */
  onRestart?(restored: Promise<ReplyFor['open'] | null>): void;
}

/** A running computation. */
export interface Job<T> {
  readonly result: Promise<T>;
  /**
   * Stops it: `result` rejects with a WorkerError of kind `cancelled`. The worker stops at its next
   * step; if it has not answered within CANCEL_GRACE_MS it is replaced.
   */
  cancel(): void;
}
export type SkeletonJob = Job<ReplyFor['skeleton']>;

interface Pending {
  resolve(reply: never): void;
  reject(error: Error): void;
  /** Requests that compute can be cancelled; open, restore and write are quick or must finish. */
  cancellable: boolean;
}

/**
 * What the worker needs to open the page's mesh again: the file (refined again the same way when
 * coarse), or the arrays of the decimated mesh as the worker computed on them.
 */
type KeptMesh =
  | { fileName: string; bytes: ArrayBuffer; choice: OpenChoice }
  | { fileName: string; positions: Float64Array; triangles: Uint32Array; refined: Refinement | null };

const UNCANCELLABLE = new Set<WorkerRequest['type']>(['open', 'restore', 'write']);

/** A request without its id (distributed over the union, so each variant keeps its own fields). */
type WithoutId<R> = R extends unknown ? Omit<R, 'id'> : never;
type RequestBody = WithoutId<WorkerRequest>;

/** Give up restarting after this many crashes in a row without a successful reply in between. */
const MAX_CONSECUTIVE_CRASHES = 3;

/** How long a cancelled job may take to stop before the worker is terminated. */
export const CANCEL_GRACE_MS = 2500;

export class GeometryClient {
  private worker: Worker;
  private nextId = 1;
  private readonly pending = new Map<number, Pending>();
  /** Pipeline news listeners of running skeleton jobs, by request id. */
  private readonly news = new Map<number, (news: PipelineNews, event: ProgressEvent) => void>();
  /** The last mesh the worker opened successfully, to re-open after a crash. */
  private current: KeptMesh | null = null;
  private crashes = 0;
  private dead = false;

  /**
   * Test hooks, from the page's address (`?memoryLimitMB=`, `?separatorCrash=`): `memoryLimitMB` caps
   * the WASM cores' memory; `separatorCrash` makes the worker's first separator worker abort on that
   * request (1: its first). The worker reads them from its name, which is all a module worker gets
   * before its first message.
   */
  constructor(
    private readonly hooks: ClientHooks = {},
    private readonly testHooks: { memoryLimitMB?: number | null; separatorCrash?: number | null } = {},
  ) {
    this.worker = this.spawn();
  }

  /**
   * Opens a mesh or point-cloud file in the worker (a cloud with `neighbours` per point, and above
   * POINT_LIMIT on a subsample unless `allPoints`; a mesh as a cloud of its vertices when `asCloud`).
   * `bytes` is transferred (detached) after a copy is kept.
   */
  async open(fileName: string, bytes: ArrayBuffer, choice: OpenChoice): Promise<ReplyFor['open']> {
    const kept = bytes.slice(0);
    const reply = await this.request({ type: 'open', fileName, bytes, withArrays: true, ...choice }, [bytes]);
    this.current = { fileName, bytes: kept, choice };
    return reply;
  }

  /**
   * Decimates the open mesh to about `targetFaces` faces in the worker, where it replaces the open
   * mesh (and is what a restart re-opens).
   */
  decimate(targetFaces: number): Job<DecimatedReply> {
    const fileName = this.current?.fileName ?? 'mesh';
    const job = this.job({ type: 'decimate', targetFaces });
    const result = job.result.then((reply) => {
      this.current = { fileName, positions: reply.exactPositions, triangles: reply.triangles.slice(), refined: reply.refined };
      return reply;
    });
    return { result, cancel: job.cancel };
  }

  /** Stage 1 from `source` (null: the worker's last source) with options differing from the defaults. */
  separator(source: number | null, options: Partial<Options> = {}): Promise<ReplyFor['separator']> {
    return this.request({ type: 'separator', source, options });
  }

  /**
   * The whole pipeline on the open mesh with options differing from the defaults, stage 1 on
   * `workers` threads; `onNews` gets the progress (sources done / total and the new loops) after
   * every step.
   */
  skeleton(options: Partial<Options>, workers: RunSettings['workers'], onNews?: (news: PipelineNews, event: ProgressEvent) => void): SkeletonJob {
    const id = this.nextId;
    if (onNews) this.news.set(id, onNews);
    const job = this.job({ type: 'skeleton', options, workers });
    return { result: job.result.finally(() => this.news.delete(id)), cancel: job.cancel };
  }

  /** Cancels every computing request sent and not answered yet (the page's Cancel). */
  cancelRunning(): void {
    for (const [id, pending] of this.pending) if (pending.cancellable) this.cancel(id);
  }

  /** The reconstruction error of the last skeleton the worker computed on the open mesh. */
  evaluate(): Promise<ReplyFor['evaluate']> {
    return this.request({ type: 'evaluate' });
  }

  /** A file of the last skeleton the worker computed (see WriteRequest). */
  write(what: WriteRequest['what'], mesh: string): Promise<ReplyFor['write']> {
    return this.request({ type: 'write', what, mesh });
  }

  /** Test hook: the worker fails as if the WASM core had aborted, dies of an uncaught error, or hangs. */
  simulateCrash(how: 'abort' | 'uncaught' | 'hang' = 'abort'): Promise<never> {
    return this.request({ type: 'crash', how });
  }

  dispose(): void {
    this.dead = true;
    this.worker.terminate();
    this.rejectAll('The geometry worker was stopped.');
  }

  private job<B extends RequestBody>(body: B): Job<ReplyFor[B['type']]> {
    const id = this.nextId;
    return { result: this.request(body), cancel: () => this.cancel(id) };
  }

  private request<B extends RequestBody>(body: B, transfer: Transferable[] = []): Promise<ReplyFor[B['type']]> {
    if (this.dead) return Promise.reject(new WorkerError('crash', 'The geometry worker is not running.'));
    const id = this.nextId++;
    return new Promise<ReplyFor[B['type']]>((resolve, reject) => {
      this.pending.set(id, { resolve: resolve as (reply: never) => void, reject, cancellable: !UNCANCELLABLE.has(body.type) });
      this.worker.postMessage({ ...body, id }, transfer);
    });
  }

  /** Asks the worker to stop request `id`; replaces the worker when it has not within CANCEL_GRACE_MS. */
  private cancel(id: number): void {
    const pending = this.pending.get(id);
    if (!pending?.cancellable) return;
    pending.cancellable = false; // asked once
    this.news.delete(id);
    this.worker.postMessage({ type: 'cancel', id });
    const worker = this.worker;
    setTimeout(() => {
      if (this.pending.has(id) && this.worker === worker) this.replace('The computation was cancelled.', 'cancel');
    }, CANCEL_GRACE_MS);
  }

  private spawn(): Worker {
    const { memoryLimitMB, separatorCrash } = this.testHooks;
    const name = ['cscd-geometry', memoryLimitMB && `memoryLimitMB=${memoryLimitMB}`, separatorCrash && `separatorCrash=${separatorCrash}`].filter(Boolean).join(' ');
    const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name });
    worker.onmessage = (event: MessageEvent<WorkerMessage>) => this.receive(event.data);
    worker.onerror = (event: ErrorEvent) => {
      event.preventDefault();
      this.crash(`The geometry worker failed: ${event.message || 'it could not start or threw an uncaught error'}`);
    };
    worker.onmessageerror = () => this.crash('The geometry worker sent a message that could not be read.');
    return worker;
  }

  private receive(message: WorkerMessage): void {
    if (message.type === 'progress') {
      this.hooks.onProgress?.(message);
      if (message.pipeline) this.news.get(message.id)?.(message.pipeline, message);
      return;
    }
    const pending = this.pending.get(message.id);
    if (!pending) return;
    this.pending.delete(message.id);
    if (message.type === 'error') {
      pending.reject(new WorkerError(message.kind, message.message));
      if (message.kind === 'crash') this.crash(message.message);
      if (message.kind === 'memory') this.replace(message.message, 'memory');
    } else {
      this.crashes = 0;
      pending.resolve(message as never);
    }
  }

  private rejectAll(message: string, kind: ErrorKind = 'crash'): void {
    const pending = [...this.pending.values()];
    this.pending.clear();
    this.news.clear();
    for (const p of pending) p.reject(new WorkerError(kind, message));
  }

  private crash(message: string): void {
    this.replace(message, 'crash');
  }

  /** Terminates the worker, fails what it had pending, starts a new one and re-opens the mesh in it. */
  private replace(message: string, why: 'crash' | 'cancel' | 'memory'): void {
    if (this.dead) return;
    this.worker.terminate();
    this.rejectAll(message, why === 'cancel' ? 'cancelled' : why);
    // Out of memory counts too: a mesh that exhausts even a fresh worker must not restart it forever.
    if (why !== 'cancel') this.crashes++;
    if (this.crashes > MAX_CONSECUTIVE_CRASHES) {
      this.dead = true;
      const final = `${message} The geometry worker keeps failing; reload the page.`;
      this.hooks.onCrash?.(final, Promise.resolve(null));
      return;
    }
    this.worker = this.spawn();
    let restored: Promise<ReplyFor['open'] | null> = Promise.resolve(null);
    const kept = this.current;
    if (kept && 'bytes' in kept) {
      const copy = kept.bytes.slice(0);
      restored = this.request({ type: 'open', fileName: kept.fileName, bytes: copy, withArrays: false, ...kept.choice }, [copy]);
    } else if (kept) {
      const positions = kept.positions.slice(), triangles = kept.triangles.slice();
      restored = this.request({ type: 'restore', fileName: kept.fileName, positions, triangles, refined: kept.refined }, [positions.buffer, triangles.buffer]);
    }
    if (why === 'crash') this.hooks.onCrash?.(message, restored);
    else this.hooks.onRestart?.(restored);
  }
}
