// Types of the test module built from wasm/tests/toy_pipeline.cpp (copied next to build/wasm/cscd_toy.js
// by scripts/build-wasm.sh). Its Pipeline is the same binding template as the core's (cscd.d.ts).
import type { CoreFailure, CscdModuleOptions, PipelineHandle } from './cscd.js';

export interface ToyShapeHandle {
  error(): CoreFailure | null;
  delete(): void;
}

export interface ToyModule {
  ToyShape: new (kind: string) => ToyShapeHandle;
  Pipeline: new (shape: ToyShapeHandle, options: object) => PipelineHandle;
}

export default function createToyModule(options?: CscdModuleOptions): Promise<ToyModule>;
