/// <reference lib="webworker" />
/**
 * A separator worker of the page's pool (page-pool.ts), started by the geometry worker: its first
 * message is a PoolStart (the compiled core, the mesh as the geometry worker opened it, the options),
 * then it serves `{id, sources}` requests as every pool worker does (lib/core/pool-worker.ts).
 */
import { servePoolWorker, type PoolRequest, type PoolStart } from '../../../lib/core/pool-worker.ts';

declare const self: DedicatedWorkerGlobalScope;

self.addEventListener(
  'message',
  (event: MessageEvent<PoolStart>) =>
    void servePoolWorker(event.data, {
      post: (message, transfer = []) => self.postMessage(message, transfer),
      listen: (handler) => self.addEventListener('message', (e: MessageEvent<PoolRequest>) => handler(e.data)),
      exit: () => self.close(),
    }),
  { once: true },
);
