// Loading the core in Node (CLI, tests): the WASM bytes are read from the build folder and handed over,
// because Emscripten 3.1.6's loader cannot fetch a file path under Node 20.
import { readFile } from 'node:fs/promises';
import { createCore, type Core, type CoreSettings } from './index.ts';

export * from './index.ts';

export const wasmPath = new URL('../../build/wasm/cscd.wasm', import.meta.url);

export async function loadCoreNode(settings: CoreSettings = {}): Promise<Core> {
  return createCore(await compiledCore(), settings);
}

let compiled: Promise<WebAssembly.Module> | null = null;

/** build/wasm/cscd.wasm compiled once per thread; a pool hands it to its threads (it can be posted). */
export function compiledCore(): Promise<WebAssembly.Module> {
  compiled ??= readFile(wasmPath).then((bytes) => WebAssembly.compile(bytes));
  return compiled;
}
