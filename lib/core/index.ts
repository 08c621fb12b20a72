// The CSCD core for TypeScript callers (CLI, worker, tests): a thin layer over the embind module that
// turns its failures into CoreError (of their kind) and frees WASM objects through dispose().
import createCscdModule, {
  type CloudHandle,
  type CoreFailure,
  type CscdModule,
  type CscdModuleOptions,
  type PipelineHandle,
  type SurfaceHandle,
} from '../../build/wasm/cscd.js';
import { refine, refinedPoint, refinementOf, skeletonForInput } from '../mesh/refine.ts';
import { stage1Mesh } from '../mesh/simplify.ts';
import {
  CoreError,
  type CandidateRecord,
  type Cloud,
  type CloudArrays,
  type CloudFacts,
  type CloudNeighbourhood,
  type CloudOptions,
  type CloudSeparatorStages,
  type Core,
  type Evaluation,
  type MeshArrays,
  type MeshFacts,
  type Options,
  type Pipeline,
  type PipelineProgress,
  type Polyline,
  type RefinedSurface,
  type Refinement,
  type Simplification,
  type Separator,
  type ShortenedCloudLoop,
  type Skeleton,
  type Sphere,
  type SkeletonInput,
  type Stage1Input,
  type Surface,
  type SurfacePoint,
} from './types.ts';

export * from './types.ts';
import { defaultOptions } from './options.ts';
import { CORE_MEMORY } from './pool-size.ts';
export { defaultOptions };

/** Turns the core's failures into CoreError; `unwrap(x)` returns x when it is not one. */
type Unwrap = <T>(result: T | CoreFailure) => T;

const isFailure = (x: unknown): x is CoreFailure => typeof x === 'object' && x !== null && 'coreError' in x;

/** WebAssembly memory pages are 64 KiB. */
const PAGE_BYTES = 65536;
/** The core's own maximum (wasm/CMakeLists.txt -sMAXIMUM_MEMORY) and its initial size (-sINITIAL_MEMORY). */
const { initialMB: CORE_INITIAL_MB, maximumMB: CORE_MAXIMUM_MB } = CORE_MEMORY;

/** What shrinks each kind of shape when the core runs out of memory. */
const SHRINK = { mesh: 'decimate it to fewer faces', 'point cloud': 'subsample it to fewer points' } as const;

/** A failed allocation (kind memory) gets the limit that was hit and what to do about it. */
function unwrapper(memoryLimitMB: number, shape: keyof typeof SHRINK): Unwrap {
  return <T>(result: T | CoreFailure): T => {
    if (!isFailure(result)) return result;
    if (result.coreError === 'memory') {
      throw new CoreError(`out of memory: the ${shape} needs more than ${memoryLimitMB} MB; ${SHRINK[shape]} and try again`, 'memory');
    }
    throw new CoreError(result.message, result.coreError);
  };
}

/** An object just made in the core (its constructor cannot throw into JS): it, or its failure thrown as a CoreError. */
function opened<H extends { error(): CoreFailure | null; delete(): void }>(handle: H, unwrap: Unwrap): H {
  const error = handle.error();
  if (error) {
    handle.delete();
    unwrap(error);
  }
  return handle;
}

/** A wrapper that owns an object of the core: dispose() frees it once, and later calls are refused. */
abstract class Owner<H extends { delete(): void }> {
  private handle: H | null;

  constructor(
    handle: H,
    private readonly what: string,
  ) {
    this.handle = handle;
  }

  dispose(): void {
    this.handle?.delete();
    this.handle = null;
  }

  protected live(): H {
    if (!this.handle) throw new CoreError(`this ${this.what} has been disposed`);
    return this.handle;
  }
}

class WasmPipeline extends Owner<PipelineHandle> implements Pipeline {
  constructor(
    handle: PipelineHandle,
    private readonly unwrap: Unwrap,
  ) {
    super(handle, 'pipeline');
  }

  step(sources: number): PipelineProgress {
    return this.unwrap(this.live().step(sources)) as PipelineProgress;
  }

  draw(): Uint32Array {
    return this.unwrap(this.live().draw());
  }

  separators(sources: Uint32Array): CandidateRecord[] {
    return this.unwrap(this.live().separators(sources)) as CandidateRecord[];
  }

  accept(records: CandidateRecord[]): PipelineProgress {
    return this.unwrap(this.live().accept(records)) as PipelineProgress;
  }

  finish(): Skeleton {
    return this.unwrap(this.live().finish()) as Skeleton;
  }
}

class WasmSurface extends Owner<SurfaceHandle> implements Surface {
  readonly facts: MeshFacts;

  constructor(
    handle: SurfaceHandle,
    private readonly module: CscdModule,
    private readonly unwrap: Unwrap,
  ) {
    super(handle, 'surface');
    this.facts = handle.facts() as MeshFacts;
  }

  distanceFromVertex(vertex: number): Float64Array {
    return this.unwrap(this.live().distanceFromVertex(vertex));
  }

  exactDistanceFromVertex(vertex: number): Float64Array {
    return this.unwrap(this.live().exactDistanceFromVertex(vertex));
  }

  separator(source: number, options: Partial<Options> = {}): Separator {
    return this.unwrap(this.live().separator(source, options)) as Separator;
  }

  /** The pipeline on this surface, or with `working`: stage 1 there (a simplified copy), stage 2 here. */
  pipeline(options: Partial<Options> = {}, working?: Surface): Pipeline {
    if (working && !(working instanceof WasmSurface)) throw new CoreError('the working surface must be one of this core', 'input');
    const handle = working ? new this.module.Pipeline(working.live(), options, this.live()) : new this.module.Pipeline(this.live(), options);
    return new WasmPipeline(opened(handle, this.unwrap), this.unwrap);
  }

  skeleton(options: Partial<Options> = {}): Skeleton {
    return skeletonOf(this, options);
  }

  distanceFromPoints(points: SurfacePoint[]): Float64Array {
    const faces = Uint32Array.from(points, (p) => p.face);
    const barycentric = Float64Array.from(points.flatMap((p) => p.barycentric));
    return this.unwrap(this.live().distanceFromPoints(faces, barycentric));
  }
}

/** The whole pipeline of a surface or cloud in one call. */
function skeletonOf(shape: { pipeline(options: Partial<Options>): Pipeline }, options: Partial<Options>): Skeleton {
  const pipeline = shape.pipeline(options);
  try {
    return pipeline.finish();
  } finally {
    pipeline.dispose();
  }
}

/** A pipeline on the refined mesh (or with stage 1 on a simplified copy) whose skeleton is for the mesh as given. */
class RefinedPipeline implements Pipeline {
  constructor(
    private readonly inner: Pipeline,
    private readonly refined: Refinement | null,
    private readonly simplified: Simplification | null,
  ) {}

  step(sources: number): PipelineProgress {
    return this.inner.step(sources);
  }

  draw(): Uint32Array {
    return this.inner.draw();
  }

  separators(sources: Uint32Array): CandidateRecord[] {
    return this.inner.separators(sources);
  }

  accept(records: CandidateRecord[]): PipelineProgress {
    return this.inner.accept(records);
  }

  finish(): Skeleton {
    return skeletonForInput(this.inner.finish(), this.refined, this.simplified);
  }

  dispose(): void {
    this.inner.dispose();
  }
}

/** See RefinedSurface (types.ts): the solver is opened on the refined mesh, whose first vertices are the input's. */
class WasmRefinedSurface implements RefinedSurface {
  /** Stage 1's simplified copy (lib/mesh/simplify.ts) for the last `stage1Vertices` asked, opened by the first pipeline that needs it. */
  private working: { stage1Vertices: number; surface: WasmSurface } | null = null;

  constructor(
    private readonly inner: WasmSurface,
    readonly facts: MeshFacts,
    readonly refined: Refinement | null,
    /** Stage 1's mesh for a `stage1Vertices` when it is a simplified copy, else null. */
    private readonly stage1: (stage1Vertices: number) => { mesh: MeshArrays; simplified: Simplification } | null,
    private readonly open: (mesh: MeshArrays) => WasmSurface,
  ) {}

  distanceFromVertex(vertex: number): Float64Array {
    return this.cut(this.inner.distanceFromVertex(this.checked(vertex)));
  }

  exactDistanceFromVertex(vertex: number): Float64Array {
    return this.cut(this.inner.exactDistanceFromVertex(this.checked(vertex)));
  }

  distanceFromPoints(points: SurfacePoint[]): Float64Array {
    const levels = this.refined?.levels ?? 0;
    return this.cut(this.inner.distanceFromPoints(points.map((p) => refinedPoint(p.face, p.barycentric, levels))));
  }

  separator(source: number, options: Partial<Options> = {}): Separator {
    const result = this.inner.separator(this.checked(source), options);
    const { cutLocus } = result;
    return {
      ...result,
      distance: this.cut(result.distance),
      cutLocus: { ...cutLocus, angleDeviation: this.cut(cutLocus.angleDeviation), laplacian: this.cut(cutLocus.laplacian) },
      refined: this.refined,
    };
  }

  pipeline(options: Partial<Options> = {}): Pipeline {
    const stage1Vertices = options.stage1Vertices ?? defaultOptions.stage1Vertices;
    const stage1 = this.stage1(stage1Vertices);
    if (stage1 && this.working?.stage1Vertices !== stage1Vertices) {
      this.working?.surface.dispose();
      this.working = { stage1Vertices, surface: this.open(stage1.mesh) };
    }
    return new RefinedPipeline(this.inner.pipeline(options, stage1 ? this.working!.surface : undefined), this.refined, stage1?.simplified ?? null);
  }

  skeleton(options: Partial<Options> = {}): Skeleton {
    return skeletonOf(this, options);
  }

  dispose(): void {
    this.working?.surface.dispose();
    this.inner.dispose();
  }

  /** The vertex, when it is one of the input's (the refined mesh has more, which no caller can name). */
  private checked(vertex: number): number {
    if (!(Number.isInteger(vertex) && vertex >= 0 && vertex < this.facts.vertices)) {
      throw new CoreError(`vertex ${vertex} is out of range (the mesh has ${this.facts.vertices} vertices)`);
    }
    return vertex;
  }

  private cut(values: Float64Array): Float64Array {
    return this.refined ? values.slice(0, this.facts.vertices) : values;
  }
}

class WasmCloud extends Owner<CloudHandle> implements Cloud {
  readonly facts: CloudFacts;

  constructor(
    handle: CloudHandle,
    private readonly module: CscdModule,
    private readonly unwrap: Unwrap,
  ) {
    super(handle, 'cloud');
    this.facts = handle.facts() as CloudFacts;
  }

  distance(source: number): Float64Array {
    return this.unwrap(this.live().distance(source));
  }

  pipeline(options: Partial<Options> = {}): Pipeline {
    return new WasmPipeline(opened(new this.module.CloudPipeline(this.live(), options), this.unwrap), this.unwrap);
  }

  skeleton(options: Partial<Options> = {}): Skeleton {
    return skeletonOf(this, options);
  }

  referenceDistance(source: number): Float64Array {
    return this.unwrap(this.live().referenceDistance(source));
  }

  distanceFromPoints(sources: number[]): Float64Array {
    return this.unwrap(this.live().distanceFromPoints(Float64Array.from(sources)));
  }

  windingNumbers(points: Float64Array): Float64Array {
    return this.unwrap(this.live().windingNumbers(points));
  }

  inside(points: Float64Array): Uint8Array {
    return this.unwrap(this.live().inside(points));
  }

  project(points: Polyline): { points: Polyline; normals: Float64Array; quadratic: Uint8Array } {
    return this.unwrap(this.live().project(points)) as { points: Polyline; normals: Float64Array; quadratic: Uint8Array };
  }

  shortenLoop(polyline: Polyline, options: { sphere?: Sphere | null; recordFrames?: number } = {}): ShortenedCloudLoop {
    return this.unwrap(this.live().shortenLoop(polyline, options)) as ShortenedCloudLoop;
  }

  neighbourhood(): CloudNeighbourhood {
    return this.unwrap(this.live().neighbourhood()) as CloudNeighbourhood;
  }

  separatorStages(source: number, options: Partial<Options> = {}, recordFrames = 0): CloudSeparatorStages {
    return this.unwrap(this.live().separatorStages(source, options, recordFrames)) as CloudSeparatorStages;
  }
}

class WasmCore implements Core {
  private readonly unwrap: Unwrap;
  private readonly unwrapCloud: Unwrap;

  constructor(
    private readonly module: CscdModule,
    memoryLimitMB: number,
    private readonly memory: WebAssembly.Memory,
  ) {
    this.unwrap = unwrapper(memoryLimitMB, 'mesh');
    this.unwrapCloud = unwrapper(memoryLimitMB, 'point cloud');
  }

  memoryMB(): number {
    return this.memory.buffer.byteLength / (1024 * 1024);
  }

  inspect(mesh: MeshArrays): MeshFacts {
    return this.unwrap(this.module.inspect(mesh.positions, mesh.triangles)) as MeshFacts;
  }

  optionLimits() {
    return this.module.optionLimits();
  }

  evaluate(mesh: MeshArrays, skeleton: SkeletonInput): Evaluation {
    const result = this.module.evaluate(mesh.positions, mesh.triangles, skeleton.nodes, skeleton.edges, skeleton.radii ?? null);
    return this.unwrap(result) as Evaluation;
  }

  evaluateCloud(cloud: CloudArrays, skeleton: SkeletonInput): Evaluation {
    const result = this.module.evaluateCloud(cloud.positions, skeleton.nodes, skeleton.edges, skeleton.radii ?? null);
    return this.unwrapCloud(result) as Evaluation;
  }

  openSurface(mesh: MeshArrays): WasmSurface {
    return new WasmSurface(opened(new this.module.Surface(mesh.positions, mesh.triangles), this.unwrap), this.module, this.unwrap);
  }

  openCloud(cloud: CloudArrays, options: Partial<CloudOptions> = {}): Cloud {
    return new WasmCloud(opened(new this.module.Cloud(cloud.positions, cloud.normals, options), this.unwrapCloud), this.module, this.unwrapCloud);
  }

  openStage1Surface(mesh: MeshArrays, options: Partial<Options> = {}): Surface {
    const facts = this.inspect(mesh);
    const stage1 = stage1Mesh(mesh, facts, options.stage1Vertices ?? defaultOptions.stage1Vertices);
    return stage1 ? this.openSurface(stage1.mesh) : this.refinedSurface(mesh, facts);
  }

  stage1Input(mesh: MeshArrays, options: Partial<Options> = {}): Stage1Input {
    const stage1 = stage1Mesh(mesh, this.inspect(mesh), options.stage1Vertices ?? defaultOptions.stage1Vertices);
    return stage1 ? { mesh: stage1.mesh, refine: false } : { mesh, refine: true };
  }

  openRefinedSurface(mesh: MeshArrays): RefinedSurface {
    return this.refinedSurface(mesh, this.inspect(mesh));
  }

  private refinedSurface(mesh: MeshArrays, facts: MeshFacts): RefinedSurface {
    const refined = refinementOf(facts);
    return new WasmRefinedSurface(this.openSurface(refine(mesh, refined?.levels ?? 0)), facts, refined, (limit) => stage1Mesh(mesh, facts, limit), (m) => this.openSurface(m));
  }
}

export interface CoreSettings {
  /**
   * Most memory the core may use, in MB (at least 64, at most 4096, the default). Beyond it an
   * allocation fails and the call throws a CoreError "out of memory: …"; the memory is not returned to
   * the system afterwards (WebAssembly memory never shrinks), so a caller that needs it back starts a
   * new core.
   */
  memoryLimitMB?: number;
}

/**
 * Instantiates the WASM core from the bytes of build/wasm/cscd.wasm (fetched by the caller), or from
 * that file compiled once (a WebAssembly.Module: workers of one pool share the compile).
 */
export async function createCore(wasm: ArrayBuffer | Uint8Array | WebAssembly.Module, settings: CoreSettings = {}): Promise<Core> {
  const limit = Math.round(settings.memoryLimitMB ?? CORE_MAXIMUM_MB);
  if (!(limit >= CORE_INITIAL_MB && limit <= CORE_MAXIMUM_MB)) {
    throw new RangeError(`memoryLimitMB must be between ${CORE_INITIAL_MB} and ${CORE_MAXIMUM_MB}, got ${settings.memoryLimitMB}`);
  }
  const pages = (mb: number) => (mb * 1024 * 1024) / PAGE_BYTES;
  const compiled = wasm instanceof WebAssembly.Module ? wasm : null;
  const memory = new WebAssembly.Memory({ initial: pages(CORE_INITIAL_MB), maximum: pages(limit) });
  const moduleSettings: CscdModuleOptions = {
    ...(compiled
      ? {
          instantiateWasm: (imports, receive) => {
            void WebAssembly.instantiate(compiled, imports).then((instance) => receive(instance, compiled));
            return {};
          },
        }
      : { wasmBinary: wasm as ArrayBuffer | Uint8Array }),
    // The module is linked with -sIMPORTED_MEMORY and takes this memory; its maximum is the cap.
    wasmMemory: memory,
    // The module has no file system; anything it prints is a library diagnostic, kept off stdout.
    print: (text) => console.warn(`[cscd core] ${text}`),
    printErr: (text) => console.warn(`[cscd core] ${text}`),
  };
  const module = await createCscdModule(moduleSettings);
  return new WasmCore(module, limit, memory);
}
