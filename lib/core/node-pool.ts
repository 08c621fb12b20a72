// A pool of worker threads for stage 1 in Node (CLI, library): each thread loads its own core, opens
// the same mesh as the caller (refined as openRefinedSurface refines it) or the same point cloud and a pipeline with the same
// options, and computes the separators of the sources it is sent (lib/core/pool.ts).
import { Worker } from 'node:worker_threads';
import { compiledCore } from './node.ts';
import { PooledWorker, startError, type PoolReady, type PoolReply, type PoolRequest, type PoolStart } from './pool-worker.ts';
import { CoreError, type CloudArrays, type CloudOptions, type Options, type Stage1Input } from './types.ts';

export interface PoolSettings {
  /** Threads that compute stage 1 (1: none but the caller's, no pool); the caller's only draws and accepts. */
  workers: number;
  /** The memory limit of each thread's core (CoreSettings.memoryLimitMB). */
  memoryLimitMB?: number;
}

export class ThreadWorker extends PooledWorker {
  constructor(private readonly thread: Worker) {
    super();
    thread.on('message', (reply: PoolReply) => this.receive(reply));
    thread.on('error', (error) => this.fail(error));
    thread.on('exit', (code) => this.fail(new CoreError(`a worker thread stopped (exit code ${code})`, 'internal')));
  }

  protected send(request: PoolRequest): void {
    this.thread.postMessage(request);
  }

  close(): Promise<number> {
    return this.thread.terminate();
  }
}

/**
 * `workers` threads (none for 1), each ready (its surface and pipeline open) when this resolves. `input`:
 * Core.stage1Input of the caller's mesh and options (horse: simplifying it took 0.9 s, which every thread
 * spent again when each was sent the mesh as read).
 */
export function openNodePool(input: Stage1Input, options: Partial<Options>, settings: PoolSettings): Promise<NodePool> {
  const { mesh, refine } = input;
  return openPool(settings, (wasm) => ({ mesh: { positions: mesh.positions, triangles: mesh.triangles }, refine, options, memoryLimitMB: settings.memoryLimitMB, wasm }));
}

/** The same for a point cloud: each thread opens the cloud (with `options.neighbours`) and its pipeline. */
export function openNodeCloudPool(cloud: CloudArrays, options: Partial<CloudOptions>, settings: PoolSettings): Promise<NodePool> {
  return openPool(settings, (wasm) => ({ cloud: { positions: cloud.positions, normals: cloud.normals }, options, memoryLimitMB: settings.memoryLimitMB, wasm }));
}

async function openPool(settings: PoolSettings, start: (wasm: WebAssembly.Module) => PoolStart): Promise<NodePool> {
  const count = settings.workers >= 2 ? Math.floor(settings.workers) : 0;
  if (count === 0) return new NodePool([]);
  // One compile of the core for all threads (each instantiates its own copy of it).
  const workerData = start(await compiledCore());
  const threads = Array.from({ length: count }, () => new Worker(new URL('./node-pool-thread.mjs', import.meta.url), { workerData }));
  try {
    await Promise.all(threads.map((thread) => new Promise<void>((resolve, reject) => {
      thread.once('message', (m: PoolReady) => {
        const error = startError(m);
        if (error) reject(error);
        else resolve();
      });
      thread.once('error', reject);
    })));
  } catch (error) {
    await Promise.all(threads.map((t) => t.terminate()));
    throw error;
  }
  return new NodePool(threads.map((t) => new ThreadWorker(t)));
}

export class NodePool {
  constructor(readonly workers: readonly ThreadWorker[]) {}

  async close(): Promise<void> {
    await Promise.all(this.workers.map((w) => w.close()));
  }
}
