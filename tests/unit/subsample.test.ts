// Subsampling of large point clouds (lib/cloud/subsample.ts) and the size limit that offers it.
import { describe, expect, it } from 'vitest';
import { subsample, subsampleCloud } from '../../lib/cloud/subsample.ts';
import { POINT_LIMIT, SUBSAMPLE_TARGET, cloudSizeWarning } from '../../lib/mesh/limits.ts';
import { nearestDistances, spherePoints } from './support/clouds.ts';

/** CPU time since `start`: unlike wall time, it does not grow when other processes share the cores. */
function cpuMs(start: NodeJS.CpuUsage): number {
  const { user, system } = process.cpuUsage(start);
  return (user + system) / 1000;
}

const key = (values: ArrayLike<number>, i: number) => `${values[3 * i]} ${values[3 * i + 1]} ${values[3 * i + 2]}`;

/** For each point of `all`, the distance to the nearest point of `some` (brute force). */
function coverDistances(all: Float64Array, some: Float64Array): number[] {
  return Array.from({ length: all.length / 3 }, (_, i) => {
    let best = Infinity;
    for (let j = 0; j < some.length; j += 3) best = Math.min(best, Math.hypot(all[3 * i] - some[j], all[3 * i + 1] - some[j + 1], all[3 * i + 2] - some[j + 2]));
    return best;
  });
}

describe('subsampleCloud', () => {
  const sphere = spherePoints(20_000, 1);

  it('returns the cloud itself when it has no more points than the target', () => {
    expect(subsampleCloud(sphere, 20_000, 1)).toBe(sphere);
  });

  it('keeps at most the target and at least 95% of it: input points in input order, with their normals', () => {
    const kept = subsampleCloud(sphere, 2000, 1);
    const n = kept.positions.length / 3;
    expect(n).toBeLessThanOrEqual(2000);
    expect(n).toBeGreaterThanOrEqual(1900);
    const index = new Map(Array.from({ length: 20_000 }, (_, i) => [key(sphere.positions, i), i]));
    const from = Array.from({ length: n }, (_, p) => index.get(key(kept.positions, p))!);
    expect(from.every((i, p) => i !== undefined && (p === 0 || i > from[p - 1]))).toBe(true);
    from.forEach((i, p) => expect(key(kept.normals!, p)).toBe(key(sphere.normals, i)));
  });

  it('is the same for a seed, and other for another seed', () => {
    const a = subsampleCloud(sphere, 1000, 7), b = subsampleCloud(sphere, 1000, 7), c = subsampleCloud(sphere, 1000, 8);
    expect(Array.from(a.positions)).toEqual(Array.from(b.positions));
    expect(Array.from(a.positions)).not.toEqual(Array.from(c.positions));
  });

  it('spreads the points evenly: every input point is nearer a kept one than any two kept points are to each other', () => {
    const kept = subsampleCloud(sphere, 1000, 3).positions;
    const spacing = nearestDistances(kept);
    const closest = Math.min(...spacing);
    const median = spacing.sort((x, y) => x - y)[spacing.length >> 1];
    // Random picks would put some points almost on top of others.
    expect(closest).toBeGreaterThan(0.6 * median);
    expect(Math.max(...coverDistances(sphere.positions, kept))).toBeLessThan(closest);
  });

  it('leaves out every other point, each with a kept stand-in nearer it than any two kept points are to each other', () => {
    const { cloud, leftOut, standIn } = subsample(sphere, 1000, 3);
    expect(Array.from(cloud.positions)).toEqual(Array.from(subsampleCloud(sphere, 1000, 3).positions));
    const kept = cloud.positions.length / 3;
    expect(leftOut.length).toBe(20_000 - kept);
    expect(new Set(leftOut).size).toBe(leftOut.length);
    const keptKeys = new Set(Array.from({ length: kept }, (_, p) => key(cloud.positions, p)));
    expect(Array.from(leftOut).some((i) => keptKeys.has(key(sphere.positions, i)))).toBe(false);
    const closest = Math.min(...nearestDistances(cloud.positions));
    const far = Array.from(leftOut).map((i, j) => {
      const p = standIn[j];
      return Math.hypot(...[0, 1, 2].map((c) => sphere.positions[3 * i + c] - cloud.positions[3 * p + c]));
    });
    expect(Math.max(...far)).toBeLessThan(closest);
    expect(subsample(sphere, 20_000, 1).leftOut).toHaveLength(0);
  });

  it('maps every input point to its place in the subsample, or to its stand-in\'s', () => {
    const { cloud, leftOut, standIn, pointOf } = subsample(sphere, 1000, 3);
    const isLeftOut = new Set(leftOut);
    for (let i = 0; i < 20_000; i++) {
      if (isLeftOut.has(i)) continue;
      expect(key(cloud.positions, pointOf[i]), `kept point ${i}`).toBe(key(sphere.positions, i));
    }
    leftOut.forEach((i, j) => expect(pointOf[i]).toBe(standIn[j]));
    expect(Array.from(subsample(sphere, 20_000, 1).pointOf.subarray(0, 5))).toEqual([0, 1, 2, 3, 4]);
  });

  it('leaves points out in a shuffled order: the first few spread like all of them, whatever the input order', () => {
    // The sphere's points from south to north, as a scan's lines come.
    const south = Array.from({ length: 20_000 }, (_, i) => i).sort((a, b) => sphere.positions[3 * a + 2] - sphere.positions[3 * b + 2]);
    const sorted = { positions: Float64Array.from(south.flatMap((i) => Array.from(sphere.positions.subarray(3 * i, 3 * i + 3)))), normals: null };
    const { leftOut } = subsample(sorted, 1000, 3);
    const firstTenth = Array.from(leftOut.subarray(0, leftOut.length / 10));
    const north = firstTenth.filter((i) => sorted.positions[3 * i + 2] > 0).length / firstTenth.length;
    expect(north).toBeGreaterThan(0.4);
    expect(north).toBeLessThan(0.6);
  });

  it('thins dense parts and keeps sparse ones', () => {
    // The x < 0 half ten times as dense as the other.
    const dense = spherePoints(60_000, 2);
    const indices = Array.from({ length: 60_000 }, (_, i) => i).filter((i) => dense.positions[3 * i] < 0 || i % 10 === 0);
    const cloud = { positions: Float64Array.from(indices.flatMap((i) => Array.from(dense.positions.subarray(3 * i, 3 * i + 3)))), normals: null };
    const kept = subsampleCloud(cloud, 1000, 4).positions;
    const left = kept.filter((x, i) => i % 3 === 0 && x < 0).length;
    const right = kept.length / 3 - left;
    // A random pick keeps the 10:1; a maximal packing of the sparse half has fewer candidates to fill its gaps from.
    expect(left / right).toBeGreaterThan(1);
    expect(left / right).toBeLessThan(1.5);
  });

  it('subsamples 200,000 points in seconds', () => {
    const big = spherePoints(200_000, 5);
    const start = process.cpuUsage();
    const kept = subsampleCloud(big, 10_000, 1);
    expect(cpuMs(start)).toBeLessThan(5000);
    expect(kept.positions.length / 3).toBeGreaterThanOrEqual(9500);
  });
});

describe('the point-cloud size limit', () => {
  it('warns above POINT_LIMIT and offers SUBSAMPLE_TARGET', () => {
    expect([POINT_LIMIT, SUBSAMPLE_TARGET]).toEqual([100_000, 50_000]);
    expect(cloudSizeWarning(100_000)).toBeNull();
    expect(cloudSizeWarning(250_000)).toBe('this point cloud has 250000 points, more than the 100000 advised; subsample it to about 50000');
  });
});
