// The vertex map is compact: a node's vertices lie around it, a cross-section of the tube it stands
// for, so radii read from the map (the median distance of a node's vertices to it, the bench's second
// rule) rebuild the shape about as well as radii fitted to the surface. Before the map took each vertex
// to its nearest node along the skeleton, band pieces slanted near junctions and borders gave nodes
// vertices a tube diameter away: on these shapes the map's error was 2.5-4 times the fitted one.
import { beforeAll, describe, expect, it } from 'vitest';
import { vertexMapRadii } from '../../bench/metrics.ts';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import { graphTopology } from '../../lib/graph/topology.ts';
import { readMesh } from './support/meshes.ts';
import { sharedSynthetic } from '../paths.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

describe('vertex map', () => {
  it.each(['star8_coarse.ply', 'tree_coarse.ply'])('%s: radii from the map rebuild the shape within 2x of fitted radii', (name) => {
    const mesh = readMesh(sharedSynthetic(name));
    const surface = core.openRefinedSurface(mesh);
    const skeleton = surface.skeleton({});
    surface.dispose();
    const graph = { nodes: skeleton.nodes, edges: skeleton.edges };
    const fitted = core.evaluate(mesh, { ...graph, radii: null });
    const { radii } = vertexMapRadii(mesh.positions, graph, skeleton.vertexToNode, fitted.radii);
    const fromMap = core.evaluate(mesh, { ...graph, radii });
    expect(fromMap.reconError).toBeLessThan(2 * fitted.reconError);

    // Every node's vertices are one piece of the surface.
    const vertexCount = mesh.positions.length / 3;
    const sameNode: number[] = [];
    for (let c = 0; c < mesh.triangles.length; c++) {
      const a = mesh.triangles[c], b = mesh.triangles[c % 3 === 2 ? c - 2 : c + 1];
      if (skeleton.vertexToNode[a] === skeleton.vertexToNode[b]) sameNode.push(a, b);
    }
    expect(graphTopology(vertexCount, sameNode).components).toBe(new Set(skeleton.vertexToNode).size);
  });
});
