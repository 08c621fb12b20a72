// CSCD-PC's per-cloud object through the real WASM module: its facts, heat-method distances on the
// tufted triangulation (held to the exact geodesics of the mesh the bob cloud was sampled from), bad
// input, and the CLI's info and distance on a cloud.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { CoreError, loadCoreNode, type Cloud, type Core } from '../../lib/core/node.ts';
import { parseShape, type ParsedCloud } from '../../lib/io/index.ts';
import { fixture, sharedData, sharedMesh } from '../paths.ts';
import { cscd } from './support/cli.ts';
import { cloudPly, nearestPoints, spherePoints } from './support/clouds.ts';
import { readMesh } from './support/meshes.ts';

const tmp = mkdtempSync(path.join(tmpdir(), 'cscd-cloud-'));
afterAll(() => rmSync(tmp, { recursive: true, force: true }));

function readCloud(file: string): ParsedCloud {
  const shape = parseShape(new Uint8Array(readFileSync(file)), path.basename(file));
  if (shape.kind !== 'cloud') throw new Error(`${file} holds a mesh`);
  return shape;
}

let core: Core;
const bob = readCloud(fixture('clouds', 'bob_subsample.ply'));
let bobCloud: Cloud;
beforeAll(async () => {
  core = await loadCoreNode();
  bobCloud = core.openCloud(bob);
});
afterAll(() => bobCloud.dispose());

describe('a cloud opened in the core', () => {
  it('has the facts of bob_subsample (1948 points with normals)', () => {
    const { facts } = bobCloud;
    expect(facts).toMatchObject({ points: 1948, neighbours: 30, components: 1, normalsFromFile: true });
    expect(facts.bboxDiagonal).toBeCloseTo(2.5516, 3);
    // Neighbouring points of 1948 spread over bob's surface (about 7.5 square units) are some 0.06 apart.
    expect(facts.meanSpacing).toBeGreaterThan(0.02);
    expect(facts.meanSpacing).toBeLessThan(0.2);
  });

  it('has the facts of the GEL armadillo (6488 points, PCA normals), with the k asked for', () => {
    const cloud = core.openCloud(readCloud(fixture('clouds', 'armadillo_gel_pts.ply')), { neighbours: 12 });
    try {
      expect(cloud.facts).toMatchObject({ points: 6488, neighbours: 12, normalsFromFile: false });
      expect(cloud.facts.bboxDiagonal).toBeCloseTo(229.2, 1);
      const d = cloud.distance(0);
      expect(d[0]).toBe(0);
      expect(Array.from(d).filter((x) => Number.isFinite(x)).length).toBeGreaterThan(0.99 * 6488);
    } finally {
      cloud.dispose();
    }
  });
});

describe('geodesic distance on a cloud', () => {
  it('is 0 at the source, positive and finite elsewhere on a connected cloud', () => {
    const d = bobCloud.distance(100);
    expect(d).toHaveLength(1948);
    expect(d[100]).toBe(0);
    d.forEach((x, p) => p !== 100 && expect(x, `point ${p}`).toBeGreaterThan(0));
    expect(d.every((x) => Number.isFinite(x))).toBe(true);
  });

  it('is near the exact geodesic distance on the bob mesh the cloud was sampled from', () => {
    const mesh = readMesh(sharedMesh('bob.ply'));
    const surface = core.openSurface(mesh);
    const vertexOf = nearestPoints(bob.positions, mesh.positions);
    let sum = 0;
    let count = 0;
    try {
      for (const source of [0, 700, 1400]) {
        const d = bobCloud.distance(source);
        const exact = surface.exactDistanceFromVertex(vertexOf[source]);
        // Far enough from the source that the cloud point and its nearest vertex being apart does not count.
        for (let p = 0; p < d.length; p++) {
          const reference = exact[vertexOf[p]];
          if (!(reference > 0.1 * bobCloud.facts.bboxDiagonal)) continue;
          sum += Math.abs(d[p] - reference) / reference;
          count++;
        }
      }
    } finally {
      surface.dispose();
    }
    expect(count).toBeGreaterThan(1948);
    // Measured 2026-12-02: 2.8% (k = 8 to 50 alike); the mesh's own heat method, between the same vertices, 2.2%.
    expect(sum / count).toBeLessThan(0.035);
  });

  it('is geometry-central’s PointCloudHeatSolver’s, up to the rounding of summing copies of a face once', () => {
    // Copies of one tufted face are summed once with their count as weight (geodesics/heat_distance.cpp):
    // the same arithmetic in another order. Measured 2026-12-05: at most 2.4e-15 of the largest distance.
    for (const source of [0, 1000]) {
      const ours = bobCloud.distance(source), reference = bobCloud.referenceDistance(source);
      const largest = Math.max(...reference);
      let worst = 0;
      for (let i = 0; i < ours.length; i++) worst = Math.max(worst, Math.abs(ours[i] - reference[i]));
      expect(worst).toBeLessThan(1e-12 * largest);
    }
  });

  it('from several points is near the least of their distances, near 0 at each', () => {
    const sources = [0, 700, 1400];
    const both = bobCloud.distanceFromPoints(sources);
    const singles = sources.map((s) => bobCloud.distance(s));
    // One additive constant for all sources: their mean is 0, each one near it.
    for (const s of sources) expect(both[s]).toBeLessThan(0.01 * bobCloud.facts.bboxDiagonal);
    let sum = 0;
    for (let p = 0; p < both.length; p++) sum += Math.abs(both[p] - Math.min(...singles.map((d) => d[p])));
    // Measured: 0.64% of the diagonal on average (the heat method smooths where the fronts meet).
    expect(sum / both.length / bobCloud.facts.bboxDiagonal).toBeLessThan(0.01);
  });

  it('hardly depends on the normals: every other one flipped, or PCA normals instead of the file’s', () => {
    const flipped = Float32Array.from(bob.normals ?? [], (x, i) => (Math.floor(i / 3) % 2 ? -x : x));
    const d = bobCloud.distance(0);
    for (const normals of [flipped, null]) {
      const other = core.openCloud({ positions: bob.positions, normals });
      try {
        let sum = 0;
        other.distance(0).forEach((x, p) => (sum += Math.abs(x - d[p])));
        // Measured: 0.03% (flipped) and 0.05% (PCA) of the diagonal on average.
        expect(sum / d.length / bobCloud.facts.bboxDiagonal).toBeLessThan(0.001);
      } finally {
        other.dispose();
      }
    }
  });

  it('refuses a source that is not a point of the cloud', () => {
    expect(() => bobCloud.distance(1948)).toThrow(new CoreError('point 1948 is out of range (the cloud has 1948 points)'));
    expect(() => bobCloud.distance(1.5)).toThrow(CoreError);
  });
});

describe('bad clouds', () => {
  const small = spherePoints(20, 3);

  it('are refused with an input error: k larger than the cloud, a non-finite coordinate', () => {
    const tooFew = (() => {
      try {
        core.openCloud(small);
      } catch (error) {
        return error;
      }
    })();
    expect(tooFew).toBeInstanceOf(CoreError);
    expect(tooFew).toMatchObject({ kind: 'input', message: 'the cloud has 20 points, too few for the neighbour count k = 30: every point needs k others' });
    const nan = Float64Array.from(small.positions);
    nan[4] = NaN;
    expect(() => core.openCloud({ positions: nan, normals: null }, { neighbours: 5 })).toThrow(new CoreError('point 1 has a non-finite coordinate'));
    expect(() => core.openCloud(small, { neighbours: 2 })).toThrow(new CoreError('option neighbours must be between 3 and 256, got 2'));
  });

  it('that do not fit in the memory limit are refused as out of memory, and the core goes on', async () => {
    // 20K points take about 140 MB (docs/pointcloud.md).
    const small = await loadCoreNode({ memoryLimitMB: 64 });
    expect(() => small.openCloud(readCloud(path.join(sharedData, 'pointclouds', 'bob_clean.ply')))).toThrow(
      new CoreError('out of memory: the point cloud needs more than 64 MB; subsample it to fewer points and try again', 'memory'),
    );
    const cloud = small.openCloud(bob);
    expect(cloud.facts.points).toBe(1948);
    cloud.dispose();
  });

  it('are refused by the CLI in one line, as meshes are', async () => {
    const file = path.join(tmp, 'small.ply');
    writeFileSync(file, cloudPly(Array.from({ length: 20 }, (_, i) => Array.from(small.positions.subarray(3 * i, 3 * i + 3))), null, 'ascii', 'float'));
    expect(await cscd('info', file)).toEqual({
      status: 1, stdout: '', stderr: 'cscd: the cloud has 20 points, too few for the neighbour count k = 30: every point needs k others\n',
    });
    expect(await cscd('info', file, '--neighbours', '2')).toMatchObject({ status: 2, stderr: "cscd: --neighbours must be an integer from 3 to 256, got '2'\n" });
    expect(JSON.parse((await cscd('info', file, '--neighbours', '8')).stdout)).toMatchObject({ points: 20, neighbours: 8 });
    expect(await cscd('info', sharedMesh('bob.ply'), '--neighbours', '8')).toMatchObject({ status: 2, stderr: `cscd: --neighbours does not apply to ${sharedMesh('bob.ply')}: it is a mesh\n` });
  });
});

describe('the CLI on a cloud', () => {
  it('info prints its facts', async () => {
    const file = fixture('clouds', 'bob_subsample.ply');
    const result = await cscd('info', file);
    expect(result.status, result.stderr).toBe(0);
    const report = JSON.parse(result.stdout);
    expect(report).toMatchObject({ file, format: 'ply', points: 1948, neighbours: 30, components: 1, normalsFromFile: true, warnings: [], repairs: [] });
    expect(report.bboxDiagonal).toBeCloseTo(2.5516, 3);
    expect(report.meanSpacing).toBeCloseTo(bobCloud.facts.meanSpacing, 12);
  });

  it('distance writes one distance per point of the file, 0 at the source', async () => {
    const result = await cscd('distance', fixture('clouds', 'bob_subsample.ply'), '--source', '100');
    expect(result.status, result.stderr).toBe(0);
    const { distance } = JSON.parse(result.stdout) as { distance: number[] };
    expect(distance).toEqual(Array.from(bobCloud.distance(100)));
    expect(await cscd('distance', fixture('clouds', 'bob_subsample.ply'), '--source', '1948')).toMatchObject({
      status: 2, stderr: "cscd: --source must be a point index from 0 to 1947, got '1948'\n",
    });
  });
});
