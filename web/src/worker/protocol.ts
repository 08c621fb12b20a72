/**
 * Messages between the page and the geometry worker.
 *
 * Every request carries an `id`; the worker answers it with exactly one reply of the matching type
 * or an `error` with the same id, and may send `progress` events for it before that. Large arrays
 * travel in transfer lists in both directions (see `transferables`).
 */
import type { RunSettings } from '../../../lib/core/options.ts';
import type { CloudFacts, Evaluation, MeshFacts, Options, Refinement, Separator, Skeleton } from '../../../lib/core/types.ts';
import type { SkeletonFormat } from '../../../lib/io/skeleton.ts';
import type { MeshFormat, ShapeFormat } from '../../../lib/io/types.ts';

// ---------------------------------------------------------------------------------------------
// Page -> worker

/** How a file is opened: the page's choices, kept to open it again. */
export interface OpenChoice {
  /** k of a point cloud's neighbourhoods (the `neighbours` option), should the file be one or run as one. */
  neighbours: number;
  /** A point cloud above POINT_LIMIT is computed on all its points (the offer's choice), not on a subsample. */
  allPoints: boolean;
  /**
   * A point cloud is computed on about this many of its points (the CLI's --subsample; the page asks for
   * it for a cloud scanned in lines, lib/cloud/scan-lines.ts's scanLineSubsample), or null.
   */
  subsample: number | null;
  /** A mesh file runs as a point cloud of its vertices (AS_CLOUD, lib/cloud/from-mesh.ts); nothing for a cloud file. */
  asCloud: boolean;
}

export interface OpenRequest extends OpenChoice {
  type: 'open';
  id: number;
  fileName: string;
  /** The file's bytes; transferred, so the sender's buffer is detached afterwards. */
  bytes: ArrayBuffer;
  /** Send positions and triangles back (false when re-opening a mesh the page already shows). */
  withArrays: boolean;
}

/**
 * Stage 1 of CSCD-M (one separator, every intermediate kept) from a source vertex. Per-mesh data is
 * cached in the core, so re-running the same source with other options is cheap.
 */
export interface SeparatorRequest {
  type: 'separator';
  id: number;
  /** Source vertex; null re-runs the worker's last source (an options change). */
  source: number | null;
  /** Options that differ from `defaultOptions`. */
  options: Partial<Options>;
}

/**
 * Test hook: `abort` fails the request as a WASM abort would (an error reply of kind `crash`);
 * `uncaught` throws outside any request, which the page sees as the Worker's `error` event;
 * `hang` keeps the worker busy for a minute without yielding (a step that never ends).
 */
export interface CrashRequest {
  type: 'crash';
  id: number;
  how: 'abort' | 'uncaught' | 'hang';
}

/**
 * The whole CSCD-M pipeline (stage 1 from N sources, then stage 2) on the open mesh. The worker runs
 * it a few sources at a time, or on a pool of separator workers (page-pool.ts) with sources drawn ahead,
 * sends a `progress` event with `pipeline` news after every step and answers with a `skeleton`
 * reply, or an `error` of kind `cancelled` after a `cancel`.
 */
export interface SkeletonRequest {
  type: 'skeleton';
  id: number;
  /** Options that differ from `defaultOptions` (n, seed, pruneLengthFactor, and the stage-1 ones). */
  options: Partial<Options>;
  /** Separator workers that compute stage 1 (1: this worker alone), or auto (lib/core/pool-size.ts); not an option: the skeleton is the same for any. */
  workers: RunSettings['workers'];
}

/** The reconstruction error (paper Sec. 5) of the last skeleton the worker computed on the open mesh. */
export interface EvaluateRequest {
  type: 'evaluate';
  id: number;
}

/** A file of the last skeleton the worker computed: the skeleton in a format, or its packed separators (OBJ loops). */
export interface WriteRequest {
  type: 'write';
  id: number;
  what: SkeletonFormat | 'separators-obj';
  /** The mesh's name, written into the file's header. */
  mesh: string;
}

/**
 * The open mesh decimated to about `targetFaces` faces (lib/mesh/decimate.ts); it replaces the open
 * mesh in the worker (the geodesic solver is opened on it when needed). Runs in steps, with `progress`.
 */
export interface DecimateRequest {
  type: 'decimate';
  id: number;
  targetFaces: number;
}

/**
 * Opens a mesh this worker's predecessor had decimated (after a restart): the arrays it computed on,
 * no parsing, repair or refinement.
 */
export interface RestoreRequest {
  type: 'restore';
  id: number;
  fileName: string;
  /** Transferred. */
  positions: Float64Array;
  triangles: Uint32Array;
  /** How the predecessor refined the decimated mesh into these arrays (DecimatedReply.refined). */
  refined: Refinement | null;
}

/**
 * Asks the worker to stop the request with this `id` (any but `open`, `restore` and `write`) at its next
 * step: before or after opening the geodesic solver, between pipeline or decimation steps. It has no
 * reply of its own: the request it names answers with an `error` of kind `cancelled` (or with its
 * result, when it had already finished). Unlike every other request it is handled at once, not queued.
 */
export interface CancelRequest {
  type: 'cancel';
  id: number;
}

export type WorkerRequest =
  | OpenRequest
  | SeparatorRequest
  | SkeletonRequest
  | EvaluateRequest
  | WriteRequest
  | DecimateRequest
  | RestoreRequest
  | CancelRequest
  | CrashRequest;

// ---------------------------------------------------------------------------------------------
// Worker -> page

export interface OpenTimings {
  parseMs: number;
  inspectMs: number;
}

export interface OpenedReply {
  type: 'opened';
  shape: 'mesh';
  id: number;
  fileName: string;
  format: MeshFormat;
  /** xyz per vertex (float32 for the GPU); empty when the request had `withArrays: false`. */
  positions: Float32Array;
  triangles: Uint32Array;
  facts: MeshFacts;
  warnings: string[];
  /** What the repair on load did (lib/io/repair.ts), one sentence each; the arrays and facts are after it. */
  repairs: string[];
  /**
   * How the worker refined a coarse mesh to compute on (lib/mesh/refine.ts), or null. The arrays are
   * then those of the refined mesh (the same surface; vertex numbers in requests and replies are its
   * own), the facts those of the mesh as opened.
   */
  refined: Refinement | null;
  /**
   * Why geodesic computations are unavailable on this mesh (e.g. non-manifold), or null. Known at once
   * for a mesh whose facts show it; otherwise the geodesic solver is only opened by the first request
   * that needs it, which then fails with the reason.
   */
  surfaceError: string | null;
  timings: OpenTimings;
}

/**
 * A point cloud opened (checked, subsampled when above POINT_LIMIT, opened in the core with its
 * neighbours): the page draws its points, those left out of a subsample too; only the whole-shape
 * stages compute on it.
 */
export interface CloudOpenedReply {
  type: 'opened';
  shape: 'cloud';
  id: number;
  fileName: string;
  format: ShapeFormat;
  /** xyz per point computed on (float32 for the GPU); empty when the request had `withArrays: false`. */
  positions: Float32Array;
  /**
   * The points a subsample left out, drawn but not computed on (xyz), and for each the point of
   * `positions` that stands for it (within the subsample's radius): its colours and its picks. Empty
   * when not subsampled or without arrays.
   */
  leftOut: { positions: Float32Array; standIn: Uint32Array };
  facts: CloudFacts;
  warnings: string[];
  /** What the checks on load did (lib/io/cloud-check.ts) and a subsampling, one sentence each. */
  repairs: string[];
  /** The cloud's point count when it was subsampled to compute on (above POINT_LIMIT without `allPoints`, or as `subsample` asked), else null. */
  subsampledFrom: number | null;
  /** The file is a mesh, run as a point cloud of its vertices (the request's `asCloud`). */
  asCloud: boolean;
  timings: OpenTimings;
}

export interface DecimatedReply {
  type: 'decimated';
  id: number;
  /** xyz per vertex, float32 for the GPU. */
  positions: Float32Array;
  /** The same positions in full precision: what the worker computes on, kept by the page to restore it after a restart. */
  exactPositions: Float64Array;
  triangles: Uint32Array;
  facts: MeshFacts;
  decimatedFrom: number;
  /** How the decimated mesh was then refined, when it came out coarse (as in OpenedReply: the arrays are after it, the facts before). */
  refined: Refinement | null;
  timings: { decimateMs: number };
}

/** A Separator as it travels to the page: float32 arrays for the GPU, every buffer transferred. */
export interface SeparatorData extends Omit<Separator, 'distance' | 'cutLocus' | 'paths' | 'approxLoop' | 'loop'> {
  /** Geodesic distance per vertex; non-finite values (unreachable vertices) are kept as is. */
  distance: Float32Array;
  cutLocus: Omit<Separator['cutLocus'], 'points' | 'angleDeviation' | 'laplacian'> & {
    points: Float32Array;
    angleDeviation: Float32Array;
    laplacian: Float32Array;
  };
  paths: [Float32Array, Float32Array];
  approxLoop: Float32Array;
  loop: Float32Array;
  /** On a point cloud: the loop as its shortening's descent moved it, every k-th step (the last is the loop); absent on a mesh, whose loop FlipOut shortens by edge flips. */
  iterates?: Float32Array[];
}

export interface SeparatorReply {
  type: 'separator';
  id: number;
  separator: SeparatorData;
  /** The options the run used (defaults filled in). */
  options: Options;
  /** Largest finite distance. */
  distanceMax: number;
  /** Wall time of the whole call in the worker (the core's own per-stage times are in `separator.timings`). */
  timings: { separatorMs: number };
}

/** A Skeleton as it travels to the page: float32 arrays for the GPU, every buffer transferred. */
export interface SkeletonData extends Omit<Skeleton, 'nodes' | 'radii' | 'candidates'> {
  nodes: Float32Array;
  radii: Float32Array;
  candidates: Omit<Skeleton['candidates'], 'loops'> & { loops: Float32Array[] };
}

/** What stage 1 ran on. */
export interface PoolReport {
  /** Separator workers at the start (1 also when the geometry worker computed alone, without a pool). */
  workers: number;
  /** `workers` auto chose fewer than the cores allow, for want of memory. */
  memoryCapped: boolean;
  /** Separator workers that could not start or were lost, one sentence each. */
  notices: string[];
  /** Wall time to have the separator workers ready (0: none, or kept from the last run). */
  openMs: number;
}

export interface SkeletonReply {
  type: 'skeleton';
  id: number;
  skeleton: SkeletonData;
  /** The options the run used (defaults filled in). */
  options: Options;
  pool: PoolReport;
  /**
   * Wall times in the worker: stage 1 (alone: its steps summed; on a pool: from the first draw to
   * the last accept), stage 2 (`finish`), and the number of steps or accepts.
   */
  timings: { stage1Ms: number; stage2Ms: number; steps: number };
}

/** An Evaluation as it travels to the page: float32 arrays for the GPU, every buffer transferred. */
export interface EvaluationData extends Omit<Evaluation, 'radii' | 'vertexError'> {
  radii: Float32Array;
  vertexError: Float32Array;
}

export interface EvaluationReply {
  type: 'evaluation';
  id: number;
  evaluation: EvaluationData;
  /** Wall time of the call in the worker. */
  timings: { evaluateMs: number };
}

export interface WrittenReply {
  type: 'written';
  id: number;
  /** The file's bytes (UTF-8 text), transferred. */
  bytes: Uint8Array;
}

/**
 * `format`: the file is not a readable mesh; `core`: the core refused the input or computation;
 * both leave the worker usable. `memory`: the core ran out of memory; the worker is usable but keeps
 * the memory (WebAssembly memory never shrinks), so the page replaces it. `crash`: the WASM core aborted
 * or the worker hit an unexpected error; its state is lost and the page must replace it. `cancelled`:
 * the request was cancelled (the worker is fine).
 */
export type ErrorKind = 'format' | 'core' | 'memory' | 'crash' | 'cancelled';

export interface ErrorReply {
  type: 'error';
  id: number;
  kind: ErrorKind;
  message: string;
}

export type ProgressStage = 'parse' | 'load-core' | 'inspect' | 'prepare' | 'decimate' | 'separator' | 'sources' | 'stage2' | 'evaluate';

/** News of a pipeline run after one step (PipelineProgress with float32 loops, transferred). */
export interface PipelineNews {
  done: number;
  total: number;
  finished: boolean;
  /** The loops found by this step's sources (empty for failed sources), xyz triples. */
  newLoops: Float32Array[];
  /** Per new loop: 1 closed, 0 an open path ending on the mesh boundary. */
  newClosed: Uint8Array;
  /** What happened to the pool so far (PoolReport.notices). */
  notices: string[];
}

/** Intermediate news about a request; `fraction` in [0, 1] when the stage can measure itself. */
export interface ProgressEvent {
  type: 'progress';
  id: number;
  stage: ProgressStage;
  message: string;
  fraction?: number;
  /** Set on the `sources` events of a skeleton request. */
  pipeline?: PipelineNews;
  /** Set when the geodesic solver has just been opened: how long that took. */
  solverMs?: number;
}

export type WorkerReply =
  | OpenedReply
  | CloudOpenedReply
  | SeparatorReply
  | SkeletonReply
  | EvaluationReply
  | WrittenReply
  | DecimatedReply
  | ErrorReply;
export type WorkerMessage = WorkerReply | ProgressEvent;

/** The reply type that answers each request type. */
export interface ReplyFor {
  open: OpenedReply | CloudOpenedReply;
  separator: SeparatorReply;
  skeleton: SkeletonReply;
  evaluate: EvaluationReply;
  write: WrittenReply;
  decimate: DecimatedReply;
  restore: OpenedReply;
  cancel: never;
  crash: never;
}

/** Distinct array buffers of the given typed arrays, for a postMessage transfer list. */
export function transferables(...arrays: ArrayBufferView[]): ArrayBuffer[] {
  const buffers = new Set<ArrayBuffer>();
  for (const a of arrays) {
    if (a.buffer instanceof ArrayBuffer && a.buffer.byteLength > 0) buffers.add(a.buffer);
  }
  return [...buffers];
}
