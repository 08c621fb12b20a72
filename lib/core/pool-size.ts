// How many threads stage 1 runs on (the `workers` run setting, lib/core/options.ts), the same rule in
// the page and the CLI. Each thread holds its own core with the mesh and its solver, so memory bounds
// K as well as the cores do (docs/parallel.md, "The page's pool").
import type { RunSettings } from './options.ts';

/**
 * A core's peak memory (Core.memoryMB) after a skeleton of 12 sources in rounds of 4, fitted as
 * a + b·V over 11 shared meshes of 2.9K-48K vertices (scripts/core-memory.ts, docs/parallel.md;
 * measured again 2026-12-03 with the loop patches' flat arrays); no core is below its initial 64 MB,
 * none above wasm32's 4096 MB (its default limit, lib/core/index.ts).
 */
export const CORE_MEMORY = Object.freeze({ baseMB: 32, perVertexMB: 0.00536, initialMB: 64, maximumMB: 4096 });

/** Estimated memory of one thread's core on a mesh of `vertices` vertices (the mesh computed on). */
export const coreMemoryMB = (vertices: number) => Math.max(CORE_MEMORY.initialMB, CORE_MEMORY.baseMB + CORE_MEMORY.perVertexMB * vertices);

/**
 * A cloud's core holds about as much per point as a mesh's per one and a half vertices (the
 * neighbourhood graph, the tufted triangulation, the MLS kd-tree): 191 MB after a skeleton of 12
 * sources on 20K-point clouds (bob_clean, horse_clean), 77 MB on 6.5K points, which the mesh fit above
 * gives at 30K and 8.4K vertices; so a cloud of P points is sized as a mesh of 1.5 P.
 */
export const CLOUD_VERTICES_PER_POINT = 1.5;

/** The memory budget of a pool when the machine's memory is not known. */
export const FALLBACK_BUDGET_MB = 2048;

export interface PoolSizeInput {
  workers: RunSettings['workers'];
  /** Logical cores (navigator.hardwareConcurrency, os.availableParallelism()). */
  cores: number;
  /** The machine's memory in GB (navigator.deviceMemory, os.totalmem()), or null when unknown. */
  memoryGB: number | null;
  /** Vertices of the mesh computed on. */
  vertices: number;
  drawAhead: number;
  /** Sources stage 1 may still draw (n, or the auto mode's most). */
  sourcesLeft: number;
}

export interface PoolSize {
  /** Threads that compute stage 1 (1: the caller's alone, no pool; K > 1: K beside the caller's, which only draws and accepts). */
  workers: number;
  /** auto gave fewer threads than the cores allow because of memory. */
  memoryCapped: boolean;
}

/**
 * auto: min(cores − 1, what a quarter of the memory (2 GB when unknown) holds, drawAhead, sources left), at least 1.
 * A pool of K holds K + 1 cores (the caller's too), so memory allows K when K + 1 cores fit.
 * A number is taken as asked, except that more threads than sources drawn ahead would idle.
 */
export function poolSize(input: PoolSizeInput): PoolSize {
  const useful = Math.max(1, Math.min(input.drawAhead, input.sourcesLeft));
  if (input.workers !== 'auto') return { workers: Math.min(input.workers, useful), memoryCapped: false };
  const byCores = Math.max(1, input.cores - 1);
  const budgetMB = input.memoryGB ? (input.memoryGB * 1024) / 4 : FALLBACK_BUDGET_MB;
  const byMemory = Math.max(1, Math.floor(budgetMB / coreMemoryMB(input.vertices)) - 1);
  const workers = Math.max(1, Math.min(byCores, byMemory, useful));
  return { workers, memoryCapped: byMemory < Math.min(byCores, useful) };
}
