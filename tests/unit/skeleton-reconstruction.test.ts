// The skeleton rebuilds its shape: the paper's reconstruction error with radii fitted to the surface
// (nodes centred on their elements) and with radii read from the vertex map (each node's vertices a
// compact cross-section around it, the bench's second rule), on the synthetic shapes of
// ../shared/data/synthetic. Bounds sit between the errors measured before and after those two changes
// (star8_coarse: 0.078 -> 0.014 fitted, 0.315 -> 0.041 from the map; tree_coarse: 0.0059 -> 0.0026
// and 0.0148 -> 0.0049; docs/skeleton.md).
import { beforeAll, describe, expect, it } from 'vitest';
import { vertexMapRadii } from '../../bench/metrics.ts';
import { loadCoreNode, type Core, type Evaluation, type MeshArrays, type Skeleton } from '../../lib/core/node.ts';
import { readMesh } from './support/meshes.ts';
import { nodePieces } from './support/skeletons.ts';
import { sharedSynthetic } from '../paths.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

describe.each([
  { shape: 'star8_coarse', fittedBound: 0.03, mapBound: 0.1 },
  { shape: 'tree_coarse', fittedBound: 0.0032, mapBound: 0.008 },
])('the skeleton of $shape', ({ shape, fittedBound, mapBound }) => {
  let mesh: MeshArrays;
  let skeleton: Skeleton;
  let fitted: Evaluation;
  beforeAll(() => {
    mesh = readMesh(sharedSynthetic(`${shape}.ply`));
    const surface = core.openRefinedSurface(mesh);
    try {
      skeleton = surface.skeleton({});
    } finally {
      surface.dispose();
    }
    fitted = core.evaluate(mesh, { nodes: skeleton.nodes, edges: skeleton.edges, radii: null });
  });

  it('rebuilds the shape with radii fitted to the surface (nodes centred on their elements), the median of three seeds', () => {
    // One seed's error moves with the sources drawn: tree_coarse at seeds 1-4, 0.0035, 0.0016, 0.0026,
    // 0.0041 with sources drawn 4 ahead, 0.0010, 0.0042, 0.0038, 0.0029 in the former rounds of 8.
    const errors = [fitted.reconError];
    for (const seed of [2, 3]) {
      const surface = core.openRefinedSurface(mesh);
      try {
        const other = surface.skeleton({ seed });
        errors.push(core.evaluate(mesh, { nodes: other.nodes, edges: other.edges, radii: null }).reconError);
      } finally {
        surface.dispose();
      }
    }
    expect(errors.sort((a, b) => a - b)[1]).toBeLessThan(fittedBound);
  });

  it('rebuilds the shape with radii from the vertex map (each node\'s vertices around it)', () => {
    const graph = { nodes: skeleton.nodes, edges: skeleton.edges };
    // Nodes that own no vertex take their neighbours' radii; those of components that own none (none here) the fitted ones.
    const { radii } = vertexMapRadii(mesh.positions, graph, skeleton.vertexToNode, fitted.radii);
    expect(core.evaluate(mesh, { ...graph, radii }).reconError).toBeLessThan(mapBound);
  });

  it('gives every node a connected piece of the surface', () => {
    expect(nodePieces(mesh, skeleton.vertexToNode)).toBe(new Set(skeleton.vertexToNode).size);
  });
});
