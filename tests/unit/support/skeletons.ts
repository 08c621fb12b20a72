// Checks of whole-pipeline skeletons on the shared meshes, shared by the skeleton test files.
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core } from '../../../lib/core/node.ts';
import { closedConnectedMeshes, topologyProblems } from './topology.ts';

export * from './topology.ts';

/**
 * A representative part of the topology check (the whole shared set is `npm run check:corpus`,
 * scripts/check-corpus.ts): genus 0 to 4, each in auto mode. Several components, open surfaces and
 * sheets have their own tests (skeleton.test.ts, boundary.test.ts).
 */
export const TOPOLOGY_MESHES = ['spot.ply', 'bob.ply', 'two_torus.ply', 'dtorus.ply', 'elephant_small.ply', 'fertility_9k.ply'];

export function skeletonTopologySuite(): void {
  let core: Core;
  beforeAll(async () => {
    core = await loadCoreNode();
  });

  describe('skeleton topology', () => {
    const meshes = closedConnectedMeshes();
    it('checks genus 0 to 4 among the closed connected meshes of the shared set', () => {
      const genera = TOPOLOGY_MESHES.map((file) => meshes.find((m) => m.file === file)?.genus);
      expect(genera).not.toContain(undefined);
      expect(new Set(genera)).toEqual(new Set([0, 1, 2, 3, 4]));
    });
    for (const file of TOPOLOGY_MESHES) {
      const genus = meshes.find((m) => m.file === file)?.genus ?? -1;
      it(`of ${file} is connected with cycle rank ${genus} (the genus), its nodes inside`, () => {
        expect(topologyProblems(core, file, genus)).toEqual([]);
      });
    }
  });
}
