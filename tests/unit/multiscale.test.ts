// Multiscale stage 1 (lib/mesh/simplify.ts, docs/multiscale.md): above `stage1Vertices` vertices the
// separators are computed on a simplified copy and mapped back; stage 2 and the skeleton are on the
// mesh as given. Small meshes with a small limit stand in for large ones with the default.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core, type MeshArrays, type Options, type Skeleton } from '../../lib/core/node.ts';
import { openNodePool, type NodePool } from '../../lib/core/node-pool.ts';
import { runStage1 } from '../../lib/core/pool.ts';
import { defaultOptions } from '../../lib/core/options.ts';
import { writeSkeletonJson } from '../../lib/io/skeleton.ts';
import { simplificationOf, stage1Mesh } from '../../lib/mesh/simplify.ts';
import { sharedMesh } from '../paths.ts';
import { readMesh } from './support/meshes.ts';

const MESH: MeshArrays = readMesh(sharedMesh('fertility_9k.ply')); // 4494 vertices, genus 4
const OPTIONS: Options = { ...defaultOptions, n: 40, drawAhead: 4, seed: 3, stage1Vertices: 2500 };

let core: Core;
let pool: NodePool;
beforeAll(async () => {
  core = await loadCoreNode();
  pool = await openNodePool(core.stage1Input(MESH, OPTIONS), OPTIONS, { workers: 2 });
}, 60_000);
afterAll(() => pool?.close());

function skeletonOf(options: Options): Skeleton {
  const surface = core.openRefinedSurface(MESH);
  try {
    return surface.skeleton(options);
  } finally {
    surface.dispose();
  }
}

const json = (s: Skeleton) => writeSkeletonJson({ ...s, stats: { ...s.stats, timings: {} } }, { mesh: 'fertility_9k.ply', options: OPTIONS });

describe('multiscale stage 1', () => {
  it('simplifies only meshes above the limit, never a coarse one, and the same way every time', () => {
    const facts = core.inspect(MESH);
    expect(simplificationOf(facts, 0)).toBeNull();
    expect(simplificationOf(facts, facts.vertices)).toBeNull();
    expect(simplificationOf(facts, 2500)).toMatchObject({ fromVertices: 4494, fromFaces: facts.faces });
    const a = stage1Mesh(MESH, facts, 2500)!;
    const b = stage1Mesh(readMesh(sharedMesh('fertility_9k.ply')), facts, 2500)!; // another copy of the file: made anew
    expect(b.mesh.triangles).toEqual(a.mesh.triangles);
    expect(b.mesh.positions).toEqual(a.mesh.positions);
    expect(a.simplified.toVertices).toBeGreaterThan(2400);
    expect(a.simplified.toVertices).toBeLessThan(2600);
    const copy = core.inspect(a.mesh);
    expect([copy.genus, copy.components, copy.boundaryLoops]).toEqual([facts.genus, facts.components, facts.boundaryLoops]);
  });

  it('gives a skeleton of the mesh as given: its vertices, cycles = genus, error near the full run’s', () => {
    const full = skeletonOf({ ...OPTIONS, stage1Vertices: 0 });
    const multi = skeletonOf(OPTIONS);
    expect(full.stats.simplified).toBeNull();
    expect(multi.stats.simplified).toEqual(stage1Mesh(MESH, core.inspect(MESH), 2500)!.simplified);
    expect(multi.vertexToNode).toHaveLength(4494);
    const nodes = multi.radii.length;
    expect(multi.vertexToNode.every((node) => node < nodes)).toBe(true);
    // Sources are vertices of the copy.
    expect(Math.max(...multi.candidates.sources)).toBeLessThan(multi.stats.simplified!.toVertices);
    expect(multi.stats.cycles).toBe(4);
    const error = (s: Skeleton) => core.evaluate(MESH, { nodes: s.nodes, edges: s.edges, radii: null }).reconError;
    expect(error(multi)).toBeLessThan(1.5 * error(full));
  });

  it('gives the same skeleton, byte for byte, on 0, 1 and 2 worker threads (each simplifies the mesh itself)', async () => {
    const alone = json(skeletonOf(OPTIONS));
    for (const workers of [pool.workers.slice(0, 1), pool.workers]) {
      const surface = core.openRefinedSurface(MESH);
      const pipeline = surface.pipeline(OPTIONS);
      try {
        await runStage1(pipeline, workers, {});
        expect(json(pipeline.finish()), `${workers.length} worker threads`).toBe(alone);
      } finally {
        pipeline.dispose();
        surface.dispose();
      }
    }
  }, 120_000);
});
