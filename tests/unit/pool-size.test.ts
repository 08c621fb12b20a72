// How many threads stage 1 runs on (lib/core/pool-size.ts): auto takes every core but one, fewer when
// a quarter of the memory cannot hold that many cores on the mesh, never more than a round's sources;
// a number is taken as asked, within the round.
import { describe, expect, it } from 'vitest';
import { coreMemoryMB, poolSize, type PoolSizeInput } from '../../lib/core/pool-size.ts';

const base: PoolSizeInput = { workers: 'auto', cores: 8, memoryGB: 8, vertices: 20_000, drawAhead: 8, sourcesLeft: 400 };

describe('coreMemoryMB', () => {
  it('grows with the mesh from the core initial 64 MB, as measured (docs/parallel.md)', () => {
    expect(coreMemoryMB(3_000)).toBe(64);
    expect(coreMemoryMB(48_485)).toBeCloseTo(32 + 0.00536 * 48_485, 6); // horse: measured 275 MB
    expect(coreMemoryMB(1_000_000)).toBeCloseTo(5392, 6);
  });
});

describe('poolSize', () => {
  it('auto: every core but one when memory and the round allow', () => {
    expect(poolSize(base)).toEqual({ workers: 7, memoryCapped: false });
    expect(poolSize({ ...base, cores: 2 })).toEqual({ workers: 1, memoryCapped: false });
    expect(poolSize({ ...base, cores: 1 })).toEqual({ workers: 1, memoryCapped: false });
  });

  it('auto: no more than a round has sources, nor than are left', () => {
    expect(poolSize({ ...base, drawAhead: 1 })).toEqual({ workers: 1, memoryCapped: false });
    expect(poolSize({ ...base, drawAhead: 4 })).toEqual({ workers: 4, memoryCapped: false });
    expect(poolSize({ ...base, sourcesLeft: 3 })).toEqual({ workers: 3, memoryCapped: false });
  });

  it('auto: a quarter of the memory (2 GB when unknown) over the estimate per core, the calling thread counted', () => {
    // 1M vertices: 5392 MB per core; a quarter of 8 GB holds none, so the caller's thread alone.
    expect(poolSize({ ...base, vertices: 1_000_000 })).toEqual({ workers: 1, memoryCapped: true });
    // 100K vertices: 568 MB per core; 2048 MB hold 3 cores: 2 workers and the caller's.
    expect(poolSize({ ...base, vertices: 100_000 })).toEqual({ workers: 2, memoryCapped: true });
    expect(poolSize({ ...base, vertices: 100_000, memoryGB: null })).toEqual({ workers: 2, memoryCapped: true });
    // 200K vertices: 1104 MB per core; 2048 MB hold 1 core, too few for a pool; 8192 MB (32 GB) hold 7: 6 workers, one fewer than the cores allow.
    expect(poolSize({ ...base, vertices: 200_000 })).toEqual({ workers: 1, memoryCapped: true });
    expect(poolSize({ ...base, vertices: 200_000, memoryGB: 32 })).toEqual({ workers: 6, memoryCapped: true });
    // 32 GB and 100K vertices: 8192 MB hold 14 cores, cut by the cores to 7.
    expect(poolSize({ ...base, vertices: 100_000, memoryGB: 32 })).toEqual({ workers: 7, memoryCapped: false });
    // Capped by the round, not by memory: nothing to say about memory.
    expect(poolSize({ ...base, vertices: 200_000, memoryGB: 32, drawAhead: 2 })).toEqual({ workers: 2, memoryCapped: false });
  });

  it('a number: as asked, but no more than the round has sources', () => {
    expect(poolSize({ ...base, workers: 3, cores: 2, vertices: 1_000_000 })).toEqual({ workers: 3, memoryCapped: false });
    expect(poolSize({ ...base, workers: 16 })).toEqual({ workers: 8, memoryCapped: false });
    expect(poolSize({ ...base, workers: 4, sourcesLeft: 2 })).toEqual({ workers: 2, memoryCapped: false });
  });
});
