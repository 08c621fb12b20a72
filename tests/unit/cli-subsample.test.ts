// --subsample K (in-process CLI): a cloud computed on about K of its points, the page's subsample of a
// cloud above the point limit. tests/fixtures/clouds/bob_subsample.ply is that subsample of bob_clean.ply
// (lib/cloud/subsample.ts, target 2000, seed 1), written by make.ts: the CLI must compute on exactly it.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { POINT_LIMIT } from '../../lib/mesh/limits.ts';
import { fixture, sharedData, sharedMesh } from '../paths.ts';
import { cscd } from './support/cli.ts';
import { torusPoints, xyzText } from './support/clouds.ts';

const bobClean = path.join(sharedData, 'pointclouds', 'bob_clean.ply');
const bobSubsample = fixture('clouds', 'bob_subsample.ply');

let folder: string;
beforeAll(() => {
  folder = mkdtempSync(path.join(tmpdir(), 'cscd-cli-subsample-'));
});
afterAll(() => rmSync(folder, { recursive: true, force: true }));

/** A skeleton's JSON without what differs between two files of the same points: the path and the timings. */
function skeletonOf(stdout: string) {
  const { mesh: _, stats: { timings: __, ...stats }, ...skeleton } = JSON.parse(stdout);
  return { ...skeleton, stats };
}

describe('cscd --subsample K', () => {
  it('computes the skeleton on the subsample the page would compute on, and says so', async () => {
    const subsampled = await cscd('skeleton', bobClean, '--subsample', '2000', '--n', '8');
    expect(subsampled.status).toBe(0);
    expect(subsampled.stderr).toMatch(/^cscd: subsampled .*bob_clean\.ply from 20000 to 1948 points \(Poisson-disk, seed 1\) in [\d.]+ s\n$/);
    const ofFixture = await cscd('skeleton', bobSubsample, '--n', '8');
    expect(ofFixture.status).toBe(0);
    const skeleton = skeletonOf(subsampled.stdout);
    expect(skeleton.vertexToNode).toHaveLength(1948);
    expect(skeleton).toEqual(skeletonOf(ofFixture.stdout));
  }, 60_000);

  it('reports the facts of the subsample with the count before, and leaves a cloud of fewer points as it is', async () => {
    const result = await cscd('info', bobClean, '--subsample', '2000');
    expect(result.status).toBe(0);
    expect(JSON.parse(result.stdout)).toMatchObject({ points: 1948, subsampledFrom: 20000 });
    const asIs = await cscd('info', bobSubsample, '--subsample', '2000');
    expect(asIs.stderr).toBe('');
    expect(JSON.parse(asIs.stdout)).toMatchObject({ points: 1948 });
    expect(JSON.parse(asIs.stdout)).not.toHaveProperty('subsampledFrom');
  }, 60_000);

  it('gives every point of the file a distance: a point left out has that of the kept point standing for it', async () => {
    const out = path.join(folder, 'distance.json');
    const result = await cscd('distance', bobClean, '--subsample', '2000', '--source', '0', '--out', out);
    expect(result.status).toBe(0);
    const { distance } = JSON.parse((await import('node:fs')).readFileSync(out, 'utf8')) as { distance: number[] };
    expect(distance).toHaveLength(20000);
    expect(distance[0]).toBe(0);
    expect(distance.every(Number.isFinite)).toBe(true);
    expect(new Set(distance).size).toBe(1948);
  }, 60_000);

  it('warns above the point limit with the flag that helps, and not once the cloud is subsampled', async () => {
    const big = path.join(folder, 'torus-above.xyz');
    writeFileSync(big, xyzText(torusPoints(POINT_LIMIT + 1000, 1, 0.3, 1).positions));
    const warned = await cscd('info', big, '--neighbours', '10'); // fewer neighbours: opened sooner
    expect(warned.status).toBe(0);
    expect(warned.stderr).toMatch(/cscd: warning: .*torus-above\.xyz: this point cloud has 101000 points, more than the 100000 advised; subsample it to about 50000 \(--subsample 50000\)\n/);
    const subsampled = await cscd('info', big, '--subsample', '3000');
    expect(subsampled.stderr).toMatch(/^cscd: subsampled .*torus-above\.xyz from 101000 to 2\d{3} points \(Poisson-disk, seed 1\) in [\d.]+ s\n$/);
    expect(JSON.parse(subsampled.stdout)).toMatchObject({ subsampledFrom: 101000, components: 1 });
  }, 120_000);

  it('is a usage error on a mesh and below the neighbour count', async () => {
    const onMesh = await cscd('skeleton', sharedMesh('bob.ply'), '--subsample', '1000');
    expect(onMesh).toMatchObject({ status: 2, stderr: `cscd: --subsample does not apply to ${sharedMesh('bob.ply')}: it is a mesh\n` });
    const tooFew = await cscd('info', bobSubsample, '--subsample', '20');
    expect(tooFew).toMatchObject({ status: 2, stderr: "cscd: --subsample must be a whole number of points above the 30 neighbours, got '20'\n" });
  });
});
