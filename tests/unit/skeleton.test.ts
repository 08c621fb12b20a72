// The whole CSCD-M pipeline (stage 1 over many sources, then stage 2) on the shared meshes.
// The topology check: skeleton-topology.test.ts (a representative part) and `npm run check:corpus` (every closed shared mesh).
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core, type MeshArrays, type Skeleton } from '../../lib/core/node.ts';
import { graphTopology } from '../../lib/graph/topology.ts';
import { leafIndices } from '../../bench/metrics.ts';
import { extremities, readMesh, torus } from './support/meshes.ts';
import { distance3, nodePieces, point } from './support/skeletons.ts';
import { sharedMesh } from '../paths.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

/** The skeleton of a shared mesh with the default options. */
function skeletonOf(file: string): Skeleton {
  const surface = core.openSurface(readMesh(sharedMesh(file)));
  try {
    return surface.skeleton({});
  } finally {
    surface.dispose();
  }
}

/** The nearest leaf of the skeleton to every tip must be a different node, within `reach` of it. */
function expectOneLeafPerTip(mesh: MeshArrays, skeleton: Skeleton, tips: number[], reach: number) {
  const leaves = leafIndices(skeleton.radii.length, skeleton.edges);
  const nearest = tips.map((tip) => {
    const at = point(mesh.positions, tip);
    const best = leaves.reduce((a, b) => (distance3(point(skeleton.nodes, a), at) <= distance3(point(skeleton.nodes, b), at) ? a : b));
    expect(distance3(point(skeleton.nodes, best), at)).toBeLessThan(reach);
    return best;
  });
  expect(new Set(nearest).size).toBe(tips.length);
}

describe('skeleton shape and bookkeeping', () => {
  it('puts the nodes of a torus on its core circle, with the tube radius', () => {
    // Ring radius 1, tube radius 0.3: a region's area centroid would sit 0.045 (r^2 / 2R) outside the circle.
    const surface = core.openSurface(torus(1, 0.3, 96, 32));
    const skeleton = surface.skeleton({});
    surface.dispose();
    expect(skeleton.stats.cycles).toBe(1);
    for (let i = 0; i < skeleton.radii.length; i++) {
      const [x, y, z] = point(skeleton.nodes, i);
      expect(Math.hypot(Math.hypot(x, y) - 1, z), `node ${i} off the core circle`).toBeLessThan(0.01);
      expect(skeleton.radii[i]).toBeCloseTo(0.3, 2);
    }
  });

  it('gives one piece per connected component: three rings of one cycle each, the seven shells of a CAD part', () => {
    const rings = skeletonOf('rings.ply');
    const ringOf = graphTopology(rings.radii.length, rings.edges).componentOf;
    const pieces = [...new Set(ringOf)];
    expect(pieces).toHaveLength(3);
    for (const piece of pieces) {
      const nodes = ringOf.filter((c) => c === piece).length;
      let edges = 0;
      for (let i = 0; i < rings.edges.length; i += 2) if (ringOf[rings.edges[i]] === piece) edges++;
      expect(edges - nodes + 1, 'cycles of one ring').toBe(1);
    }
    const cup = skeletonOf('thingi10k_37361_linkCupBase.ply');
    expect(graphTopology(cup.radii.length, cup.edges).components).toBe(7);
    expect(cup.stats.cycles).toBe(0);
  });

  it('follows the ring of a torus with holes: one loop, no branches, on the core circle', () => {
    // torus_two_holes_open: ring radius 1 around z, tube radius 0.4, three small holes (MANIFEST.md).
    const skeleton = skeletonOf('torus_two_holes_open.ply');
    expect(skeleton.stats.cycles).toBe(1);
    expect(leafIndices(skeleton.radii.length, skeleton.edges)).toEqual([]);
    // The holes have one boundary loop each: no two points of one hole face each other, and points of
    // two different holes are never paired (a path between them would cut the tube), so every
    // separator is a loop around the tube.
    expect(skeleton.candidates.closed.every((closed) => closed === 1)).toBe(true);
    for (let i = 0; i < skeleton.radii.length; i++) {
      const [x, y, z] = point(skeleton.nodes, i);
      expect(Math.hypot(Math.hypot(x, y) - 1, z), `node ${i} off the core circle`).toBeLessThan(0.05);
    }
  });

  // Six extremities each: the hand's five fingertips and wrist; the armadillo's hands, feet, head and tail.
  it.each(['hand.ply', 'armadillo.ply'])('has a leaf at each of the six extremities of %s', (file) => {
    const mesh = readMesh(sharedMesh(file));
    const surface = core.openSurface(mesh);
    const skeleton = surface.skeleton();
    expectOneLeafPerTip(mesh, skeleton, extremities(surface, 6), 0.15 * surface.facts.bboxDiagonal);
    surface.dispose();
  });

  it('maps every vertex to a node, with connected regions, deterministically for a seed', () => {
    const mesh = readMesh(sharedMesh('fertility_9k.ply'));
    const surface = core.openSurface(mesh);
    const skeleton = surface.skeleton({ seed: 3 });
    const again = surface.skeleton({ seed: 3 });
    const other = surface.skeleton({ seed: 4 });
    surface.dispose();
    const json = (s: Skeleton) =>
      JSON.stringify(s, (key, value) => (ArrayBuffer.isView(value) ? Array.from(value as Float64Array) : key === 'timings' ? undefined : value));
    expect(json(again)).toBe(json(skeleton));
    expect(json(other)).not.toBe(json(skeleton));
    expect(skeleton.stats.seed).toBe(3);

    const nV = mesh.positions.length / 3;
    expect(skeleton.vertexToNode.length).toBe(nV);
    const nodeCount = skeleton.radii.length;
    expect(Math.max(...skeleton.vertexToNode)).toBeLessThan(nodeCount);
    // Regions are connected on the surface: one piece per node.
    expect(nodePieces(mesh, skeleton.vertexToNode)).toBe(new Set(skeleton.vertexToNode).size);
    // Stats agree with the data.
    expect(skeleton.stats.packed).toBe(skeleton.packed.length);
    expect(skeleton.stats.n).toBe(skeleton.candidates.loops.length);
    expect(skeleton.stats.candidates).toBe(skeleton.candidates.fates.filter((f) => f !== 'failed').length);
    expect(skeleton.candidates.fates.filter((f) => f === 'packed').length).toBe(skeleton.packed.length);
  });

  it('runs as a resumable job with progress, source by source', () => {
    const surface = core.openSurface(readMesh(sharedMesh('two_torus.ply')));
    const pipeline = surface.pipeline({ n: 12, drawAhead: 5 });
    const seen: number[] = [];
    let progress;
    do {
      progress = pipeline.step(5);
      seen.push(progress.done);
      expect(progress.total).toBe(12);
      expect(progress.newLoops.length).toBe(seen.length === 1 ? 5 : progress.done - seen[seen.length - 2]);
    } while (!progress.finished);
    expect(seen).toEqual([5, 10, 12]);
    const skeleton = pipeline.finish();
    expect(skeleton.stats.n).toBe(12);
    pipeline.dispose();
    expect(() => surface.pipeline({ n: 'many' as unknown as number })).toThrow(/n must be a number of sources or 'auto'/);
    surface.dispose();
  });
});
