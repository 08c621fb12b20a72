// Entry of a Node pool thread: the thread's code is TypeScript, loaded through tsx as the CLI's is
// (a worker's own --import hooks would not yet be in place for its entry module under Node 20).
import { register } from 'tsx/esm/api';

register();
await import('./node-pool-worker.ts');
