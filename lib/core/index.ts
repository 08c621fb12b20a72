// The CSCD core for TypeScript callers (CLI, worker, tests): a thin layer over the embind module that
// turns its error strings into CoreError and frees WASM objects through dispose().
import createCscdModule, { type CscdModule, type SurfaceHandle } from '../../build/wasm/cscd.js';
import {
  CoreError,
  type Core,
  type MeshArrays,
  type MeshFacts,
  type Options,
  type Separator,
  type Surface,
  type SurfacePoint,
} from './types.ts';

export * from './types.ts';
export { defaultOptions } from './options.ts';

function unwrap<T>(result: T | string): T {
  if (typeof result === 'string') throw new CoreError(result);
  return result;
}

class WasmSurface implements Surface {
  readonly facts: MeshFacts;
  private handle: SurfaceHandle | null;

  constructor(handle: SurfaceHandle) {
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

  openSurface(mesh: MeshArrays): Surface {
    const handle = new this.module.Surface(mesh.positions, mesh.triangles);
    const error = handle.error();
    if (error) {
      handle.delete();
      throw new CoreError(error);
    }
    return new WasmSurface(handle);
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
