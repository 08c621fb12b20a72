// Each point's neighbours trimmed to those that lie flat before its local triangulation is made
// (wasm/src/pointcloud/flat_neighbours.h; docs/pointcloud.md, "A neighbour count per point"): across a
// part thinner than the neighbourhood down to 12, on flat and gently curved parts all k, on a noisy
// cloud never.
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import { fixture } from '../paths.ts';
import { readCloudFile } from './support/clouds.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

/** Rings of `around` points a unit apart, each turned half a step from the last, rows 0.87 apart (a triangular lattice rolled up). */
function cylinder(around: number, rows: number): Float64Array {
  const radius = around / (2 * Math.PI), positions: number[] = [];
  for (let row = 0; row < rows; row++)
    for (let i = 0; i < around; i++) {
      const angle = ((i + (row % 2) / 2) * 2 * Math.PI) / around;
      positions.push(radius * Math.cos(angle), radius * Math.sin(angle), row * 0.87);
    }
  return new Float64Array(positions);
}

function meanFlatNeighbours(positions: Float64Array): number {
  const cloud = core.openCloud({ positions, normals: null });
  try {
    return cloud.facts.meanFlatNeighbours;
  } finally {
    cloud.dispose();
  }
}

describe('neighbours trimmed to those that lie flat', () => {
  it('keeps 12 around a cylinder ten points round, all 30 on one 120 round and on a plane', () => {
    expect(meanFlatNeighbours(cylinder(10, 60))).toBe(12);
    expect(meanFlatNeighbours(cylinder(16, 50))).toBe(12);
    expect(meanFlatNeighbours(cylinder(120, 20))).toBe(30);
    const plane: number[] = [];
    for (let row = 0; row < 40; row++) for (let i = 0; i < 40; i++) plane.push(i + (row % 2) / 2, row * 0.87, 0);
    expect(meanFlatNeighbours(new Float64Array(plane))).toBe(30);
  });

  it('trims a sparse clean cloud where it curves, never a noisy one (its neighbourhoods average the noise out)', () => {
    for (const [name, low, high] of [['hand_subsample.ply', 15, 25], ['bob_subsample.ply', 15, 25], ['hand_noise_subsample.ply', 30, 30], ['bob_noise_subsample.ply', 30, 30]] as const) {
      const cloud = core.openCloud(readCloudFile(fixture('clouds', name)));
      try {
        expect(cloud.facts.meanFlatNeighbours, name).toBeGreaterThanOrEqual(low);
        expect(cloud.facts.meanFlatNeighbours, name).toBeLessThanOrEqual(high);
        expect(cloud.neighbourhood().noisy, name).toBe(low === 30);
      } finally {
        cloud.dispose();
      }
    }
  });
});
