// Types of the embind module built from wasm/src/bindings/ (bindings.cpp registers it; copied next to
// the generated build/wasm/cscd.js by scripts/build-wasm.sh). Failing calls return a CoreFailure instead of their result.

/** What a failing call returns: the kind of failure (input, memory, internal) and a message for the user. */
export interface CoreFailure {
  coreError: 'input' | 'memory' | 'internal';
  message: string;
}
export interface SurfaceHandle {
  error(): CoreFailure | null;
  facts(): unknown;
  distanceFromVertex(vertex: number): Float64Array | CoreFailure;
  exactDistanceFromVertex(vertex: number): Float64Array | CoreFailure;
  separator(source: number, options: object): object | CoreFailure;
  distanceFromPoints(faces: Uint32Array, barycentric: Float64Array): Float64Array | CoreFailure;
  delete(): void;
}

export interface PipelineHandle {
  error(): CoreFailure | null;
  step(sources: number): object | CoreFailure;
  draw(): Uint32Array | CoreFailure;
  separators(sources: Uint32Array): object[] | CoreFailure;
  accept(records: object[]): object | CoreFailure;
  finish(): object | CoreFailure;
  delete(): void;
}

export interface CloudHandle {
  error(): CoreFailure | null;
  facts(): unknown;
  distance(point: number): Float64Array | CoreFailure;
  referenceDistance(point: number): Float64Array | CoreFailure;
  distanceFromPoints(points: Float64Array): Float64Array | CoreFailure;
  windingNumbers(points: Float64Array): Float64Array | CoreFailure;
  inside(points: Float64Array): Uint8Array | CoreFailure;
  project(points: Float64Array): object | CoreFailure;
  shortenLoop(polyline: Float64Array, options: object): object | CoreFailure;
  neighbourhood(): object | CoreFailure;
  separatorStages(source: number, options: object, recordFrames: number): object | CoreFailure;
  delete(): void;
}

export interface CscdModule {
  inspect(positions: Float64Array | Float32Array, triangles: Uint32Array): object | CoreFailure;
  evaluate(
    positions: Float64Array | Float32Array,
    triangles: Uint32Array,
    nodes: Float64Array,
    edges: Uint32Array,
    radii: Float64Array | null,
  ): object | CoreFailure;
  evaluateCloud(positions: Float64Array, nodes: Float64Array, edges: Uint32Array, radii: Float64Array | null): object | CoreFailure;
  /** Test-only: the core's option defaults, ranges and auto-N constants. */
  optionLimits(): { defaults: Record<string, unknown>; ranges: Record<string, [number, number]>; autoN: Record<string, number> };
  Surface: new (positions: Float64Array | Float32Array, triangles: Uint32Array) => SurfaceHandle;
  /** With `given`: stage 1 on `surface` (a simplified copy), stage 2 and the skeleton on `given`. */
  Pipeline: new (surface: SurfaceHandle, options: object, given?: SurfaceHandle) => PipelineHandle;
  Cloud: new (positions: Float64Array, normals: Float32Array | null, options: object) => CloudHandle;
  CloudPipeline: new (cloud: CloudHandle, options: object) => PipelineHandle;
}

export interface CscdModuleOptions {
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** The module's memory (it is linked with -sIMPORTED_MEMORY): its maximum caps the heap. */
  wasmMemory?: WebAssembly.Memory;
  locateFile?: (path: string, prefix: string) => string;
  /** Instantiates the module from the caller's own compiled WebAssembly.Module (e.g. one shared by workers). */
  instantiateWasm?: (imports: WebAssembly.Imports, receive: (instance: WebAssembly.Instance, module: WebAssembly.Module) => void) => object;
  print?: (text: string) => void;
  printErr?: (text: string) => void;
  onAbort?: (what: unknown) => void;
}

export default function createCscdModule(options?: CscdModuleOptions): Promise<CscdModule>;
