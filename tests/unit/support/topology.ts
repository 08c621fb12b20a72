// Skeleton checks that need no test runner: shared by the unit tests and scripts/check-corpus.ts.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import type { Core } from '../../../lib/core/index.ts';
import { graphTopology } from '../../../lib/graph/topology.ts';
import { windingNumber } from '../../../lib/mesh/winding.ts';
import { readMesh } from './meshes.ts';
import { sharedData, sharedMesh } from '../../paths.ts';

/** Closed, connected meshes of the shared set with their genus (MANIFEST.md). */
export function closedConnectedMeshes(): { file: string; genus: number }[] {
  return readFileSync(path.join(sharedData, 'MANIFEST.md'), 'utf8')
    .split('\n')
    .filter((line) => line.startsWith('| `meshes/'))
    .map((line) => line.split('|').map((cell) => cell.trim()))
    .filter((c) => c[4] === 'yes' && c[8] === '1' && c[9] === '0')
    .map((c) => ({ file: c[1].replaceAll('`', '').replace('meshes/', ''), genus: Number(c[6]) }));
}

export const point = (flat: ArrayLike<number>, i: number) => [flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]];
export const distance3 = (a: number[], b: number[]) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

/** Each node's number of edges. */
export function degrees(skeleton: { radii: ArrayLike<number>; edges: ArrayLike<number> }): number[] {
  const degree = new Array<number>(skeleton.radii.length).fill(0);
  for (let i = 0; i < skeleton.edges.length; i++) degree[skeleton.edges[i]]++;
  return degree;
}

/**
 * Connected pieces of the surface that the vertex map gives the nodes: the mesh edges whose two
 * vertices share a node join them. Equal to the number of nodes that own vertices when every node's
 * vertices are one piece.
 */
export function nodePieces(mesh: { triangles: ArrayLike<number>; positions: ArrayLike<number> }, vertexToNode: ArrayLike<number>): number {
  const withinNodes: number[] = [];
  for (let c = 0; c < mesh.triangles.length; c++) {
    const a = mesh.triangles[c], b = mesh.triangles[c % 3 === 2 ? c - 2 : c + 1];
    if (vertexToNode[a] === vertexToNode[b]) withinNodes.push(a, b);
  }
  return graphTopology(mesh.positions.length / 3, withinNodes).components;
}

/** What is wrong with the auto-mode skeleton of a closed connected mesh: not connected, cycles other than the genus, nodes outside. */
export function topologyProblems(core: Core, file: string, genus: number): string[] {
  const mesh = readMesh(sharedMesh(file));
  const surface = core.openSurface(mesh);
  const skeleton = surface.skeleton();
  surface.dispose();
  const nodeCount = skeleton.radii.length;
  const problems: string[] = [];
  const { components, cycleRank } = graphTopology(nodeCount, skeleton.edges);
  if (components !== 1) problems.push(`${components} components`);
  if (skeleton.stats.cycles !== genus) problems.push(`${skeleton.stats.cycles} cycles for genus ${genus}`);
  if (cycleRank !== skeleton.stats.cycles) problems.push('stats.cycles is not the cycle rank of the edges');
  // Centring: the nodes lie inside the shape.
  let inside = 0;
  for (let i = 0; i < nodeCount; i++) if (windingNumber(mesh, point(skeleton.nodes, i)) > 0.5) inside++;
  if (inside / nodeCount < 0.98) problems.push(`${nodeCount - inside} of ${nodeCount} nodes outside the shape`);
  return problems;
}
