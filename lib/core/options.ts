import type { Options } from './types.ts';

/** Defaults of every option (mirrors wasm/src/cscd/options.h; the tests check that they agree). */
export const defaultOptions: Readonly<Options> = Object.freeze({
  target: 'euclid',
  sphere: true,
  seed: 1,
  angleThreshold: 1.75,
  laplacianThreshold: 0.2,
  pruneDepth: 3,
  n: 'auto',
  pruneLengthFactor: 3,
});

/** Accepted ranges of the numeric options; the core checks the same (toOptions in bindings.cpp). */
export const optionRanges = Object.freeze({
  seed: [0, 0xffffffff],
  angleThreshold: [0, Math.PI],
  laplacianThreshold: [0, 1e6],
  pruneDepth: [0, 1000],
  n: [1, 100000],
  pruneLengthFactor: [0, 1000],
} as const);
