/**
 * Page-side handle on the geometry worker: typed requests returning promises, and crash recovery.
 *
 * When the worker dies or reports a crash (WASM abort), every pending request is rejected with a
 * WorkerError of kind `crash`, the worker is replaced and the last successfully opened mesh is re-opened in
 * the new one from bytes kept here. Requests made meanwhile queue behind that re-open.
 *
 * A skeleton run is a job that can be cancelled: the worker stops it between two steps; when it has
 * not answered within CANCEL_GRACE_MS (a step that takes long or hangs), the worker is replaced the
 * same way, without counting as a crash.
 */
import type { Options } from '../../../lib/core/types.ts';
import {
  type ErrorKind,
  type OpenedReply,
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
  onCrash?(message: string, restored: Promise<OpenedReply | null>): void;
  /** The worker was replaced to stop a cancelled job that did not stop in time (not an error). */
  onRestart?(restored: Promise<OpenedReply | null>): void;
}

/** A running skeleton computation. */
export interface SkeletonJob {
  readonly result: Promise<ReplyFor['skeleton']>;
  /**
   * Stops it: `result` rejects with a WorkerError of kind `cancelled`. The worker stops between two
   * steps; if it has not answered within CANCEL_GRACE_MS it is replaced.
   */
  cancel(): void;
}

interface Pending {
  resolve(reply: never): void;
  reject(error: Error): void;
}

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
  private current: { fileName: string; bytes: ArrayBuffer } | null = null;
  private crashes = 0;
  private dead = false;

  constructor(private readonly hooks: ClientHooks = {}) {
    this.worker = this.spawn();
  }

  /** Opens a mesh file in the worker. `bytes` is transferred (detached) after a copy is kept. */
  async open(fileName: string, bytes: ArrayBuffer): Promise<OpenedReply> {
    const kept = bytes.slice(0);
    const reply = await this.request({ type: 'open', fileName, bytes, withArrays: true }, [bytes]);
    this.current = { fileName, bytes: kept };
    return reply;
  }

  distance(source: number): Promise<ReplyFor['distance']> {
    return this.request({ type: 'distance', source });
  }

  /** Stage 1 from `source` (null: the worker's last source) with options differing from the defaults. */
  separator(source: number | null, options: Partial<Options> = {}): Promise<ReplyFor['separator']> {
    return this.request({ type: 'separator', source, options });
  }

  /**
   * The whole pipeline on the open mesh with options differing from the defaults; `onNews` gets the
   * progress (sources done / total and the new loops) after every step.
   */
  skeleton(options: Partial<Options>, onNews?: (news: PipelineNews, event: ProgressEvent) => void): SkeletonJob {
    const id = this.nextId;
    if (onNews) this.news.set(id, onNews);
    const result = this.request({ type: 'skeleton', options }).finally(() => this.news.delete(id));
    let cancelled = false;
    const cancel = () => {
      if (cancelled || !this.pending.has(id)) return;
      cancelled = true;
      this.news.delete(id);
      this.worker.postMessage({ type: 'cancel', id });
      const worker = this.worker;
      setTimeout(() => {
        if (this.pending.has(id) && this.worker === worker) this.replace('The computation was cancelled.', 'cancel');
      }, CANCEL_GRACE_MS);
    };
    return { result, cancel };
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

  private request<B extends RequestBody>(body: B, transfer: Transferable[] = []): Promise<ReplyFor[B['type']]> {
    if (this.dead) return Promise.reject(new WorkerError('crash', 'The geometry worker is not running.'));
    const id = this.nextId++;
    return new Promise<ReplyFor[B['type']]>((resolve, reject) => {
      this.pending.set(id, { resolve: resolve as (reply: never) => void, reject });
      this.worker.postMessage({ ...body, id }, transfer);
    });
  }

  private spawn(): Worker {
    const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'cscd-geometry' });
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
  private replace(message: string, why: 'crash' | 'cancel'): void {
    if (this.dead) return;
    this.worker.terminate();
    this.rejectAll(message, why === 'crash' ? 'crash' : 'cancelled');
    if (why === 'crash') this.crashes++;
    if (this.crashes > MAX_CONSECUTIVE_CRASHES) {
      this.dead = true;
      const final = `${message} The geometry worker keeps failing; reload the page.`;
      this.hooks.onCrash?.(final, Promise.resolve(null));
      return;
    }
    this.worker = this.spawn();
    let restored: Promise<OpenedReply | null> = Promise.resolve(null);
    if (this.current) {
      const { fileName, bytes } = this.current;
      const copy = bytes.slice(0);
      restored = this.request({ type: 'open', fileName, bytes: copy, withArrays: false }, [copy]);
    }
    if (why === 'crash') this.hooks.onCrash?.(message, restored);
    else this.hooks.onRestart?.(restored);
  }
}
