// Checks of whole-pipeline skeletons on the shared meshes, shared by the skeleton test files.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core, type MeshArrays } from '../../../lib/core/node.ts';
import { readMesh } from './meshes.ts';
import { sharedData, sharedMesh } from '../../paths.ts';

/** Closed, connected meshes of the shared set with their genus (MANIFEST.md). */
function closedConnectedMeshes(): { file: string; genus: number }[] {
  return readFileSync(path.join(sharedData, 'MANIFEST.md'), 'utf8')
    .split('\n')
    .filter((line) => line.startsWith('| `meshes/'))
    .map((line) => line.split('|').map((cell) => cell.trim()))
    .filter((c) => c[4] === 'yes' && c[8] === '1' && c[9] === '0')
    .map((c) => ({ file: c[1].replaceAll('`', '').replace('meshes/', ''), genus: Number(c[6]) }));
}

export const point = (flat: ArrayLike<number>, i: number) => [flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]];
export const distance3 = (a: number[], b: number[]) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

/** The connected component of every node (its smallest node index). */
export function componentOf(nodeCount: number, edges: Uint32Array): number[] {
  const parent = Array.from({ length: nodeCount }, (_, i) => i);
  const find = (x: number): number => (parent[x] === x ? x : (parent[x] = find(parent[x])));
  for (let i = 0; i < edges.length; i += 2) {
    const [a, b] = [find(edges[i]), find(edges[i + 1])];
    parent[Math.max(a, b)] = Math.min(a, b);
  }
  return parent.map((_, i) => find(i));
}

export function components(nodeCount: number, edges: Uint32Array): number {
  return new Set(componentOf(nodeCount, edges)).size;
}

/** Generalised winding number of a closed mesh around p (1 inside, 0 outside). */
export function windingNumber(mesh: MeshArrays, p: number[]): number {
  let total = 0;
  for (let f = 0; f < mesh.triangles.length / 3; f++) {
    const [a, b, c] = [0, 1, 2].map((k) => point(mesh.positions, mesh.triangles[3 * f + k]).map((x, j) => x - p[j]));
    const [la, lb, lc] = [a, b, c].map((v) => Math.hypot(v[0], v[1], v[2]));
    const dot = (u: number[], v: number[]) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    const det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    total += 2 * Math.atan2(det, la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb);
  }
  return total / (4 * Math.PI);
}

/**
 * The topology check of the whole pipeline on every closed connected shared mesh (issue 4: one
 * skeleton per mesh, the longest part of the unit tests), in two halves (alternate meshes) run by two
 * test files, so that Vitest's two workers share it.
 */
export function skeletonTopologySuite(half: 0 | 1): void {
  let core: Core;
  beforeAll(async () => {
    core = await loadCoreNode();
  });

  describe(`skeleton topology (half ${half + 1} of 2)`, () => {
    const meshes = closedConnectedMeshes();
    it('covers the closed connected meshes of the shared set', () => expect(meshes.length).toBeGreaterThanOrEqual(20));
    for (const { file, genus } of meshes.filter((_, i) => i % 2 === half)) {
      it(`of ${file} is connected with cycle rank ${genus} (the genus)`, () => {
        const mesh = readMesh(sharedMesh(file));
        const surface = core.openSurface(mesh);
        const skeleton = surface.skeleton();
        surface.dispose();
        const nodeCount = skeleton.radii.length;
        expect(components(nodeCount, skeleton.edges)).toBe(1);
        expect(skeleton.stats.cycles).toBe(genus);
        expect(skeleton.edges.length / 2 - nodeCount + 1).toBe(genus);
        // Centring: the nodes lie inside the shape.
        let inside = 0;
        for (let i = 0; i < nodeCount; i++) if (windingNumber(mesh, point(skeleton.nodes, i)) > 0.5) inside++;
        expect(inside / nodeCount).toBeGreaterThanOrEqual(0.98);
      });
    }
  });
}
