// Types of the embind module built from wasm/src/bindings/bindings.cpp (copied next to the generated
// build/wasm/cscd.js by scripts/build-wasm.sh). Failing calls return the error message as a string.
export interface SurfaceHandle {
  error(): string;
  facts(): unknown;
  distanceFromVertex(vertex: number): Float64Array | string;
  exactDistanceFromVertex(vertex: number): Float64Array | string;
  separator(source: number, options: object): object | string;
  distanceFromPoints(faces: Uint32Array, barycentric: Float64Array): Float64Array | string;
  delete(): void;
}

export interface PipelineHandle {
  error(): string;
  step(sources: number): object | string;
  finish(): object | string;
  delete(): void;
}

export interface CscdModule {
  inspect(positions: Float64Array | Float32Array, triangles: Uint32Array): unknown;
  evaluate(
    positions: Float64Array | Float32Array,
    triangles: Uint32Array,
    nodes: Float64Array,
    edges: Uint32Array,
    radii: Float64Array | null,
  ): object | string;
  Surface: new (positions: Float64Array | Float32Array, triangles: Uint32Array) => SurfaceHandle;
  Pipeline: new (surface: SurfaceHandle, options: object) => PipelineHandle;
}

export interface CscdModuleOptions {
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** The module's memory (it is linked with -sIMPORTED_MEMORY): its maximum caps the heap. */
  wasmMemory?: WebAssembly.Memory;
  locateFile?: (path: string, prefix: string) => string;
  print?: (text: string) => void;
  printErr?: (text: string) => void;
  onAbort?: (what: unknown) => void;
}

export default function createCscdModule(options?: CscdModuleOptions): Promise<CscdModule>;
