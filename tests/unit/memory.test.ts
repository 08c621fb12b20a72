// A memory cap on the WASM core (createCore's memoryLimitMB): a solver that does not fit fails with a
// clear CoreError instead of taking the machine, and the same core keeps working afterwards.
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import { torus } from './support/meshes.ts';

const LIMIT_MB = 128;
let core: Core;
beforeAll(async () => {
  core = await loadCoreNode({ memoryLimitMB: LIMIT_MB });
});

describe('memory limit', () => {
  it('reports a solver that needs more than the limit as out of memory, naming the limit', () => {
    const big = torus(10, 3, 300, 300); // 180K faces: about 300 MB to prefactor
    expect(() => core.openSurface(big)).toThrowError(
      new RegExp(`^out of memory: the mesh needs more than ${LIMIT_MB} MB; decimate it`),
    );
  });

  it('keeps the core usable after an allocation failed', () => {
    const surface = core.openSurface(torus(10, 3, 40, 20));
    const distance = surface.distanceFromVertex(0);
    surface.dispose();
    expect(distance.length).toBe(800);
    expect(Math.max(...distance)).toBeGreaterThan(10);
  });

  it('reports its memory, which grows with the mesh and stays within the limit', async () => {
    const fresh = await loadCoreNode({ memoryLimitMB: LIMIT_MB });
    const before = fresh.memoryMB();
    expect(before).toBeGreaterThanOrEqual(64);
    const surface = fresh.openSurface(torus(10, 3, 200, 100)); // 40K faces
    surface.distanceFromVertex(0);
    surface.dispose();
    const after = fresh.memoryMB();
    expect(after).toBeGreaterThan(before);
    expect(after).toBeLessThanOrEqual(LIMIT_MB);
    expect(fresh.memoryMB()).toBe(after); // WebAssembly memory never shrinks: the peak so far
  });

  it('refuses a limit outside what the core can address', async () => {
    await expect(loadCoreNode({ memoryLimitMB: 16 })).rejects.toThrow(/memoryLimitMB must be between 64 and 4096/);
  });
});
