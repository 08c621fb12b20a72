// The CSCD core for TypeScript callers (CLI, worker, tests): a thin layer over the embind module that
// turns its error strings into CoreError and frees WASM objects through dispose().
import createCscdModule, { type CscdModule, type PipelineHandle, type SurfaceHandle } from '../../build/wasm/cscd.js';
import {
  CoreError,
  type Core,
  type Evaluation,
  type MeshArrays,
  type MeshFacts,
  type Options,
  type Pipeline,
  type PipelineProgress,
  type Separator,
  type Skeleton,
  type SkeletonInput,
  type Surface,
  type SurfacePoint,
} from './types.ts';

export * from './types.ts';
export { defaultOptions } from './options.ts';

function unwrap<T>(result: T | string): T {
  if (typeof result === 'string') throw new CoreError(result);
  return result;
}

class WasmPipeline implements Pipeline {
  private handle: PipelineHandle | null;

  constructor(handle: PipelineHandle) {
    this.handle = handle;
  }

  step(sources: number): PipelineProgress {
    return unwrap(this.live().step(sources)) as PipelineProgress;
  }

  finish(): Skeleton {
    return unwrap(this.live().finish()) as Skeleton;
  }

  dispose(): void {
    this.handle?.delete();
    this.handle = null;
  }

  private live(): PipelineHandle {
    if (!this.handle) throw new CoreError('this pipeline has been disposed');
    return this.handle;
  }
}

class WasmSurface implements Surface {
  readonly facts: MeshFacts;
  private handle: SurfaceHandle | null;

  constructor(
    handle: SurfaceHandle,
    private readonly module: CscdModule,
  ) {
    this.handle = handle;
    this.facts = handle.facts() as MeshFacts;
  }

  distanceFromVertex(vertex: number): Float64Array {
    return unwrap(this.live().distanceFromVertex(vertex));
  }

  exactDistanceFromVertex(vertex: number): Float64Array {
    return unwrap(this.live().exactDistanceFromVertex(vertex));
  }

  separator(source: number, options: Partial<Options> = {}): Separator {
    return unwrap(this.live().separator(source, options)) as Separator;
  }

  pipeline(options: Partial<Options> = {}): Pipeline {
    const handle = new this.module.Pipeline(this.live(), options);
    const error = handle.error();
    if (error) {
      handle.delete();
      throw new CoreError(error);
    }
    return new WasmPipeline(handle);
  }

  skeleton(options: Partial<Options> = {}): Skeleton {
    const pipeline = this.pipeline(options);
    try {
      return pipeline.finish();
    } finally {
      pipeline.dispose();
    }
  }

  distanceFromPoints(points: SurfacePoint[]): Float64Array {
    const faces = Uint32Array.from(points, (p) => p.face);
    const barycentric = Float64Array.from(points.flatMap((p) => p.barycentric));
    return unwrap(this.live().distanceFromPoints(faces, barycentric));
  }

  dispose(): void {
    this.handle?.delete();
    this.handle = null;
  }

  private live(): SurfaceHandle {
    if (!this.handle) throw new CoreError('this surface has been disposed');
    return this.handle;
  }
}

class WasmCore implements Core {
  constructor(private readonly module: CscdModule) {}

  inspect(mesh: MeshArrays): MeshFacts {
    return unwrap(this.module.inspect(mesh.positions, mesh.triangles) as MeshFacts | string);
  }

  evaluate(mesh: MeshArrays, skeleton: SkeletonInput): Evaluation {
    const result = this.module.evaluate(mesh.positions, mesh.triangles, skeleton.nodes, skeleton.edges, skeleton.radii ?? null);
    return unwrap(result) as Evaluation;
  }

  openSurface(mesh: MeshArrays): Surface {
    const handle = new this.module.Surface(mesh.positions, mesh.triangles);
    const error = handle.error();
    if (error) {
      handle.delete();
      throw new CoreError(error);
    }
    return new WasmSurface(handle, this.module);
  }
}

/** Instantiates the WASM core from the bytes of build/wasm/cscd.wasm (fetched by the caller). */
export async function createCore(wasmBinary: ArrayBuffer | Uint8Array): Promise<Core> {
  const module = await createCscdModule({
    wasmBinary,
    // The module has no file system; anything it prints is a library diagnostic, kept off stdout.
    print: (text) => console.warn(`[cscd core] ${text}`),
    printErr: (text) => console.warn(`[cscd core] ${text}`),
  });
  return new WasmCore(module);
}
