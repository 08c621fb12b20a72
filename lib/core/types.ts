/** Types of the CSCD core as seen from TypeScript (CLI, worker, tests). */

/** An indexed triangle mesh: xyz per vertex, three vertex indices per triangle. */
export interface MeshArrays {
  positions: Float64Array | Float32Array;
  triangles: Uint32Array;
}

/** The arrays of a point cloud, which the cloud checks, the subsampling and the core work on. */
export interface CloudArrays {
  /** x y z of each point, interleaved. */
  positions: Float64Array;
  /** nx ny nz of each point, interleaved; null when the file has no normals (not all three of them). */
  normals: Float32Array | null;
}

/** A point on the surface: a face of the input mesh and barycentric coordinates in it. */
export interface SurfacePoint {
  face: number;
  barycentric: [number, number, number];
}

/** The axis-aligned bounding box of a shape, and its diagonal (the length tolerances are relative to). */
export interface BoundingBox {
  bboxMin: [number, number, number];
  bboxMax: [number, number, number];
  bboxDiagonal: number;
}

/** Facts about a point cloud, once opened (Core.openCloud). */
export interface CloudFacts extends BoundingBox {
  points: number;
  /** k of the k-nearest-neighbour search (the `neighbours` option). */
  neighbours: number;
  /**
   * The neighbours each point's local triangulation is made from, on average: `neighbours` where every
   * neighbourhood lies flat (and on a noisy cloud), fewer (down to 12) where parts are thinner than it.
   */
  meanFlatNeighbours: number;
  /** Connected components of the tufted triangulation built from the neighbours: distances stay within one. */
  components: number;
  /**
   * The share of the points (every 16th) whose own surface fit (the point and its `neighbours` - 1 nearest,
   * weighted as the MLS fits weigh them) has them along a line (spread across it under a tenth of along
   * it), not around the point on a surface: a cloud scanned in lines farther apart than its points along
   * them (lib/cloud/scan-lines.ts).
   */
  lineLikeShare: number;
  /**
   * Over those points, the median distance to the nearest point across the line (more across it than
   * along it): the lines' spacing; 0 when no fit sees a line, or the next line lies beyond 8k nearest.
   */
  lineSpacing: number;
  /**
   * About how many points the cloud keeps when thinned along its lines to their spacing (each line-like
   * point's nearest distance over its across distance, the median, times the points); 0 as lineSpacing.
   */
  pointsAtLineSpacing: number;
  /** Mean edge length of the tufted triangulation (its edges join neighbouring points): the counterpart of a mesh's meanEdgeLength. */
  meanSpacing: number;
  /** Whether the normals are the file's (else they are estimated from the neighbours, by PCA). */
  normalsFromFile: boolean;
}

/** Facts about a mesh, computed without requiring it to be manifold. */
export interface MeshFacts extends BoundingBox {
  vertices: number;
  faces: number;
  edges: number;
  /** Connected components of the faces (vertices referenced by no face are not counted). */
  components: number;
  boundaryLoops: number;
  /** V - E + F over the referenced vertices. */
  eulerCharacteristic: number;
  /** Sum over components of (2 - chi - boundary loops) / 2; null when the mesh is not manifold. */
  genus: number | null;
  manifold: boolean;
  /** Every edge shared by two faces is traversed in opposite directions by them. */
  consistentlyOriented: boolean;
  nonManifoldEdges: number;
  nonManifoldVertices: number;
  unreferencedVertices: number;
  /** Faces that repeat a vertex or have (near) zero area. */
  degenerateFaces: number;
  meanEdgeLength: number;
}

/**
 * How a coarse mesh was refined before computing on it (lib/mesh/refine.ts): `levels` rounds of
 * midpoint subdivision took it from `fromFaces` to `toFaces` faces, the same surface sampled more
 * densely. Its `fromVertices` vertices are the refined mesh's first ones.
 */
export interface Refinement {
  fromVertices: number;
  fromFaces: number;
  toFaces: number;
  levels: number;
}

/**
 * How a large mesh was simplified for stage 1 (lib/mesh/simplify.ts, docs/multiscale.md): the sources
 * and loops of stage 1 are on a copy of `toVertices` vertices; stage 2 and the skeleton are on the mesh
 * as given.
 */
export interface Simplification {
  fromVertices: number;
  fromFaces: number;
  toVertices: number;
  toFaces: number;
}

/**
 * Every option of the CSCD pipeline, with the same names in C++ (wasm/src/cscd/options.h), the
 * bindings, worker messages, UI labels and CLI flags. Defaults: `defaultOptions` in lib/core/options.ts.
 */
export interface Options {
  /** How the target cut-locus point is chosen: nearest to the source in space or along the surface. */
  target: 'euclid' | 'geodesic';
  /** Keep the shortened loop inside a sphere around the source (paper Sec. 4.1.6). */
  sphere: boolean;
  /** Fixes every random choice (source sampling). */
  seed: number;
  /** Cut locus: minimum turn of the distance gradient at a ridge, radians in [0, pi]. */
  angleThreshold: number;
  /** Cut locus: minimum ridge sharpness, -(mean edge length) x (Laplacian of the distance), scale-free. */
  laplacianThreshold: number;
  /** Cut locus: leaf branches with fewer edges than this are pruned. */
  pruneDepth: number;
  /** Number of sources (separators tried), or 'auto': sample until new separators stop adding coverage. */
  n: number | 'auto';
  /** Prune: loops shorter than this many mean edge lengths enclose no feature (paper Sec. 4.2.2). */
  pruneLengthFactor: number;
  /** Sources drawn ahead of their separators in stage 1 (up to this many computed side by side, by a pool of workers); 1: one at a time. */
  drawAhead: number;
  /** Meshes only: above this many vertices stage 1 runs on a copy simplified to about as many (lib/mesh/simplify.ts); 0: never. */
  stage1Vertices: number;
}

/**
 * The options of a point cloud: every option but the mesh-only ones, and those only clouds have
 * (lib/core/options.ts, `shapes: 'cloud'`), which say how the cloud is made into a surface to compute on.
 */
export interface CloudOptions extends Omit<Options, 'stage1Vertices'> {
  /** Neighbours of each point (k of the kNN search) that its local triangulation is built from. */
  neighbours: number;
}

/** The options of a run on either kind of shape. */
export type ShapeOptions = Options | CloudOptions;

/** Why stage 1 produced no separator for a source ('ok' when it did). */
export type SeparatorStatus =
  | 'ok'
  | 'no-cut-locus'
  | 'no-target'
  | 'trace-failed'
  | 'degenerate-loop'
  | 'shorten-failed'
  | 'not-separating';

/** Points as xyz triples, one after the other. */
export type Polyline = Float64Array;

/** The locality constraint of paper Sec. 4.1.6: a ball around the source. */
export interface Sphere {
  center: [number, number, number];
  radius: number;
}

/** Why a loop on a cloud has no shortened loop ('ok' when it has one). */
export type ShortenStatus = 'ok' | 'degenerate-loop' | 'not-converged';

/** A closed loop shortened on a point cloud (Cloud.shortenLoop; docs/pointcloud.md, "Loop shortening on clouds"). */
export interface ShortenedCloudLoop {
  status: ShortenStatus;
  /** What went wrong, for the user; empty when status is 'ok'. */
  message: string;
  /** On the cloud's MLS surface, the last point joined to the first; empty when degenerate (the last iterate when not converged). */
  loop: Polyline;
  length: number;
  /** Areas of the two sides of the loop inside the constraint region, A1 <= A2 (as a Separator's). */
  areas: [number, number];
  /** Gradient steps taken. */
  iterations: number;
  /** With `recordFrames`: the loop as resampled from the input, evenly spaced steps and the last, at most recordFrames loops. */
  iterates: Polyline[];
}

/** Stage 1 of CSCD-M for one source, with every intermediate result (paper Sec. 4.1, Alg. 2). */
export interface Separator {
  source: number;
  status: SeparatorStatus;
  /** What went wrong, for the user; empty when status is 'ok'. */
  message: string;
  /** Geodesic distance from the source, per vertex. */
  distance: Float64Array;
  cutLocus: {
    /** Graph nodes as vertex indices, their positions (xyz) and edges (pairs of node indices). */
    vertices: Uint32Array;
    points: Float64Array;
    edges: Uint32Array;
    /** Per-vertex fields the detector used (radians; scale-free Laplacian). */
    angleDeviation: Float64Array;
    laplacian: Float64Array;
    /** The vertex farthest from the source, where the cut locus is grown from. */
    root: number;
    cycleRank: number;
  };
  /** Boundary vertices where the distance is lowest along the boundary (its gradient normal to it). */
  boundaryExtremities: { vertices: Uint32Array; points: Float64Array };
  /** Target cut-locus vertex and its position, or null (none found, or the separator is a path). */
  target: number | null;
  /** Targets tried: the nearest first, farther ones when a loop enclosed nothing. */
  attempts: number;
  targetPoint: [number, number, number] | null;
  /**
   * The two boundary extremities an open separator runs between (on one boundary loop, distance
   * gradients opposed: paper Sec. 3.2), vertex indices and positions; null for a loop.
   */
  ends: Uint32Array | null;
  endPoints: Float64Array | null;
  /** False when the separator is an open path between `ends` rather than a closed loop. */
  closed: boolean;
  /** The two steepest-descent paths from the target (or the two ends), as polylines on the surface. */
  paths: [Polyline, Polyline];
  /** Their concatenation: a closed loop (last point joins the first), or the open path. */
  approxLoop: Polyline;
  /** The loop (or path) after edge-flip shortening, on the surface. */
  loop: Polyline;
  /** The locality constraint (null when switched off). */
  sphere: Sphere | null;
  approxLength: number;
  length: number;
  /** Surface areas of the two sides of the loop inside the constraint region, A1 <= A2. */
  areas: [number, number];
  /** A1 / (A2 * length) (paper Sec. 4.2.1). */
  score: number;
  /** Whether the loop's centroid lies inside the shape (winding number > 1/2); true for paths. */
  centroidInside: boolean;
  /** Milliseconds per stage. */
  timings: Record<string, number>;
  /**
   * Set by a RefinedSurface: how the mesh was refined (null: not at all). Then `distance` and the
   * cut locus's per-vertex fields hold the input's vertices, while vertex indices (cut-locus nodes,
   * target, ends) may name vertices the refinement added (>= the input's count; their points are given).
   */
  refined?: Refinement | null;
}

/** What became of a candidate separator in stage 2. */
export type CandidateFate = 'packed' | 'overlapping' | 'short' | 'outside' | 'failed';

/** The curve skeleton and what led to it (paper Sec. 4.2, Alg. 1). */
export interface Skeleton {
  /** Node positions (xyz) and radii: the radius of the tube that best fits the surface around the node. */
  nodes: Float64Array;
  radii: Float64Array;
  /** Pairs of node indices. */
  edges: Uint32Array;
  /** Skeleton node of every input vertex: the nearest node along the skeleton from its band piece; each node's vertices are connected. */
  vertexToNode: Uint32Array;
  /** Every candidate of stage 1: its source, loop, score and fate. */
  candidates: {
    sources: Uint32Array;
    loops: Polyline[];
    /** 1 for a closed loop, 0 for a path ending on the boundary. */
    closed: Uint8Array;
    scores: Float64Array;
    fates: CandidateFate[];
  };
  /** The packed separators' indices into candidates, in the order of their regions (stage 2 cuts a region into band nodes, so node numbers are not region numbers). */
  packed: Uint32Array;
  stats: {
    /** Sources tried (N; the one chosen in auto mode). */
    n: number;
    /** Sources whose stage 1 found a loop. */
    candidates: number;
    pruned: number;
    packed: number;
    /** Independent cycles of the skeleton graph (E - V + components). */
    cycles: number;
    seed: number;
    /** Milliseconds per stage. */
    timings: Record<string, number>;
    /** Set by a RefinedSurface: how the mesh was refined (null: not at all); vertexToNode then holds the input's vertices. */
    refined?: Refinement | null;
    /** Set by a RefinedSurface: how the mesh was simplified for stage 1 (null: not at all); `candidates.sources` are then the copy's vertices. */
    simplified?: Simplification | null;
  };
}

/** Progress of a pipeline run: sources done out of the total (the total may shrink in auto mode). */
export interface PipelineProgress {
  done: number;
  total: number;
  /** True once no more sources will be tried. */
  finished: boolean;
  /** The loops found by this step's sources (empty polylines for failed sources), for progressive display. */
  newLoops: Polyline[];
  /** Per new loop: 1 closed, 0 a path ending on the boundary. */
  newClosed: Uint8Array;
}

/**
 * A stage-1 candidate as it crosses from the worker that computed it to the pipeline that draws the
 * rounds: exact (the same bits whichever worker computed it). `points` and `reach` are the
 * realization's own part (on a mesh: the loop's surface points as element kind, index and
 * coordinates, and the distance field of what it covers).
 */
export interface CandidateRecord {
  source: number;
  found: boolean;
  loop: Polyline;
  closed: boolean;
  length: number;
  score: number;
  centroidInside: boolean;
  /** On a mesh: the loop's surface points; on a cloud: the point nearest to each loop point. */
  points?: { kinds: Uint8Array; elements: Uint32Array; coords: Float64Array } | Uint32Array;
  /** The geodesic distance from the loop and the source per vertex (or point), what the candidate covers. */
  reach?: Float64Array;
}

/**
 * The whole CSCD-M pipeline as a resumable job: `step` runs a few sources of stage 1 (so callers can
 * report progress and cancel between steps), `finish` runs stage 2 and returns the skeleton.
 * Stage 1 draws `drawAhead` sources ahead of the candidates it has taken; a pool of workers runs it as
 * `draw` here, `separators` of the drawn sources on pipelines of the same mesh and options anywhere,
 * then `accept` here of their candidates in draw order (and `draw` again): the same skeleton as
 * `step`, whatever the number of workers.
 */
export interface Pipeline {
  step(sources: number): PipelineProgress;
  /** The sources drawn since the last call (as many as `accept` took candidates since; none once stage 1 is done). */
  draw(): Uint32Array;
  /** Stage 1 from these sources, drawing and keeping nothing (a pool worker's share). */
  separators(sources: Uint32Array): CandidateRecord[];
  /** The candidates of the oldest sources drawn and not taken yet, in draw order (any number of them). */
  accept(records: CandidateRecord[]): PipelineProgress;
  finish(): Skeleton;
  dispose(): void;
}

/** Per-mesh state kept in the core: prefactored geodesic solver on the intrinsic Delaunay triangulation. */
export interface Surface {
  readonly facts: MeshFacts;
  /** Geodesic distance (heat method) from one vertex to every vertex. */
  distanceFromVertex(vertex: number): Float64Array;
  /** Test-only: exact polyhedral geodesic distance (MMP) from one vertex, the reference the tests hold the heat method to. */
  exactDistanceFromVertex(vertex: number): Float64Array;
  /** Test-only: geodesic distance from the nearest of a set of surface points to every vertex (the solve regions and sampling use inside the core). */
  distanceFromPoints(points: SurfacePoint[]): Float64Array;
  /** Stage 1 for one source vertex; per-mesh data is reused, so repeated calls are cheap. */
  separator(source: number, options?: Partial<Options>): Separator;
  /**
   * The whole pipeline, as a resumable job (see Pipeline). With `working` (a surface of this core on a
   * simplified copy of this mesh, lib/mesh/simplify.ts): stage 1 runs there, stage 2 here.
   */
  pipeline(options?: Partial<Options>, working?: Surface): Pipeline;
  /** The whole pipeline in one call. */
  skeleton(options?: Partial<Options>): Skeleton;
  /** Frees the WASM-side object; the Surface must not be used afterwards. */
  dispose(): void;
}

/**
 * A Surface on a mesh as given whose computations run on the mesh refined when it is coarse
 * (Core.openRefinedSurface, lib/mesh/refine.ts). `facts`, source vertices, surface points and every
 * per-vertex output are those of the mesh as given (its vertices come first in the refined mesh).
 */
export interface RefinedSurface extends Surface {
  /** Its pipelines take no working surface: they choose it (lib/mesh/simplify.ts). */
  pipeline(options?: Partial<Options>): Pipeline;
  /** What was done to the mesh before opening the solver, or null: it is used as it is. */
  readonly refined: Refinement | null;
}

/** The graph a cloud's cut locus and loops run on (docs/pointcloud.md, "The graph"). */
export interface CloudNeighbourhood {
  /** Pairs of point indices: the local-triangulation edges that stay in the tangent planes. */
  edges: Uint32Array;
  /** Local-triangulation edges left out because they leave a tangent plane (they cross a gap between two parts). */
  bridgesRemoved: number;
  /**
   * Whether the cloud is noisy (the MLS surface fits no curvature under the noise at most points): then an
   * edge that leaves a tangent plane is tested again between its ends' MLS projections (docs/pointcloud.md).
   */
  noisy: boolean;
  /** Edges kept by that second test (0 on a clean cloud). */
  keptOnMls: number;
  /** Connected components of the graph. */
  components: number;
}

/**
 * Stage 1 of CSCD-PC for one source as far as the approximate loop (paper Sec. 4.1.2-4.1.4 on clouds),
 * named as the mesh's Separator; point indices where the mesh has vertex indices.
 */
export interface CloudSeparatorStages {
  source: number;
  /**
   * 'ok', 'no-cut-locus', 'no-target', 'trace-failed' (no target with two opposite incoming gradients and
   * a loop), 'degenerate-loop' (the loop shrank to nothing) or 'shorten-failed' (it did not settle).
   */
  status: SeparatorStatus;
  message: string;
  /** Geodesic distance from the source, per point. */
  distance: Float64Array;
  cutLocus: Separator['cutLocus'] & {
    /** Points that pass both the angle and the Laplacian test, and the connected pieces they form in the graph before the tree bridges them. */
    passingPoints: number;
    passingPieces: number;
  };
  /** The distance's gradient at every point, xyz (in its tangent plane; 0 outside the source's part of the graph). */
  gradient: Float64Array;
  /** Cut-locus points that qualify as targets, the nearest first. */
  targets: Uint32Array;
  /** The target the loop runs through, or null. */
  target: number | null;
  targetPoint: [number, number, number] | null;
  /** Targets tried: the next one when the incoming gradients at one were not opposite. */
  attempts: number;
  /** The two descending paths from the target, as polylines and as point indices (target first, meeting point last). */
  paths: [Polyline, Polyline];
  pathPoints: [Uint32Array, Uint32Array];
  /** The closed loop they form (the last point joins the first), as a polyline and as point indices. */
  approxLoop: Polyline;
  approxLoopPoints: Uint32Array;
  /** The sphere through the approximate loop's farthest point (option sphere), or null. */
  sphere: Sphere | null;
  /** The loop shortened on the cloud's MLS surface (empty unless ok), its length, side areas, score, the centroid test. */
  loop: Polyline;
  length: number;
  areas: [number, number];
  score: number;
  centroidInside: boolean;
  /** Descent steps of the shortening. */
  iterations: number;
  /** With `recordFrames`: the shortening's loops, as ShortenedCloudLoop.iterates. */
  iterates: Polyline[];
  /** Milliseconds per stage. */
  timings: Record<string, number>;
}

/**
 * Per-cloud state kept in the core (CSCD-PC): the k nearest neighbours, the tufted intrinsic
 * triangulation built from them and its prefactored geodesic solver.
 */
export interface Cloud {
  readonly facts: CloudFacts;
  /** Geodesic distance (heat method) from one point to every point; Infinity in other components. */
  distance(source: number): Float64Array;
  /** CSCD-PC as a resumable job (the mesh's Pipeline on the cloud: the same steps, rounds and records). */
  pipeline(options?: Partial<Options>): Pipeline;
  /** The whole of CSCD-PC in one call; `vertexToNode` gives each point its node. */
  skeleton(options?: Partial<Options>): Skeleton;
  /** Test-only: the same by geometry-central's PointCloudHeatSolver, which `distance` replaces (docs/pointcloud.md). */
  referenceDistance(source: number): Float64Array;
  /** Test-only: geodesic distance from the nearest of several points to every point. */
  distanceFromPoints(sources: number[]): Float64Array;
  /** Test-only: the generalised winding number (about 1 inside, 0 outside) at xyz positions, one per point. */
  windingNumbers(points: Float64Array): Float64Array;
  /**
   * Whether each point (xyz triples) is inside the shape, 1 or 0, as the centroid test and node placement
   * decide it: the winding number over one half on a clean cloud; on a noisy one, not joined to the
   * outside by empty space (docs/pointcloud.md, "Inside a noisy cloud"). On a noisy cloud the centroid
   * test also passes a loop round a tube the scan left open, whose centroid this puts outside
   * (docs/pointcloud.md, "Scans open at an end").
   */
  inside(points: Float64Array): Uint8Array;
  /**
   * Points (xyz triples) projected on the cloud's MLS surface, its unit normals there (of arbitrary sign)
   * and whether the quadratic height was fitted (1; 0: the plane alone, where the cloud is noisy or sparse).
   */
  project(points: Polyline): { points: Polyline; normals: Float64Array; quadratic: Uint8Array };
  /**
   * A closed polyline (xyz triples, at least 3 points, last not repeating the first) shortened on the
   * cloud, kept near `sphere` by the paper's penalty; `recordFrames` (0, or 2 and more) keeps that many
   * iterates for animation.
   */
  shortenLoop(polyline: Polyline, options?: { sphere?: Sphere | null; recordFrames?: number }): ShortenedCloudLoop;
  /** The graph the cut locus and loops run on (built on first use). */
  neighbourhood(): CloudNeighbourhood;
  /** Stage 1 for one source, every step kept (tests, teaching views, `cscd separator`), with `recordFrames` of the shortening's loops. */
  separatorStages(source: number, options?: Partial<Options>, recordFrames?: number): CloudSeparatorStages;
  /** Frees the WASM-side object; the Cloud must not be used afterwards. */
  dispose(): void;
}

/** A curve skeleton from any tool, as the evaluation takes it. */
export interface SkeletonInput {
  /** Node positions, xyz per node. */
  nodes: Float64Array;
  /** Pairs of node indices. */
  edges: Uint32Array;
  /** One radius per node; null or absent: derived from the mesh (see docs/evaluation.md). */
  radii?: Float64Array | null;
}

/**
 * The paper's reconstruction error of a skeleton (Sec. 5, App. "Evaluation metric"): the skeleton's
 * convolution surface against the mesh's vertices. Errors are squared distances on the mesh scaled to
 * unit bounding-box diagonal, times 1000 (the paper's unit).
 */
export interface Evaluation {
  /** Mean over the mesh's vertices of the squared distance to the reconstructed surface (x1e3). */
  reconError: number;
  median: number;
  p95: number;
  nodes: number;
  /** Independent cycles of the skeleton graph (self-loops and repeated edges left out). */
  cycles: number;
  radiiSource: 'given' | 'derived';
  /** The radii the reconstruction used. */
  radii: Float64Array;
  /** Error per input vertex (x1e3; 0 for vertices used by no face). */
  vertexError: Float64Array;
  /** The reconstructed (convolution) surface. */
  surface: { positions: Float32Array; triangles: Uint32Array };
  /** The marching-cubes grid: cell size (mesh units) and points per axis. */
  grid: { cell: number; dims: [number, number, number] };
  /** Milliseconds per step. */
  timings: Record<string, number>;
}

/** The mesh a pool worker opens to compute stage 1's separators (Core.stage1Input). */
export interface Stage1Input {
  mesh: MeshArrays;
  /**
   * false: `mesh` is what stage 1 runs on, open it as given (a simplified copy; in the page, the mesh
   * the geometry worker computes on); true: `mesh` is as given by the user, open it refined when coarse
   * (Core.openStage1Surface).
   */
  refine: boolean;
}

export interface Core {
  /** Checks the arrays (throws CoreError on empty input, bad indices, NaN/Inf) and reports mesh facts. */
  inspect(mesh: MeshArrays): MeshFacts;
  /** Builds the per-mesh state; throws CoreError when the mesh cannot be processed (e.g. non-manifold). */
  openSurface(mesh: MeshArrays): Surface;
  /**
   * openSurface on `mesh` refined when it is coarse (the same surface, sampled densely enough for
   * CSCD-M), with results per vertex of `mesh`: what every consumer that computes on a user's mesh uses.
   */
  openRefinedSurface(mesh: MeshArrays): RefinedSurface;
  /**
   * The surface a RefinedSurface's pipeline on `mesh` with `options` runs stage 1 on (refined when
   * coarse, a simplified copy when larger than `options.stage1Vertices`): what a pool worker computes
   * separators on.
   */
  openStage1Surface(mesh: MeshArrays, options?: Partial<Options>): Surface;
  /**
   * What stage 1 of openRefinedSurface(mesh).pipeline(options) runs on, for a pool worker to open: a
   * large mesh is simplified here, once (the caller's pipeline reuses the copy), not again in each worker.
   */
  stage1Input(mesh: MeshArrays, options?: Partial<Options>): Stage1Input;
  /**
   * Builds the per-cloud state (of a cloud that passed checkCloud, lib/io/cloud-check.ts); only the
   * cloud-only options matter to it. Throws CoreError when the cloud cannot be processed.
   */
  openCloud(cloud: CloudArrays, options?: Partial<CloudOptions>): Cloud;
  /** The reconstruction error of a skeleton against a mesh (the mesh need not be manifold). */
  evaluate(mesh: MeshArrays, skeleton: SkeletonInput): Evaluation;
  /** The same against a point cloud's points (radii, when derived, fitted around the points). */
  evaluateCloud(cloud: CloudArrays, skeleton: SkeletonInput): Evaluation;
  /**
   * The core's memory in MB: its WebAssembly memory, which grows as the core needs and never shrinks,
   * so this is the most it has used so far (for the bench's memory per worker).
   */
  memoryMB(): number;
  /** Test-only: the option defaults, ranges and auto-N constants the core declares (lib/core/options.ts must agree). */
  optionLimits(): { defaults: Record<string, unknown>; ranges: Record<string, [number, number]>; autoN: Record<string, number> };
}

/**
 * What kind of failure a CoreError is: the input or the arguments (the user can fix them), memory (the
 * heap or the memory limit is too small for the mesh: decimate it), or internal (a library failed).
 */
export type CoreErrorKind = 'input' | 'memory' | 'internal';

/** An error the core reports about its input or a computation: its message is meant for the user. */
export class CoreError extends Error {
  override name = 'CoreError';
  constructor(
    message: string,
    readonly kind: CoreErrorKind = 'input',
  ) {
    super(message);
  }
}
