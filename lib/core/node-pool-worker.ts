// One thread of the Node pool (lib/core/node-pool.ts): opens the mesh and a pipeline, then answers
// {id, sources} with the sources' candidate records, or with an error of the core's kind.
import { parentPort, workerData } from 'node:worker_threads';
import { createCore } from './index.ts';
import { CoreError, type CandidateRecord, type MeshArrays, type Options } from './types.ts';

const { mesh, options, memoryLimitMB, wasm } = workerData as {
  mesh: MeshArrays;
  options: Partial<Options>;
  memoryLimitMB?: number;
  /** The core as the pool compiled it. */
  wasm: WebAssembly.Module;
};
const port = parentPort!;

const kindOf = (error: unknown) => (error instanceof CoreError ? error.kind : 'internal');
const messageOf = (error: unknown) => (error instanceof Error ? error.message : String(error));

try {
  const core = await createCore(wasm, { memoryLimitMB });
  const pipeline = core.openRefinedSurface(mesh).pipeline(options);
  port.on('message', ({ id, sources }: { id: number; sources: Uint32Array }) => {
    try {
      const records: CandidateRecord[] = pipeline.separators(sources);
      const transfer = records.flatMap((r) => [
        r.loop.buffer,
        ...(r.points ? [r.points.kinds.buffer, r.points.elements.buffer, r.points.coords.buffer] : []),
        ...(r.reach ? [r.reach.buffer] : []),
      ]);
      port.postMessage({ id, records }, transfer as ArrayBuffer[]);
    } catch (error) {
      // A WebAssembly abort leaves the module unusable: the pool drops this thread.
      port.postMessage({ id, error: { message: messageOf(error), kind: error instanceof WebAssembly.RuntimeError ? 'crash' : kindOf(error) } });
      if (error instanceof WebAssembly.RuntimeError) process.exit(1);
    }
  });
  port.postMessage({ ready: true });
} catch (error) {
  port.postMessage({ error: { message: messageOf(error), kind: kindOf(error) } });
}
