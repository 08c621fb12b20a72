/// <reference lib="webworker" />
/**
 * The geometry worker: parses mesh files and runs the WASM core, one request at a time, so the
 * page never blocks. Holds at most one open mesh (its prefactored Surface).
 */
import { createCore } from '../../../lib/core/index.ts';
import type { Core, Surface } from '../../../lib/core/types.ts';
import { parseMesh } from '../../../lib/io/index.ts';
import wasmUrl from '../../../build/wasm/cscd.wasm?url';
import {
  transferables,
  type DistanceRequest,
  type ErrorKind,
  type OpenRequest,
  type ProgressStage,
  type WorkerMessage,
  type WorkerRequest,
} from './protocol.ts';

declare const self: DedicatedWorkerGlobalScope;

/** Started at once so the download and compilation overlap with the page's first file read. */
const corePromise: Promise<Core> = fetch(wasmUrl)
  .then((response) => {
    if (!response.ok) throw new Error(`HTTP ${response.status} for ${wasmUrl}`);
    return response.arrayBuffer();
  })
  .then((bytes) => createCore(bytes));
corePromise.catch(() => {}); // reported when a request needs the core

interface OpenMesh {
  vertexCount: number;
  surface: Surface | null;
  surfaceError: string | null;
}
let current: OpenMesh | null = null;

function post(message: WorkerMessage, transfer: Transferable[] = []): void {
  self.postMessage(message, transfer);
}

function progress(id: number, stage: ProgressStage, message: string): void {
  post({ type: 'progress', id, stage, message });
}

/** A failure the user should read; anything else means the worker state is no longer trusted. */
class UserError extends Error {
  constructor(
    readonly kind: ErrorKind,
    message: string,
  ) {
    super(message);
  }
}

function classify(error: unknown): { kind: ErrorKind; message: string } {
  if (error instanceof UserError) return { kind: error.kind, message: error.message };
  const name = error instanceof Error ? error.name : '';
  const message = error instanceof Error ? error.message : String(error);
  if (name === 'MeshFormatError') return { kind: 'format', message };
  if (name === 'CoreError') return { kind: 'core', message };
  // WebAssembly.RuntimeError (abort, trap, out of memory) or a bug: the core's state is suspect.
  const what = error instanceof WebAssembly.RuntimeError ? 'The geometry core crashed' : 'The geometry worker failed';
  return { kind: 'crash', message: `${what}: ${message || name || 'unknown error'}` };
}

async function loadCore(id: number): Promise<Core> {
  progress(id, 'load-core', 'loading the geometry core…');
  try {
    return await corePromise;
  } catch (error) {
    const message = error instanceof Error ? error.message : String(error);
    throw new UserError('core', `Could not load the geometry core: ${message}`);
  }
}

async function open(request: OpenRequest): Promise<void> {
  const { id, fileName } = request;
  progress(id, 'parse', `reading ${fileName}…`);
  let t = performance.now();
  const mesh = parseMesh(new Uint8Array(request.bytes), fileName);
  const parseMs = performance.now() - t;

  const core = await loadCore(id);
  progress(id, 'inspect', 'checking the mesh…');
  t = performance.now();
  const facts = core.inspect(mesh);
  const inspectMs = performance.now() - t;

  // The mesh is accepted from here on: release the previous one before building the new solver.
  current?.surface?.dispose();
  current = null;

  progress(id, 'prepare', 'preparing the geodesic solver…');
  t = performance.now();
  let surface: Surface | null = null;
  let surfaceError: string | null = null;
  try {
    surface = core.openSurface(mesh);
  } catch (error) {
    const { kind, message } = classify(error);
    if (kind !== 'core') throw error;
    surfaceError = message;
  }
  const prepareMs = performance.now() - t;
  current = { vertexCount: facts.vertices, surface, surfaceError };

  const positions = request.withArrays ? new Float32Array(mesh.positions) : new Float32Array(0);
  const triangles = request.withArrays ? mesh.triangles : new Uint32Array(0);
  post(
    {
      type: 'opened',
      id,
      fileName,
      format: mesh.format,
      positions,
      triangles,
      facts,
      warnings: mesh.warnings,
      surfaceError,
      timings: { parseMs, inspectMs, prepareMs },
    },
    transferables(positions, triangles),
  );
}

function distance(request: DistanceRequest): void {
  const { id, source } = request;
  if (!current) throw new UserError('core', 'No mesh is open.');
  if (!current.surface) {
    throw new UserError('core', `Geodesic distance is not available on this mesh: ${current.surfaceError}`);
  }
  if (!Number.isInteger(source) || source < 0 || source >= current.vertexCount) {
    throw new UserError('core', `Source vertex ${source} is not a vertex of this mesh.`);
  }
  progress(id, 'distance', 'computing distance…');
  const t = performance.now();
  const d64 = current.surface.distanceFromVertex(source);
  const distanceMs = performance.now() - t;
  const distance = new Float32Array(d64);
  let max = 0;
  for (let i = 0; i < distance.length; i++) {
    const d = distance[i];
    if (d > max && Number.isFinite(d)) max = d;
  }
  post({ type: 'distance', id, source, distance, max, timings: { distanceMs } }, transferables(distance));
}

async function handle(request: WorkerRequest): Promise<void> {
  try {
    switch (request.type) {
      case 'open':
        return await open(request);
      case 'distance':
        return distance(request);
      case 'crash':
        if (request.how === 'uncaught') {
          setTimeout(() => {
            throw new Error('simulated uncaught error');
          });
          return;
        }
        throw new WebAssembly.RuntimeError('Aborted(simulated crash)');
    }
  } catch (error) {
    post({ type: 'error', id: request.id, ...classify(error) });
  }
}

// One request at a time, in arrival order (open may await the core).
let queue: Promise<void> = Promise.resolve();
self.onmessage = (event: MessageEvent<WorkerRequest>) => {
  const request = event.data;
  queue = queue.then(() => handle(request));
};
