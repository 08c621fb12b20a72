import type { Options } from './types.ts';

/** Defaults of every option (mirrors wasm/src/cscd/options.h; the tests check that they agree). */
export const defaultOptions: Readonly<Options> = Object.freeze({
  target: 'euclid',
  sphere: true,
  seed: 1,
  angleThreshold: 1.75,
  laplacianThreshold: 0.2,
  pruneDepth: 3,
});
