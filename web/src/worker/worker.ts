/// <reference lib="webworker" />
/**
 * The geometry worker: parses mesh files and runs the WASM core, one request at a time, so the
 * page never blocks. Holds at most one open mesh (its prefactored Surface).
 */
import { createCore } from '../../../lib/core/index.ts';
import { defaultOptions } from '../../../lib/core/options.ts';
import type { Core, Options, Separator, Surface } from '../../../lib/core/types.ts';
import { parseMesh } from '../../../lib/io/index.ts';
import wasmUrl from '../../../build/wasm/cscd.wasm?url';
import {
  transferables,
  type DistanceRequest,
  type ErrorKind,
  type OpenRequest,
  type ProgressStage,
  type SeparatorData,
  type SeparatorRequest,
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
  /** The source of the last separator request, for re-runs with other options. */
  lastSource: number | null;
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
  current = { vertexCount: facts.vertices, surface, surfaceError, lastSource: null };

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

/** The open mesh's surface and a checked source vertex. */
function surfaceFor(source: number): { mesh: OpenMesh; surface: Surface } {
  if (!current) throw new UserError('core', 'No mesh is open.');
  if (!current.surface) {
    throw new UserError('core', `Geodesic distance is not available on this mesh: ${current.surfaceError}`);
  }
  if (!Number.isInteger(source) || source < 0 || source >= current.vertexCount) {
    throw new UserError('core', `Source vertex ${source} is not a vertex of this mesh.`);
  }
  return { mesh: current, surface: current.surface };
}

function finiteMax(values: ArrayLike<number>): number {
  let max = 0;
  for (let i = 0; i < values.length; i++) {
    const d = values[i];
    if (d > max && Number.isFinite(d)) max = d;
  }
  return max;
}

function distance(request: DistanceRequest): void {
  const { id, source } = request;
  const { surface } = surfaceFor(source);
  progress(id, 'distance', 'computing distance…');
  const t = performance.now();
  const d64 = surface.distanceFromVertex(source);
  const distanceMs = performance.now() - t;
  const distance = new Float32Array(d64);
  const max = finiteMax(distance);
  post({ type: 'distance', id, source, distance, max, timings: { distanceMs } }, transferables(distance));
}

const f32 = (a: ArrayLike<number> | null | undefined) => Float32Array.from(a ?? []);

/** Float32 copies of every array of a Separator (fresh buffers, safe to transfer). */
function toWire(s: Separator): SeparatorData {
  const c = s.cutLocus;
  return {
    ...s,
    distance: f32(s.distance),
    cutLocus: {
      ...c,
      vertices: Uint32Array.from(c.vertices ?? []),
      edges: Uint32Array.from(c.edges ?? []),
      points: f32(c.points),
      angleDeviation: f32(c.angleDeviation),
      laplacian: f32(c.laplacian),
    },
    paths: [f32(s.paths?.[0]), f32(s.paths?.[1])],
    approxLoop: f32(s.approxLoop),
    loop: f32(s.loop),
    timings: { ...s.timings },
  };
}

function separator(request: SeparatorRequest): void {
  const { id } = request;
  const source = request.source ?? current?.lastSource;
  if (source == null) throw new UserError('core', 'No source vertex has been picked yet.');
  const { mesh, surface } = surfaceFor(source);
  const options: Options = { ...defaultOptions, ...request.options };
  progress(id, 'separator', 'computing the separator…');
  const t = performance.now();
  const result = surface.separator(source, options);
  const separatorMs = performance.now() - t;
  mesh.lastSource = source;
  const data = toWire(result);
  const c = data.cutLocus;
  post(
    { type: 'separator', id, separator: data, options, distanceMax: finiteMax(data.distance), timings: { separatorMs } },
    transferables(data.distance, c.vertices, c.edges, c.points, c.angleDeviation, c.laplacian, ...data.paths, data.approxLoop, data.loop),
  );
}

async function handle(request: WorkerRequest): Promise<void> {
  try {
    switch (request.type) {
      case 'open':
        return await open(request);
      case 'distance':
        return distance(request);
      case 'separator':
        return separator(request);
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
