// What a pool's worker and its owner say to each other, the same for a Node worker thread
// (node-pool.ts) and a Web Worker of the page (web/src/worker/page-pool.ts): the worker opens the mesh
// (or point cloud) and a pipeline with the owner's options, says it is ready, then answers {id, sources} with the
// sources' candidate records (their buffers transferred) or with an error of the core's kind.
import { createCore } from './index.ts';
import type { SeparatorWorker } from './pool.ts';
import { CoreError, type CandidateRecord, type CloudArrays, type CloudOptions, type CoreErrorKind, type Options, type Pipeline, type Stage1Input } from './types.ts';

/** `crash`: the WebAssembly instance aborted; the worker is gone. */
export type PoolErrorKind = CoreErrorKind | 'crash';

interface PoolStartCommon {
  /** The core compiled once by the owner; each worker instantiates its own. */
  wasm: WebAssembly.Module;
  memoryLimitMB?: number;
  /** Test hook: the worker's request with this number (1: its first) aborts as a crashed core would. */
  crashOnRequest?: number;
}

/** What a pool worker is started with: a mesh, or a point cloud, and the pipeline's options. */
export type PoolStart = PoolStartCommon & (
  | (Stage1Input & { options: Partial<Options> })
  | { cloud: CloudArrays; options: Partial<CloudOptions> }
);

export type PoolReady = { ready: true } | { error: { message: string; kind: CoreErrorKind } };
export interface PoolRequest {
  id: number;
  sources: Uint32Array;
}
export type PoolReply = { id: number; records: CandidateRecord[] } | { id: number; error: { message: string; kind: PoolErrorKind } };

const kindOf = (error: unknown): CoreErrorKind => (error instanceof CoreError ? error.kind : 'internal');
const messageOf = (error: unknown) => (error instanceof Error ? error.message : String(error));

/** The buffers of records about to be posted: theirs alone (each was made for this reply), so transferred. */
function recordBuffers(records: CandidateRecord[]): ArrayBuffer[] {
  return records.flatMap((r) => [
    r.loop.buffer,
    ...(r.points instanceof Uint32Array ? [r.points.buffer] : r.points ? [r.points.kinds.buffer, r.points.elements.buffer, r.points.coords.buffer] : []),
    ...(r.reach ? [r.reach.buffer] : []),
  ]) as ArrayBuffer[];
}

/** The worker's side, given how it posts, how it hears requests and how it ends itself. */
export interface PoolPort {
  post(message: PoolReady | PoolReply, transfer?: ArrayBuffer[]): void;
  listen(handler: (request: PoolRequest) => void): void;
  exit(): void;
}

/** Runs a pool worker: opens what `start` says, then serves separators until it crashes or is stopped. */
export async function servePoolWorker(start: PoolStart, port: PoolPort): Promise<void> {
  let pipeline: Pipeline;
  try {
    const core = await createCore(start.wasm, { memoryLimitMB: start.memoryLimitMB });
    if ('cloud' in start) pipeline = core.openCloud(start.cloud, start.options).pipeline(start.options);
    else pipeline = (start.refine ? core.openStage1Surface(start.mesh, start.options) : core.openSurface(start.mesh)).pipeline(start.options);
  } catch (error) {
    port.post({ error: { message: messageOf(error), kind: kindOf(error) } });
    return;
  }
  let requests = 0;
  port.listen(({ id, sources }) => {
    try {
      if (++requests === start.crashOnRequest) throw new WebAssembly.RuntimeError('Aborted(simulated crash)');
      const records = pipeline.separators(sources);
      port.post({ id, records }, recordBuffers(records));
    } catch (error) {
      // A WebAssembly abort leaves the instance unusable: the owner drops this worker.
      const crashed = error instanceof WebAssembly.RuntimeError;
      port.post({ id, error: { message: messageOf(error), kind: crashed ? 'crash' : kindOf(error) } });
      if (crashed) port.exit();
    }
  });
  port.post({ ready: true });
}

/** The error a failed start reports, or null for `ready`. */
export function startError(message: PoolReady): CoreError | null {
  return 'ready' in message ? null : new CoreError(message.error.message, message.error.kind);
}

/**
 * The owner's side of one worker: requests by id, each settled by its reply; once the worker fails
 * (it crashed, stopped or sent something unreadable) everything pending and asked later is rejected.
 */
export abstract class PooledWorker implements SeparatorWorker {
  private readonly pending = new Map<number, { resolve: (r: CandidateRecord[]) => void; reject: (e: Error) => void }>();
  private next = 0;
  private failure: Error | null = null;

  protected abstract send(request: PoolRequest): void;

  get failed(): boolean {
    return this.failure !== null;
  }

  separators(sources: Uint32Array): Promise<CandidateRecord[]> {
    if (this.failure) return Promise.reject(this.failure);
    const id = this.next++;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject });
      this.send({ id, sources });
    });
  }

  protected receive(reply: PoolReply): void {
    const waiting = this.pending.get(reply.id);
    this.pending.delete(reply.id);
    if ('records' in reply) {
      waiting?.resolve(reply.records);
      return;
    }
    const error = new CoreError(reply.error.message, reply.error.kind === 'crash' ? 'internal' : reply.error.kind);
    waiting?.reject(error);
    // An aborted core answers nothing more (a Web Worker that closes itself tells nobody).
    if (reply.error.kind === 'crash') this.fail(error);
  }

  protected fail(error: Error): void {
    this.failure ??= error;
    for (const { reject } of this.pending.values()) reject(this.failure);
    this.pending.clear();
  }
}
