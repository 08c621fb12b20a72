// Point-cloud checks on load (lib/io/cloud-check.ts): each change on a cloud built to need it, with the
// sentence that says it, and each refusal with its message.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { checkCloud } from '../../lib/io/cloud-check.ts';
import { MeshFormatError, parseShape, type CloudArrays } from '../../lib/io/index.ts';
import { random } from '../../lib/core/random.ts';
import { fixture } from '../paths.ts';
import { spherePoints } from './support/clouds.ts';

const K = 8;
const THICKNESS = 'a point cloud needs thickness in all three dimensions to have a curve skeleton';

/** CPU time since `start`: unlike wall time, it does not grow when other processes share the cores. */
function cpuMs(start: NodeJS.CpuUsage): number {
  const { user, system } = process.cpuUsage(start);
  return (user + system) / 1000;
}

/** The cloud made of the given points of `from` (indices may repeat), in that order. */
function pick(from: CloudArrays, indices: number[]): CloudArrays {
  const triples = (values: Float64Array | Float32Array) => indices.flatMap((i) => Array.from(values.subarray(3 * i, 3 * i + 3)));
  return { positions: Float64Array.from(triples(from.positions)), normals: from.normals && Float32Array.from(triples(from.normals)) };
}

function refusal(cloud: CloudArrays, neighbours = K): string {
  try {
    checkCloud(cloud, neighbours);
  } catch (error) {
    expect(error).toBeInstanceOf(MeshFormatError);
    return (error as Error).message;
  }
  throw new Error('the cloud was accepted');
}

const range = (n: number) => Array.from({ length: n }, (_, i) => i);

describe('clouds that need nothing', () => {
  it('come back as the same object', () => {
    const sphere = spherePoints(200, 1);
    const result = checkCloud(sphere, K);
    expect(result.cloud).toBe(sphere);
    expect(result.repairs).toEqual([]);
    expect(Array.from(result.pointMap)).toEqual(range(200));
  });

  it.each(['bob_subsample.ply', 'armadillo_gel_pts.ply'])('the real cloud %s', (name) => {
    const cloud = parseShape(new Uint8Array(readFileSync(fixture('clouds', name))), name);
    expect(cloud.kind).toBe('cloud');
    expect(checkCloud(cloud as CloudArrays, K).repairs).toEqual([]);
  });
});

describe('non-finite coordinates', () => {
  it('removes the points, saying how many', () => {
    const sphere = spherePoints(20, 2);
    const cloud = pick(sphere, range(20));
    cloud.positions[3 * 4 + 1] = NaN;
    cloud.positions[3 * 9 + 2] = -Infinity;
    const result = checkCloud(cloud, K);
    expect(result.repairs).toEqual(['removed 2 points with a non-finite coordinate (NaN or infinity)']);
    const kept = range(20).filter((i) => i !== 4 && i !== 9);
    expect(result.cloud).toEqual(pick(sphere, kept));
    expect(Array.from(result.pointMap)).toEqual(range(20).map((i) => (i === 4 || i === 9 ? -1 : kept.indexOf(i))));
  });

  it('refuses a cloud of nothing else', () => {
    expect(refusal({ positions: Float64Array.from([NaN, 0, 0, 1, Infinity, 2, 0, 0, NaN]), normals: null }))
      .toBe('all 3 points have a non-finite coordinate (NaN or infinity)');
  });
});

describe('duplicate points', () => {
  it('merges equal points and points within 1e-9 of the diagonal into the first, averaging the normals', () => {
    const sphere = spherePoints(30, 3);
    const cloud = pick(sphere, [0, 1, 0, 2, ...range(30).slice(3), 1]);
    // The bounding-box diagonal is about 2*sqrt(3): 1e-9 of it is about 3.5e-9.
    cloud.positions[3 * 31] += 2e-9;
    cloud.normals!.set([1, 0, 0], 3 * 2);
    const result = checkCloud(cloud, K);
    expect(result.repairs).toEqual(['merged 2 duplicate points (closer than 1e-9 of the bounding-box diagonal), averaging their normals']);
    expect(Array.from(result.cloud.positions)).toEqual(Array.from(sphere.positions));
    expect(Array.from(result.pointMap)).toEqual([0, 1, 0, 2, ...range(30).slice(3), 1]);
    const [nx, ny, nz] = sphere.normals.subarray(0, 3);
    const sum = [nx + 1, ny, nz];
    const length = Math.hypot(...sum);
    expect(Array.from(result.cloud.normals!.subarray(0, 3))).toEqual(sum.map((x) => Math.fround(x / length)));
    expect(Array.from(result.cloud.normals!.subarray(3))).toEqual(Array.from(sphere.normals.subarray(3)));
  });

  it('keeps points 1e-7 of the diagonal apart', () => {
    const cloud = pick(spherePoints(30, 4), [...range(30), 5]);
    cloud.positions[3 * 30] += 3.5e-7;
    expect(checkCloud(cloud, K).repairs).toEqual([]);
  });

  it('opposite normals of duplicates: the first one stands', () => {
    const sphere = spherePoints(30, 5);
    const cloud = pick(sphere, [...range(30), 7]);
    cloud.normals!.set(Array.from(sphere.normals.subarray(21, 24)).map((x) => -x), 90);
    const { normals } = checkCloud(cloud, K).cloud;
    expect(normals!.length).toBe(90);
    normals!.forEach((x, i) => expect(x).toBeCloseTo(sphere.normals[i], 6));
  });

  it('merges the duplicates of a million points in seconds, the same every time', () => {
    const half = spherePoints(500_000, 6);
    const positions = new Float64Array(3_000_000);
    positions.set(half.positions);
    positions.set(half.positions, 1_500_000);
    const start = process.cpuUsage();
    const result = checkCloud({ positions, normals: null }, K, { outliers: false });
    expect(cpuMs(start)).toBeLessThan(5000);
    expect(result.repairs).toEqual(['merged 500000 duplicate points (closer than 1e-9 of the bounding-box diagonal)']);
    expect(result.cloud.positions.every((x, i) => x === half.positions[i])).toBe(true);
  });
});

describe('normals', () => {
  it('drops them all when one gives no direction', () => {
    for (const bad of [[0, 0, 0], [NaN, 0, 1]]) {
      const cloud = pick(spherePoints(20, 7), range(20));
      cloud.normals!.set(bad, 3 * 11);
      const result = checkCloud(cloud, K);
      expect(result.repairs).toEqual(['dropped the normals: 1 point has a non-finite or zero normal']);
      expect(result.cloud.normals).toBeNull();
      expect(result.cloud.positions).toBe(cloud.positions);
    }
  });

  it('scales normals to unit length, saying how many', () => {
    const sphere = spherePoints(20, 8);
    const cloud = pick(sphere, range(20));
    for (const i of [3, 4, 5]) for (let k = 0; k < 3; k++) cloud.normals![3 * i + k] *= 2;
    // Within 1e-3 of unit length: kept as it is.
    cloud.normals![3 * 6] *= 1.0005;
    const result = checkCloud(cloud, K);
    expect(result.repairs).toEqual(['scaled 3 normals to unit length']);
    for (const i of [3, 4, 5]) expect(Math.hypot(...result.cloud.normals!.subarray(3 * i, 3 * i + 3))).toBeCloseTo(1, 6);
    expect(result.cloud.normals![3 * 6]).toBe(cloud.normals![3 * 6]);
  });
});

describe('too few points', () => {
  it('refuses k points or fewer, naming k', () => {
    expect(refusal(spherePoints(8, 9))).toBe('the cloud has 8 points, too few for the neighbour count k = 8: every point needs k others');
    expect(checkCloud(spherePoints(9, 9), K).repairs).toEqual([]);
    expect(refusal(spherePoints(20, 9), 30)).toBe('the cloud has 20 points, too few for the neighbour count k = 30: every point needs k others');
  });

  it('counts the points left after the merges', () => {
    const cloud = pick(spherePoints(6, 10), [0, 1, 2, 3, 4, 5, 0, 1, 2, 3]);
    expect(refusal(cloud)).toBe('the cloud has 6 points (of 10 in the file), too few for the neighbour count k = 8: every point needs k others');
  });
});

describe('flat clouds', () => {
  const next = random(11);
  /** Points at `origin + s u + t v` for random s, t in [0, 1), rounded to float32 as most files hold them. */
  function spanned(n: number, origin: number[], u: number[], v: number[]): CloudArrays {
    const positions = new Float64Array(3 * n);
    for (let i = 0; i < n; i++) {
      const s = next(), t = next();
      for (let k = 0; k < 3; k++) positions[3 * i + k] = Math.fround(origin[k] + s * u[k] + t * v[k]);
    }
    return { positions, normals: null };
  }

  it('refuses points on a line', () => {
    expect(refusal(spanned(100, [1000, -50, 3], [1, 2, 3], [0, 0, 0])))
      .toBe(`all 100 points lie on one line (their spread across it is below 1e-4 of their spread along it): ${THICKNESS}`);
  });

  it('refuses points on a tilted plane, far from the origin in float32', () => {
    expect(refusal(spanned(500, [100, 100, 100], [1, 0.3, -0.2], [0.1, 0.9, 0.7])))
      .toBe(`all 500 points lie on one plane (their spread across it is below 1e-4 of their spread along it): ${THICKNESS}`);
  });

  it('accepts a slab 1e-3 as thick as it is wide', () => {
    const slab = spanned(500, [100, 100, 100], [1, 0, 0], [0, 1, 0]);
    for (let i = 0; i < 500; i++) slab.positions[3 * i + 2] += 1e-3 * next();
    expect(checkCloud(slab, K).repairs).toEqual([]);
  });
});
