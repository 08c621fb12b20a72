// Quadric edge-collapse decimation (lib/mesh/decimate.ts) on shared meshes: a closed genus-4 surface,
// an open torus with holes and a mesh of several components keep their topology, reach the target
// and stay close to the original surface; the same input gives the same output.
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core, type MeshArrays } from '../../lib/core/node.ts';
import { decimate, type DecimateProgress } from '../../lib/mesh/decimate.ts';
import { pointTriangleDistance2, readMesh } from './support/meshes.ts';
import { sharedMesh } from '../paths.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

/** Mean distance of every `stride`-th vertex of `original` to the surface of `decimated` (brute force). */
function meanDistance(original: MeshArrays, decimated: MeshArrays, stride: number): number {
  const p = decimated.positions, t = decimated.triangles;
  const corner = (v: number) => [p[3 * v], p[3 * v + 1], p[3 * v + 2]];
  let sum = 0;
  let count = 0;
  for (let v = 0; v < original.positions.length / 3; v += stride) {
    const q = Array.from(original.positions.subarray(3 * v, 3 * v + 3));
    let best = Infinity;
    for (let f = 0; f < t.length / 3; f++) {
      best = Math.min(best, pointTriangleDistance2(q, corner(t[3 * f]), corner(t[3 * f + 1]), corner(t[3 * f + 2])));
    }
    sum += Math.sqrt(best);
    count++;
  }
  return sum / count;
}

const CASES = [
  { file: 'fertility_9k.ply', what: 'closed, genus 4' },
  { file: 'torus_two_holes_open.ply', what: 'open, genus 1, three boundary loops' },
  { file: 'rings.ply', what: 'several components' },
];

describe('decimate', () => {
  for (const { file, what } of CASES) {
    it(`keeps the topology of ${file} (${what}) and stays close to it`, () => {
      const mesh = readMesh(sharedMesh(file));
      const before = core.inspect(mesh);
      const target = Math.round(before.faces / 4);
      const progress: DecimateProgress[] = [];
      const result = decimate(mesh, target, (p) => progress.push(p), 500);
      const after = core.inspect(result);

      expect(after.manifold).toBe(true);
      expect(after.consistentlyOriented).toBe(true);
      expect(after.degenerateFaces).toBe(0);
      expect(after.unreferencedVertices).toBe(0);
      expect(after.eulerCharacteristic).toBe(before.eulerCharacteristic);
      expect(after.genus).toBe(before.genus);
      expect(after.components).toBe(before.components);
      expect(after.boundaryLoops).toBe(before.boundaryLoops);
      expect(after.faces).toBeLessThanOrEqual(target);
      expect(after.faces).toBeGreaterThanOrEqual(target - 2);
      expect(meanDistance(mesh, result, 7)).toBeLessThan(1e-3 * before.bboxDiagonal);

      expect(progress.length).toBeGreaterThan(2);
      expect(progress.at(-1)).toEqual({ faces: after.faces, target, fraction: 1 });
      for (let i = 1; i < progress.length; i++) expect(progress[i].fraction).toBeGreaterThanOrEqual(progress[i - 1].fraction);
    });
  }

  it('is deterministic', () => {
    const mesh = readMesh(sharedMesh('fertility_9k.ply'));
    const a = decimate(mesh, 2000);
    const b = decimate(mesh, 2000);
    expect(b.positions).toEqual(a.positions);
    expect(b.triangles).toEqual(a.triangles);
  });

  it('stops short of the target where every further collapse would change the topology', () => {
    const tetrahedron = { positions: Float64Array.of(0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1), triangles: Uint32Array.of(0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3) };
    const result = decimate(tetrahedron, 1);
    expect(result.triangles.length / 3).toBe(4);
    expect(result.positions).toEqual(tetrahedron.positions);
  });
});
