// One thread of the Node pool (lib/core/node-pool.ts): a pool worker (pool-worker.ts) on worker_threads.
import { parentPort, workerData } from 'node:worker_threads';
import { servePoolWorker, type PoolRequest, type PoolStart } from './pool-worker.ts';

const port = parentPort!;
await servePoolWorker(workerData as PoolStart, {
  post: (message, transfer) => port.postMessage(message, transfer),
  listen: (handler) => port.on('message', (request: PoolRequest) => handler(request)),
  exit: () => process.exit(1),
});
