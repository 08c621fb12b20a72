// A pool of worker threads for stage 1 in Node (CLI, library): each thread loads its own core, opens
// the same mesh as the caller (refined as openRefinedSurface refines it) and a pipeline with the same
// options, and computes the separators of the sources it is sent (lib/core/pool.ts).
import os from 'node:os';
import { Worker } from 'node:worker_threads';
import { compiledCore } from './node.ts';
import type { SeparatorWorker } from './pool.ts';
import { CoreError, type CandidateRecord, type CoreErrorKind, type MeshArrays, type Options } from './types.ts';

/** Threads that compute stage 1 by default: every core but one, at least one. */
export const defaultWorkers = () => Math.max(1, os.availableParallelism() - 1);

export interface PoolSettings {
  /** Threads that compute stage 1 (1: none but the caller's, no pool); the caller's only draws and accepts. */
  workers: number;
  /** The memory limit of each thread's core (CoreSettings.memoryLimitMB). */
  memoryLimitMB?: number;
}

type Reply = { id: number; records: CandidateRecord[] } | { id: number; error: { message: string; kind: CoreErrorKind | 'crash' } };

export class ThreadWorker implements SeparatorWorker {
  private readonly pending = new Map<number, { resolve: (r: CandidateRecord[]) => void; reject: (e: Error) => void }>();
  private next = 0;
  private failure: Error | null = null;

  constructor(private readonly thread: Worker) {
    thread.on('message', (reply: Reply) => {
      const waiting = this.pending.get(reply.id);
      this.pending.delete(reply.id);
      if ('records' in reply) waiting?.resolve(reply.records);
      else waiting?.reject(new CoreError(reply.error.message, reply.error.kind === 'crash' ? 'internal' : reply.error.kind));
    });
    const fail = (error: Error) => {
      this.failure ??= error;
      for (const { reject } of this.pending.values()) reject(this.failure);
      this.pending.clear();
    };
    thread.on('error', fail);
    thread.on('exit', (code) => fail(new CoreError(`a worker thread stopped (exit code ${code})`, 'internal')));
  }

  separators(sources: Uint32Array): Promise<CandidateRecord[]> {
    if (this.failure) return Promise.reject(this.failure);
    const id = this.next++;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject });
      this.thread.postMessage({ id, sources });
    });
  }

  close(): Promise<number> {
    return this.thread.terminate();
  }
}

/** `workers` threads (none for 1), each ready (its surface and pipeline open) when this resolves. */
export async function openNodePool(mesh: MeshArrays, options: Partial<Options>, settings: PoolSettings): Promise<NodePool> {
  const count = settings.workers >= 2 ? Math.floor(settings.workers) : 0;
  // One compile of the core for all threads (each instantiates its own copy of it).
  const wasm = count > 0 ? await compiledCore() : null;
  const threads = Array.from({ length: count }, () => new Worker(new URL('./node-pool-thread.mjs', import.meta.url), {
    workerData: { mesh: { positions: mesh.positions, triangles: mesh.triangles }, options, memoryLimitMB: settings.memoryLimitMB, wasm },
  }));
  try {
    await Promise.all(threads.map((thread) => new Promise<void>((resolve, reject) => {
      thread.once('message', (m: { ready?: true; error?: { message: string; kind: CoreErrorKind } }) =>
        m.ready ? resolve() : reject(new CoreError(m.error?.message ?? 'a worker thread could not open the mesh', m.error?.kind ?? 'internal')));
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
