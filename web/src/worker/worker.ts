/// <reference lib="webworker" />
/**
 * The geometry worker: parses mesh and point-cloud files and runs the WASM core, one request at a
 * time, so the page never blocks. Holds at most one open shape: a mesh, whose geodesic solver (the
 * prefactored Surface, the costly part on a large mesh) is opened by the first request that needs it,
 * or a point cloud, opened in the core at once (its neighbourhoods are what the facts report).
 */
import { createCore } from '../../../lib/core/index.ts';
import { AUTO_N, cloudOptionsOf, defaultOptions, MESH_OPTIONS } from '../../../lib/core/options.ts';
import { runStage1 } from '../../../lib/core/pool.ts';
import { CLOUD_VERTICES_PER_POINT, poolSize } from '../../../lib/core/pool-size.ts';
import {
  CoreError,
  type Cloud,
  type CloudOptions,
  type CloudArrays,
  type Core,
  type MeshArrays,
  type MeshFacts,
  type Options,
  type Pipeline,
  type PipelineProgress,
  type Refinement,
  type Separator,
  type Simplification,
  type Skeleton,
  type Surface,
} from '../../../lib/core/types.ts';
import { meshAsCloud } from '../../../lib/cloud/from-mesh.ts';
import { scanLineWarning } from '../../../lib/cloud/scan-lines.ts';
import { subsample, type Subsample } from '../../../lib/cloud/subsample.ts';
import { checkCloud } from '../../../lib/io/cloud-check.ts';
import { parseShape } from '../../../lib/io/index.ts';
import type { ShapeFormat } from '../../../lib/io/types.ts';
import { repairMesh } from '../../../lib/io/repair.ts';
import { writeLoopsObj } from '../../../lib/io/loops.ts';
import { SKELETON_WRITERS } from '../../../lib/io/skeleton.ts';
import { Decimator } from '../../../lib/mesh/decimate.ts';
import { POINT_LIMIT, SUBSAMPLE_TARGET } from '../../../lib/mesh/limits.ts';
import { refine, refinementOf, skeletonForInput } from '../../../lib/mesh/refine.ts';
import { simplificationOf, stage1Mesh } from '../../../lib/mesh/simplify.ts';
import wasmUrl from '../../../build/wasm/cscd.wasm?url';
import { PagePool, type WebSeparatorWorker } from './page-pool.ts';
import {
  transferables,
  type PoolReport,
  type DecimateRequest,
  type ErrorKind,
  type EvaluateRequest,
  type OpenRequest,
  type ProgressStage,
  type RestoreRequest,
  type SeparatorData,
  type SeparatorRequest,
  type SkeletonData,
  type SkeletonRequest,
  type WorkerMessage,
  type WriteRequest,
  type WorkerRequest,
} from './protocol.ts';

declare const self: DedicatedWorkerGlobalScope;

/** Test hooks of the page (see client.ts), in the worker's name: a cap on the cores' memory, and the
 * request on which the first separator worker aborts. */
const memoryLimitMB = Number(/memoryLimitMB=(\d+)/.exec(self.name)?.[1]) || undefined;
const separatorCrash = Number(/separatorCrash=(\d+)/.exec(self.name)?.[1]) || undefined;

/**
 * The core compiled while it downloads, and on a later visit taken from the browser's code cache, which
 * keeps only what was compiled from a stream; a server that does not say application/wasm gets the
 * plain compile.
 */
async function compileCore(): Promise<WebAssembly.Module> {
  const response = await fetch(wasmUrl);
  if (!response.ok) throw new Error(`HTTP ${response.status} for ${wasmUrl}`);
  if (response.headers.get('Content-Type')?.startsWith('application/wasm')) return WebAssembly.compileStreaming(response);
  return WebAssembly.compile(await response.arrayBuffer());
}

/** Started at once so the download and compilation overlap with the page's first file read; compiled
 * once, for this worker's core and the separator workers' (page-pool.ts). */
const modulePromise: Promise<WebAssembly.Module> = compileCore();
const corePromise: Promise<Core> = modulePromise.then((module) => createCore(module, { memoryLimitMB }));
corePromise.catch(() => {}); // reported when a request needs the core

interface OpenMesh {
  /** What the worker computes on and the page shows: the mesh as opened, refined when it was coarse. */
  mesh: MeshArrays;
  facts: MeshFacts;
  /** How it was refined (lib/mesh/refine.ts), or null. */
  refined: Refinement | null;
  /** The geodesic solver, opened by the first request that needs it. */
  surface: Surface | null;
  /** Stage 1's simplified copy of a large mesh (lib/mesh/simplify.ts) for a `stage1Vertices`, with its solver, opened by the first skeleton run. */
  stage1: { stage1Vertices: number; surface: Surface; simplified: Simplification; mesh: MeshArrays } | null;
  /** Why the solver cannot be opened on this mesh, once known. */
  surfaceError: string | null;
  /** The source of the last separator request, for re-runs with other options. */
  lastSource: number | null;
  /** The last skeleton computed, in full precision, with its options, for `evaluate` and `write`. */
  lastSkeleton: { skeleton: Skeleton; options: Options } | null;
}
let current: OpenMesh | null = null;

interface OpenCloud {
  cloud: Cloud;
  /** The cloud as opened (after the checks and any subsample), for the separator workers to open too. */
  arrays: CloudArrays;
  neighbours: number;
  /** The source of the last separator request, for re-runs with other options. */
  lastSource: number | null;
  /** The last skeleton computed, with its options, for `write`. */
  lastSkeleton: { skeleton: Skeleton; options: CloudOptions } | null;
}
let currentCloud: OpenCloud | null = null;

/** Why a mesh-only request fails: no mesh open, or a point cloud is. */
function noMesh(what: string): UserError {
  return new UserError('core', currentCloud ? `${what} is for meshes only for now; the open file is a point cloud.` : 'No mesh is open.');
}

/** Releases the open shape, its solver and its separator workers, before another is opened. */
function closeShapes(): void {
  current?.surface?.dispose();
  current?.stage1?.surface.dispose();
  current = null;
  currentCloud?.cloud.dispose();
  currentCloud = null;
  pool?.dispose();
  pool = null;
}

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
  if (error instanceof CoreError) return { kind: error.kind === 'memory' ? 'memory' : 'core', message };
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
  const t = performance.now();
  const parsed = parseShape(new Uint8Array(request.bytes), fileName);
  if (parsed.kind === 'cloud') return openCloud(request, { ...parsed, repairs: [], asCloud: false }, t);
  // Repair on load is part of reading the file: the page only ever sees the repaired mesh.
  const { mesh: repaired, repairs } = repairMesh(parsed);
  if (request.asCloud) {
    const { cloud, note } = meshAsCloud(repaired);
    return openCloud(request, { ...cloud, format: parsed.format, warnings: [...parsed.warnings, note], repairs, asCloud: true }, t);
  }
  const parseMs = performance.now() - t;
  const { mesh, facts, refined, surfaceError, inspectMs } = await accept(id, repaired);

  const positions = request.withArrays ? new Float32Array(mesh.positions) : new Float32Array(0);
  // A copy: the page gets its own (transferred); the worker keeps the mesh for `evaluate`.
  const triangles = request.withArrays ? mesh.triangles.slice() : new Uint32Array(0);
  post(
    {
      type: 'opened',
      shape: 'mesh',
      id,
      fileName,
      format: parsed.format,
      positions,
      triangles,
      facts,
      warnings: parsed.warnings,
      repairs,
      refined,
      surfaceError,
      timings: { parseMs, inspectMs },
    },
    transferables(positions, triangles),
  );
}

/** The points a cloud opens with: a cloud file's, or a mesh file's vertices (`asCloud`, after the mesh's repairs). */
type CloudInput = CloudArrays & { format: ShapeFormat; warnings: string[]; repairs: string[]; asCloud: boolean };

/**
 * A point cloud: checked as the CLI checks it (a bad cloud is refused with its message), subsampled
 * above POINT_LIMIT unless `allPoints` (to SUBSAMPLE_TARGET points, said among the repairs: the page
 * computes on the subsample, as the CLI advises, and offers all the points) or to `subsample` points when
 * asked (a cloud scanned in lines, thinned to their spacing), then opened in the core
 * with `neighbours`, without its stray points (lib/cloud/outliers.ts; found among the points computed
 * on). The page gets the points left out too: it draws them all.
 */
async function openCloud(request: OpenRequest, input: CloudInput, started: number): Promise<void> {
  const { id, fileName, neighbours } = request;
  // Stray points are looked for among the points computed on, after the subsample (6.5 s at a million
  // points, 0.3 s at the subsample's size); the CLI, which computes on all, looks in one pass with the
  // other checks, duplicates merged first either way.
  const checks = checkCloud(input, neighbours, { outliers: false });
  const { cloud: checked } = checks;
  const repairs = [...input.repairs, ...checks.repairs];
  const points = checked.positions.length / 3;
  const aboveLimit = points > POINT_LIMIT && !request.allPoints;
  const target = Math.min(points, request.subsample ?? (aboveLimit ? SUBSAMPLE_TARGET : points));
  const subsampled = target < points;
  if (subsampled) progress(id, 'parse', `subsampling ${points} points to ${target}…`); // seconds at a million
  const sample = subsample(checked, target, defaultOptions.seed);
  if (subsampled) {
    const why = request.subsample === null ? `above ${POINT_LIMIT} points the skeleton takes too long` : 'as asked';
    repairs.push(`subsampled from ${points} to ${sample.cloud.positions.length / 3} points (Poisson-disk, seed ${defaultOptions.seed}): ${why}`);
  }
  const { cloud, leftOut, standIn } = input.asCloud ? sample : withoutStrays(sample, neighbours, repairs);
  const parseMs = performance.now() - started;
  const core = await loadCore(id);
  progress(id, 'inspect', 'finding the neighbours of every point…');
  const t = performance.now();
  closeShapes();
  currentCloud = { cloud: core.openCloud(cloud, { neighbours }), arrays: cloud, neighbours, lastSource: null, lastSkeleton: null };
  const inspectMs = performance.now() - t;
  const scanLines = scanLineWarning(currentCloud.cloud.facts);
  const positions = request.withArrays ? new Float32Array(cloud.positions) : new Float32Array(0);
  const drawnLeftOut = request.withArrays ? leftOut : new Int32Array(0);
  const leftOutPositions = new Float32Array(3 * drawnLeftOut.length);
  drawnLeftOut.forEach((i, j) => leftOutPositions.set(checked.positions.subarray(3 * i, 3 * i + 3), 3 * j));
  const leftOutStandIn = request.withArrays ? Uint32Array.from(standIn) : new Uint32Array(0);
  post(
    {
      type: 'opened',
      shape: 'cloud',
      id,
      fileName,
      format: input.format,
      positions,
      facts: currentCloud.cloud.facts,
      warnings: scanLines ? [...input.warnings, scanLines] : input.warnings,
      repairs,
      leftOut: { positions: leftOutPositions, standIn: leftOutStandIn },
      subsampledFrom: subsampled ? points : null,
      asCloud: input.asCloud,
      timings: { parseMs, inspectMs },
    },
    transferables(positions, leftOutPositions, leftOutStandIn),
  );
}

/**
 * The subsample without its stray points (lib/cloud/outliers.ts, said among the repairs); a point left
 * out whose stand-in was a stray goes with it (a stray stands alone: such points lie beside it).
 */
function withoutStrays<C extends CloudArrays>(sample: Subsample<C>, neighbours: number, repairs: string[]): Omit<Subsample<C>, 'pointOf'> {
  const checks = checkCloud(sample.cloud, neighbours, { outliers: true });
  if (checks.repairs.length === 0) return sample;
  repairs.push(...checks.repairs);
  const kept = sample.standIn.map((s) => checks.pointMap[s]);
  const keep = (_: number, j: number) => kept[j] >= 0;
  return { cloud: checks.cloud, leftOut: sample.leftOut.filter(keep), standIn: kept.filter(keep) };
}

/** A mesh the page had decimated in a worker before this one: opened as it is. */
async function restore(request: RestoreRequest): Promise<void> {
  const { id, fileName } = request;
  const { facts, refined, surfaceError, inspectMs } = await accept(id, { positions: request.positions, triangles: request.triangles }, request.refined);
  // Only says the mesh is open again: the page still shows it, with the format and notes of its first open.
  const empty = { positions: new Float32Array(0), triangles: new Uint32Array(0) };
  post({ type: 'opened', shape: 'mesh', id, fileName, format: 'ply', ...empty, facts, warnings: [], repairs: [], refined, surfaceError, timings: { parseMs: 0, inspectMs } });
}

/**
 * Inspects a mesh, refines it when it is coarse (lib/mesh/refine.ts; `known` given: the arrays are
 * already the refined mesh) and makes it the open one (releasing the previous one), without its
 * solver. Returns the arrays it computes on and the facts of the mesh as given, which is what the page
 * lists. On a mesh whose facts already say it is not an orientable manifold the solver is tried at
 * once: it fails fast, and the page learns why before anything is asked.
 */
async function accept(
  id: number,
  input: MeshArrays,
  known?: Refinement | null,
): Promise<{ mesh: MeshArrays; facts: MeshFacts; refined: Refinement | null; surfaceError: string | null; inspectMs: number }> {
  const core = await loadCore(id);
  progress(id, 'inspect', 'checking the mesh…');
  const t = performance.now();
  const facts = core.inspect(input);
  const refined = known !== undefined ? known : refinementOf(facts);
  const mesh = refined && known === undefined ? refine(input, refined.levels) : input;
  const computedOn = mesh === input ? facts : core.inspect(mesh);
  const inspectMs = performance.now() - t;
  closeShapes();
  current = { mesh, facts: computedOn, refined, surface: null, stage1: null, surfaceError: null, lastSource: null, lastSkeleton: null };
  if (!facts.manifold || !facts.consistentlyOriented) {
    try {
      current.surface = core.openSurface(mesh);
    } catch (error) {
      const { kind, message } = classify(error);
      if (kind !== 'core') throw error;
      current.surfaceError = message;
    }
  }
  return { mesh, facts, refined, surfaceError: current.surfaceError, inspectMs };
}

/**
 * The open mesh with its geodesic solver, opened now if it is not yet: a step of the request `id`
 * of its own (progress "preparing the geodesic solver…", a cancel is honoured before and after it).
 * `unavailable` starts the message when the mesh cannot have one.
 */
async function withSurface(id: number, unavailable: string): Promise<{ mesh: OpenMesh; surface: Surface }> {
  const mesh = current;
  if (!mesh) throw noMesh('Stage 1 from one source');
  if (!mesh.surface && !mesh.surfaceError) {
    const core = await loadCore(id);
    progress(id, 'prepare', 'preparing the geodesic solver…');
    await yieldToEvents();
    checkCancelled(id);
    const t = performance.now();
    try {
      mesh.surface = core.openSurface(mesh.mesh);
    } catch (error) {
      const { kind, message } = classify(error);
      if (kind !== 'core') throw error;
      mesh.surfaceError = message;
    }
    if (mesh.surface) post({ type: 'progress', id, stage: 'prepare', message: 'geodesic solver ready', solverMs: performance.now() - t });
    await yieldToEvents();
    checkCancelled(id);
  }
  if (!mesh.surface) throw new UserError('core', `${unavailable}: ${mesh.surfaceError}`);
  return { mesh, surface: mesh.surface };
}

/** The open mesh's surface and a checked source vertex. */
async function surfaceFor(id: number, source: number): Promise<{ mesh: OpenMesh; surface: Surface }> {
  const opened = await withSurface(id, 'Geodesic distance is not available on this mesh');
  if (!Number.isInteger(source) || source < 0 || source >= opened.mesh.facts.vertices) {
    throw new UserError('core', `Source vertex ${source} is not a vertex of this mesh.`);
  }
  return opened;
}

function finiteMax(values: ArrayLike<number>): number {
  let max = 0;
  for (let i = 0; i < values.length; i++) {
    const d = values[i];
    if (d > max && Number.isFinite(d)) max = d;
  }
  return max;
}

const f32 = (a: ArrayLike<number>) => Float32Array.from(a);

/**
 * A Separator for the page: Float32 copies of its coordinates and fields; its index arrays are the
 * core's own copies (the worker keeps no separator), so they are transferred as they are.
 */
function toWire(s: Separator): SeparatorData {
  const c = s.cutLocus;
  return {
    ...s,
    distance: f32(s.distance),
    cutLocus: { ...c, points: f32(c.points), angleDeviation: f32(c.angleDeviation), laplacian: f32(c.laplacian) },
    paths: [f32(s.paths[0]), f32(s.paths[1])],
    approxLoop: f32(s.approxLoop),
    loop: f32(s.loop),
    timings: { ...s.timings },
  };
}

/** Loops of a cloud's shortening sent to the page, at most (evenly spaced steps, the first and the last). */
const SHORTENING_FRAMES = 60;

/** Length of a closed polyline (xyz triples). */
function closedLength(p: ArrayLike<number>): number {
  const n = p.length / 3;
  let length = 0;
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    length += Math.hypot(p[3 * j] - p[3 * i], p[3 * j + 1] - p[3 * i + 1], p[3 * j + 2] - p[3 * i + 2]);
  }
  return length;
}

/**
 * Stage 1 from one point of the open cloud, as a mesh's run travels to the page (a cloud's separator is
 * always a loop: no boundary ends), with loops recorded along the shortening.
 */
function cloudSeparatorData(cloud: OpenCloud, source: number, options: CloudOptions): SeparatorData {
  const s = cloud.cloud.separatorStages(source, options, SHORTENING_FRAMES);
  const c = s.cutLocus;
  return {
    source,
    status: s.status,
    message: s.message,
    distance: f32(s.distance),
    cutLocus: { vertices: c.vertices, edges: c.edges, root: c.root, cycleRank: c.cycleRank, points: f32(c.points), angleDeviation: f32(c.angleDeviation), laplacian: f32(c.laplacian) },
    boundaryExtremities: { vertices: new Uint32Array(0), points: new Float64Array(0) },
    target: s.target,
    attempts: s.attempts,
    targetPoint: s.targetPoint,
    ends: null,
    endPoints: null,
    closed: true,
    paths: [f32(s.paths[0]), f32(s.paths[1])],
    approxLoop: f32(s.approxLoop),
    loop: f32(s.loop),
    sphere: s.sphere,
    approxLength: closedLength(s.approxLoop),
    length: s.length,
    areas: s.areas,
    score: s.score,
    centroidInside: s.centroidInside,
    timings: { ...s.timings },
    iterates: s.iterates.map(f32),
  };
}

async function separator(request: SeparatorRequest): Promise<void> {
  const { id } = request;
  const cloud = currentCloud;
  if (cloud) {
    const source = request.source ?? cloud.lastSource;
    if (source == null) throw new UserError('core', 'No source point has been picked yet.');
    if (!Number.isInteger(source) || source < 0 || source >= cloud.cloud.facts.points) {
      throw new UserError('core', `Source point ${source} is not a point of this cloud.`);
    }
    const options: Options = { ...defaultOptions, ...request.options };
    progress(id, 'separator', 'computing the separator…');
    const t = performance.now();
    const data = cloudSeparatorData(cloud, source, cloudOptionsOf(options, cloud.neighbours));
    cloud.lastSource = source;
    const c = data.cutLocus;
    post(
      { type: 'separator', id, separator: data, options, distanceMax: finiteMax(data.distance), timings: { separatorMs: performance.now() - t } },
      transferables(data.distance, c.vertices, c.edges, c.points, c.angleDeviation, c.laplacian, ...data.paths, data.approxLoop, data.loop, ...data.iterates!),
    );
    return;
  }
  const source = request.source ?? current?.lastSource;
  if (source == null) throw new UserError('core', 'No source vertex has been picked yet.');
  const { mesh, surface } = await surfaceFor(id, source);
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

// -- the whole pipeline -----------------------------------------------------------------------------

/** Wall time one step should take: long enough to amortise the messages, short enough to cancel. */
const STEP_TARGET_MS = 150;
const STEP_MAX_SOURCES = 64;

/** Requests received and not yet answered, and those of them asked to stop. */
const runningRequests = new Set<number>();
const cancelRequested = new Set<number>();

class Cancelled extends UserError {
  constructor() {
    super('cancelled', 'The computation was cancelled.');
  }
}

/** Between two steps of request `id`: stops it when a cancel has come in. */
function checkCancelled(id: number): void {
  if (cancelRequested.has(id)) throw new Cancelled();
}

/** Lets messages (a `cancel`) in between two steps. */
const yieldToEvents = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

/** The next step's size: scaled towards STEP_TARGET_MS by the last step's time, at most x4 per step. */
function nextStepSize(k: number, ms: number): number {
  if (!(ms > 0)) return Math.min(k * 4, STEP_MAX_SOURCES);
  const scaled = Math.floor((k * STEP_TARGET_MS) / ms);
  return Math.max(1, Math.min(scaled, k * 4, STEP_MAX_SOURCES));
}

/** A Skeleton for the page: copies of every array, since the worker keeps the skeleton (evaluate, export). */
function skeletonToWire(s: Skeleton): SkeletonData {
  const c = s.candidates;
  return {
    ...s,
    nodes: f32(s.nodes),
    radii: f32(s.radii),
    edges: s.edges.slice(),
    vertexToNode: s.vertexToNode.slice(),
    packed: s.packed.slice(),
    candidates: { sources: c.sources.slice(), loops: c.loops.map(f32), closed: c.closed.slice(), scores: c.scores.slice(), fates: [...c.fates] },
    stats: { ...s.stats, timings: { ...s.stats.timings } },
  };
}

/** Tells the page how far stage 1 is, with the loops taken since the last news. */
function postSources(id: number, p: PipelineProgress, notices: readonly string[]): void {
  const newLoops = p.newLoops.map(f32);
  const { newClosed } = p;
  post(
    {
      type: 'progress',
      id,
      stage: 'sources',
      message: [`stage 1: ${p.done} / ${p.total} sources`, ...notices].join('; '),
      fraction: p.total > 0 ? p.done / p.total : undefined,
      pipeline: { done: p.done, total: p.total, finished: p.finished, newLoops, newClosed, notices: [...notices] },
    },
    transferables(...newLoops, newClosed),
  );
}

/**
 * Stage 1's simplified copy of the open mesh and its solver when the mesh is large (lib/mesh/simplify.ts;
 * a refined mesh never is), made and opened by the first skeleton run: null otherwise.
 */
async function withStage1(id: number, stage1Vertices: number): Promise<OpenMesh['stage1']> {
  const mesh = current;
  if (!mesh || mesh.surfaceError || mesh.refined || !simplificationOf(mesh.facts, stage1Vertices)) return null;
  if (mesh.stage1?.stage1Vertices !== stage1Vertices) {
    mesh.stage1?.surface.dispose();
    mesh.stage1 = null;
    const core = await loadCore(id);
    progress(id, 'prepare', 'simplifying the mesh for stage 1…');
    await yieldToEvents();
    checkCancelled(id);
    const made = stage1Mesh(mesh.mesh, mesh.facts, stage1Vertices)!;
    await yieldToEvents();
    checkCancelled(id);
    progress(id, 'prepare', 'preparing the geodesic solver of the simplified mesh…');
    mesh.stage1 = { ...made, stage1Vertices, surface: core.openSurface(made.mesh) };
  }
  return mesh.stage1;
}

/** The separator workers of the open mesh and the options of the last run that used them. */
let pool: PagePool | null = null;

/** The options in their declared order: two runs share a pool when these are the same. */
const optionsKey = (options: Options) => JSON.stringify(MESH_OPTIONS.map((o) => options[o.key]));

let separatorWorkersStarted = 0;
/**
 * The pool (started on the open mesh or cloud with `options` when there is none) and its `count`
 * workers getting ready; the first separator worker this geometry worker ever starts carries the
 * page's crash hook.
 */
function poolFor(owner: OpenMesh | OpenCloud, options: Options, module: WebAssembly.Module, count: number) {
  if (!pool) {
    const shape = 'cloud' in owner
      ? { cloud: owner.arrays, options: cloudOptionsOf(options, owner.neighbours) }
      : { mesh: owner.stage1?.mesh ?? owner.mesh, refine: false, options }; // what this worker's stage 1 runs on: refined or simplified already
    pool = new PagePool(owner, optionsKey(options), () => ({
      ...shape,
      wasm: module,
      memoryLimitMB,
      crashOnRequest: ++separatorWorkersStarted === 1 ? separatorCrash : undefined,
    }));
  }
  return { pool, opening: pool.ready(count) };
}

/** Why a separator worker was lost, for the page. */
function lostNotice(error: unknown, left: number): string {
  const what = error instanceof CoreError && error.kind === 'memory' ? 'ran out of memory' : 'crashed';
  const message = error instanceof Error ? error.message : String(error);
  return `a separator worker ${what} (${message}): continuing on ${left > 0 ? `${left} worker${left === 1 ? '' : 's'}` : 'the geometry worker alone'}`;
}

/** Separator workers `request` asks for on a shape of `vertices` points (lib/core/pool-size.ts). */
function poolSizeFor(request: SkeletonRequest, options: Options, vertices: number) {
  return poolSize({
    workers: request.workers,
    cores: navigator.hardwareConcurrency || 1,
    memoryGB: (navigator as WorkerNavigator & { deviceMemory?: number }).deviceMemory ?? null,
    vertices,
    drawAhead: options.drawAhead,
    sourcesLeft: options.n === 'auto' ? AUTO_N.max : options.n,
  });
}

async function skeleton(request: SkeletonRequest): Promise<void> {
  const { id } = request;
  const check = () => checkCancelled(id);
  check();
  const options: Options = { ...defaultOptions, ...request.options };
  const cloud = currentCloud;
  const owner = cloud ?? current;
  if (pool && (pool.owner !== owner || pool.optionsKey !== optionsKey(options))) {
    pool.dispose();
    pool = null;
  }
  // A large mesh runs stage 1 on a simplified copy, which the separator workers open instead.
  const stage1 = cloud ? null : await withStage1(id, options.stage1Vertices);
  // A cloud's core holds about twice a mesh's per element (lib/core/pool-size.ts).
  const size = cloud
    ? poolSizeFor(request, options, CLOUD_VERTICES_PER_POINT * cloud.cloud.facts.points)
    : current && !current.surfaceError ? poolSizeFor(request, options, (stage1?.mesh ?? current.mesh).positions.length / 3) : { workers: 1, memoryCapped: false };
  // The separator workers open the shape while this worker opens its solver.
  const t0 = performance.now();
  const starting = owner && size.workers > 1 ? poolFor(owner, options, await modulePromise, size.workers) : null;
  const opened = cloud ? null : await withSurface(id, 'The skeleton is not available on this mesh');
  const started = starting ? await starting.opening : { workers: [], failures: [] };
  const report: PoolReport = {
    workers: Math.max(1, started.workers.length),
    memoryCapped: size.memoryCapped,
    notices: started.failures.map((f) => `a separator worker could not start (${f})`),
    openMs: starting ? performance.now() - t0 : 0,
  };
  progress(id, 'sources', 'stage 1: starting…');
  let pipeline: Pipeline | null = cloud ? cloud.cloud.pipeline(cloudOptionsOf(options, cloud.neighbours)) : opened!.surface.pipeline(options, stage1?.surface);
  let running = true;
  let finished = false;
  try {
    let stage1Run: Stage1Run;
    if (started.workers.length > 0) {
      const t = performance.now();
      let left = report.workers;
      let steps = 0;
      await runStage1(pipeline, started.workers, {
        check,
        progress: (p) => {
          steps++;
          postSources(id, p, report.notices);
        },
        lost: (worker, error) => {
          if (!running) return; // stopped by the end of the run, not lost
          starting!.pool.drop(worker as WebSeparatorWorker);
          report.notices.push(lostNotice(error, --left));
        },
      });
      stage1Run = { stage1Ms: performance.now() - t, steps };
    } else {
      stage1Run = await stepAlone(id, pipeline, report.notices);
    }
    running = false;
    const skeleton = await finishRun(id, pipeline, options, report, stage1Run, cloud ? undefined : (stage1?.simplified ?? null));
    if (cloud) cloud.lastSkeleton = { skeleton, options: cloudOptionsOf(options, cloud.neighbours) };
    else opened!.mesh.lastSkeleton = { skeleton, options };
    finished = true;
  } finally {
    running = false;
    // A run stopped part way (a cancel) stops every separator worker: none goes on computing its sources.
    if (!finished && starting) {
      starting.pool.dispose();
      if (pool === starting.pool) pool = null;
    }
    pipeline.dispose();
    pipeline = null;
  }
}

/** Stage 1's wall time (alone: its steps summed; on a pool: from the first draw to the last accept) and its steps or accepts. */
interface Stage1Run {
  stage1Ms: number;
  steps: number;
}

/** Stage 1 on this worker alone, a few sources a step, a cancel honoured between steps. */
async function stepAlone(id: number, pipeline: Pipeline, notices: readonly string[]): Promise<Stage1Run> {
  let k = 1;
  let stage1Ms = 0;
  let steps = 0;
  for (;;) {
    await yieldToEvents();
    checkCancelled(id);
    const t = performance.now();
    const p = pipeline.step(k);
    const ms = performance.now() - t;
    stage1Ms += ms;
    steps++;
    postSources(id, p, notices);
    if (p.finished || (p.total > 0 && p.done >= p.total)) return { stage1Ms, steps };
    k = nextStepSize(k, ms);
  }
}

/** Stage 2, then the `skeleton` reply; returns the skeleton in full precision for the worker to keep. */
/** `simplified`: how a mesh's stage 1 copy was made (lib/mesh/simplify.ts), null if it was not; undefined for a cloud. */
async function finishRun(id: number, pipeline: Pipeline, options: Options, report: PoolReport, stage1: Stage1Run, simplified: Simplification | null | undefined): Promise<Skeleton> {
  await yieldToEvents();
  checkCancelled(id);
  progress(id, 'stage2', 'stage 2: pruning, packing, regions, skeleton…');
  const t = performance.now();
  const finished = pipeline.finish();
  const result = simplified === undefined ? finished : { ...finished, stats: { ...finished.stats, simplified } };
  const stage2Ms = performance.now() - t;
  const data = skeletonToWire(result);
  const c = data.candidates;
  post(
    { type: 'skeleton', id, skeleton: data, options, pool: report, timings: { ...stage1, stage2Ms } },
    transferables(data.nodes, data.radii, data.edges, data.vertexToNode, data.packed, c.sources, c.scores, ...c.loops),
  );
  return result;
}

// -- evaluation -------------------------------------------------------------------------------------

async function evaluate(request: EvaluateRequest): Promise<void> {
  const { id } = request;
  const last = currentCloud ? currentCloud.lastSkeleton : current?.lastSkeleton;
  if (!last) throw new UserError('core', 'There is no skeleton to evaluate: compute one first.');
  const core = await loadCore(id);
  progress(id, 'evaluate', 'reconstructing the surface from the skeleton…');
  // One call into the core: a cancel stops it only before it starts (else the page replaces the worker).
  await yieldToEvents();
  checkCancelled(id);
  const t = performance.now();
  // A cloud's skeleton against its points (as `cscd evaluate` scores it), a mesh's against its vertices.
  const result = currentCloud ? core.evaluateCloud(currentCloud.arrays, last.skeleton) : core.evaluate(current!.mesh, last.skeleton);
  const evaluateMs = performance.now() - t;
  const evaluation = { ...result, radii: f32(result.radii), vertexError: f32(result.vertexError) };
  post(
    { type: 'evaluation', id, evaluation, timings: { evaluateMs } },
    transferables(evaluation.radii, evaluation.vertexError, evaluation.surface.positions, evaluation.surface.triangles),
  );
}

// -- decimation ------------------------------------------------------------------------------------

/** Collapses per decimation step: about a tenth of a second, so progress is lively and a cancel quick. */
const COLLAPSES_PER_STEP = 5000;

async function decimate(request: DecimateRequest): Promise<void> {
  const { id, targetFaces } = request;
  if (!current) throw noMesh('Decimation');
  const from = current.facts.faces;
  progress(id, 'decimate', `decimating ${from} faces…`);
  const t = performance.now();
  const decimator = new Decimator(current.mesh, targetFaces);
  for (;;) {
    await yieldToEvents();
    checkCancelled(id);
    if (decimator.step(COLLAPSES_PER_STEP)) break;
    const p = decimator.progress;
    post({ type: 'progress', id, stage: 'decimate', message: `decimating: ${p.faces} faces, target ${p.target}…`, fraction: p.fraction });
  }
  const decimateMs = performance.now() - t;
  const { mesh, facts, refined } = await accept(id, decimator.result());
  const positions = new Float32Array(mesh.positions);
  // Copies for the page: the worker keeps the mesh it computes on.
  const exactPositions = Float64Array.from(mesh.positions);
  const triangles = mesh.triangles.slice();
  post(
    { type: 'decimated', id, positions, exactPositions, triangles, facts, decimatedFrom: from, refined, timings: { decimateMs } },
    transferables(positions, exactPositions, triangles),
  );
}

// -- files ----------------------------------------------------------------------------------------

/**
 * Writes the last skeleton (or its packed separators) as a file's bytes. Done here rather than on the
 * page: the worker holds the skeleton in full precision (the page has float32 copies for the GPU), and
 * formatting a large skeleton stays off the main thread.
 */
function write(request: WriteRequest): void {
  const last = currentCloud ? currentCloud.lastSkeleton : current?.lastSkeleton;
  if (!last) throw new UserError('core', 'There is no skeleton to save: compute one first.');
  // A file is for the mesh as opened, like the CLI's: vertexToNode over its vertices, not the refined mesh's.
  const skeleton = currentCloud ? last.skeleton : skeletonForInput(last.skeleton, current?.refined ?? null, last.skeleton.stats.simplified ?? null);
  const { options } = last;
  const text =
    request.what === 'separators-obj'
      ? writeLoopsObj(
          Array.from(skeleton.packed, (i) => skeleton.candidates.loops[i]),
          Array.from(skeleton.packed, (i) => skeleton.candidates.closed[i]),
          [`CSCD packed separators of ${request.mesh}`, `options ${JSON.stringify(options)}`],
        )
      : SKELETON_WRITERS[request.what](skeleton, { mesh: request.mesh, options });
  const bytes = new TextEncoder().encode(text);
  post({ type: 'written', id: request.id, bytes }, transferables(bytes));
}

async function handle(request: WorkerRequest): Promise<void> {
  try {
    switch (request.type) {
      case 'open':
        return await open(request);
      case 'restore':
        return await restore(request);
      case 'separator':
        return await separator(request);
      case 'decimate':
        return await decimate(request);
      case 'skeleton':
        return await skeleton(request);
      case 'evaluate':
        return await evaluate(request);
      case 'write':
        return write(request);
      case 'cancel':
        return; // handled on arrival
      case 'crash':
        if (request.how === 'hang') {
          const end = performance.now() + 60_000;
          while (performance.now() < end) {
            // busy, as a runaway WASM loop would be: no message gets in
          }
          throw new WebAssembly.RuntimeError('simulated hang ended');
        }
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
  } finally {
    runningRequests.delete(request.id);
    cancelRequested.delete(request.id);
  }
}

// One request at a time, in arrival order (a request yields between its steps, so a cancel gets in).
// A cancel is not queued: it marks its request, which stops at its next step (or at once, if queued).
let queue: Promise<void> = Promise.resolve();
self.onmessage = (event: MessageEvent<WorkerRequest>) => {
  const request = event.data;
  if (request.type === 'cancel') {
    if (runningRequests.has(request.id)) cancelRequested.add(request.id);
    return;
  }
  runningRequests.add(request.id);
  queue = queue.then(() => handle(request));
};
