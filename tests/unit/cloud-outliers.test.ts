// Stray points of a scan (lib/cloud/outliers.ts, step 4 of lib/io/cloud-check.ts) and the k-d tree
// they are found with (lib/cloud/nearest.ts): no point of a real cloud goes, the lone strays of
// bob_strays.ply all go, and with them gone its skeleton is bob's again; pairs of strays go, fragments
// as dense as the surface stay; a mesh's vertices keep theirs.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { nearestNeighbours } from '../../lib/cloud/nearest.ts';
import { findOutliers } from '../../lib/cloud/outliers.ts';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import { random } from '../../lib/core/random.ts';
import { checkCloud } from '../../lib/io/cloud-check.ts';
import type { CloudArrays } from '../../lib/io/index.ts';
import { fixture, sharedMesh } from '../paths.ts';
import { cscd } from './support/cli.ts';
import { readCloudFile } from './support/clouds.ts';
import { icosphere, readMesh } from './support/meshes.ts';

/** bob_subsample.ply's 1948 points (normals dropped) followed by 24 strays 0.6-1 diagonals from its centre (make.ts). */
const BOB_POINTS = 1948;
const STRAYS = 24;

describe('nearestNeighbours', () => {
  it('finds what a scan of every pair finds, ties ranked by index', () => {
    const next = random(3);
    // Coordinates on a grid of quarters: many equal distances.
    const n = 300, k = 16;
    const positions = Float64Array.from({ length: 3 * n }, () => Math.round(next() * 12) / 4);
    const { index, distance } = nearestNeighbours(positions, k);
    for (let p = 0; p < n; p++) {
      const d2 = (q: number) => (positions[3 * q] - positions[3 * p]) ** 2 + (positions[3 * q + 1] - positions[3 * p + 1]) ** 2 + (positions[3 * q + 2] - positions[3 * p + 2]) ** 2;
      const ranked = Array.from({ length: n }, (_, q) => q).filter((q) => q !== p).sort((a, b) => d2(a) - d2(b) || a - b).slice(0, k);
      expect(Array.from(index.subarray(p * k, p * k + k)), `point ${p}`).toEqual(ranked);
      expect(Array.from(distance.subarray(p * k, p * k + k))).toEqual(ranked.map((q) => Math.sqrt(d2(q))));
    }
  });
});

describe('stray points', () => {
  it.each([
    'bob_subsample.ply', 'hand_subsample.ply', 'bob_noise_subsample.ply', 'hand_noise_subsample.ply',
    'torus_open_noise_subsample.ply', 'tree_sw_trunk.ply', 'armadillo_gel_pts.ply',
  ])('none in the real cloud %s', (name) => {
    const outliers = findOutliers(readCloudFile(fixture('clouds', name)).positions);
    expect(outliers.reduce((sum, x) => sum + x, 0)).toBe(0);
  });

  it('bob_strays.ply: the checks remove the strays, saying so, and leave bob\'s points as they were', () => {
    const strays = readCloudFile(fixture('clouds', 'bob_strays.ply'));
    const bob = readCloudFile(fixture('clouds', 'bob_subsample.ply'));
    const { cloud, repairs, pointMap } = checkCloud(strays, 30);
    expect(repairs).toEqual([
      `removed ${STRAYS} stray points (alone or in twos and threes, more than 3 times as far from the other points as those are from their 16th nearest)`,
    ]);
    expect(Array.from(pointMap)).toEqual([...Array.from({ length: BOB_POINTS }, (_, i) => i), ...Array<number>(STRAYS).fill(-1)]);
    expect(Array.from(cloud.positions)).toEqual(Array.from(bob.positions));
  });

  it('removes a pair standing apart together, but not one as close as the surface\'s points (a fragment)', () => {
    // bob_subsample's neighbourhoods are 0.10-0.14 wide (16th nearest). Far from bob: two points 0.05
    // apart (closer than a width: a fragment sampled like the surface, as a twig hit by two beams), two
    // 0.22 apart (within 3 widths of each other, more than one apart: strays), and one alone.
    const bob = readCloudFile(fixture('clouds', 'bob_subsample.ply')).positions;
    const positions = Float64Array.from([...Array.from(bob), 6, 0, 0, 6, 0.05, 0, 0, 6, 0, 0, 6.22, 0, 0, 0, 6]);
    const outliers = findOutliers(positions);
    expect(Array.from(outliers.subarray(BOB_POINTS))).toEqual([0, 0, 1, 1, 1]);
    expect(outliers.subarray(0, BOB_POINTS).every((x) => x === 0)).toBe(true);
  });
});

describe('the skeleton of a cloud with strays', () => {
  let core: Core;
  beforeAll(async () => {
    core = await loadCoreNode();
  });

  /** The skeleton (n = 40, seed 1) of a cloud and its error against the bob mesh. */
  function skeletonOf(cloud: CloudArrays) {
    const opened = core.openCloud(cloud);
    try {
      const skeleton = opened.skeleton({ n: 40, seed: 1 });
      const { reconError } = core.evaluate(readMesh(sharedMesh('bob.ply')), { nodes: skeleton.nodes, edges: skeleton.edges, radii: null });
      return { skeleton, reconError };
    } finally {
      opened.dispose();
    }
  }

  it('is bob\'s once the checks removed them; with them, its error is several times bob\'s', () => {
    const strays = readCloudFile(fixture('clouds', 'bob_strays.ply'));
    const bob = readCloudFile(fixture('clouds', 'bob_subsample.ply'));
    const alone = skeletonOf({ positions: bob.positions, normals: null });
    const checked = skeletonOf(checkCloud(strays, 30).cloud);
    expect(checked.skeleton.nodes).toEqual(alone.skeleton.nodes);
    expect(checked.skeleton.edges).toEqual(alone.skeleton.edges);
    // Measured: 0.0856 without strays, 0.237 with them kept (the step off); 0.0367 and 0.336 before clean
    // clouds' targets took fronts that meet at a shallow angle (docs/pointcloud.md).
    const kept = skeletonOf(checkCloud(strays, 30, { outliers: false }).cloud);
    expect(kept.reconError).toBeGreaterThan(2 * alone.reconError);
  }, 60_000);
});

describe('the CLI', () => {
  it('says how many strays it removed', async () => {
    const { status, stdout } = await cscd('info', fixture('clouds', 'bob_strays.ply'));
    expect(status).toBe(0);
    const info = JSON.parse(stdout);
    expect(info.points).toBe(BOB_POINTS);
    expect(info.repairs[0]).toMatch(/^removed 24 stray points/);
  });

  it('distance: null at the strays, which cannot be a source', async () => {
    const file = fixture('clouds', 'bob_strays.ply');
    const { status, stdout } = await cscd('distance', file, '--source', '7');
    expect(status).toBe(0);
    const distance = JSON.parse(stdout).distance as (number | null)[];
    expect(distance).toHaveLength(BOB_POINTS + STRAYS);
    expect(distance.slice(BOB_POINTS)).toEqual(Array(STRAYS).fill(null));
    expect(distance.slice(0, BOB_POINTS).every((d) => typeof d === 'number')).toBe(true);
    const refused = await cscd('distance', file, '--source', String(BOB_POINTS));
    expect(refused.status).toBe(2);
    expect(refused.stderr).toContain(`--source ${BOB_POINTS} is a point the checks removed (a non-finite coordinate, a stray point`);
  });

  it('keeps every vertex of a mesh run as a cloud: they lie on its surface, however apart', async () => {
    // An icosphere and a large triangle far from it: as a cloud file, each of its corners is a stray.
    const sphere = icosphere(3);
    const vertices = [...Array.from(sphere.positions), 10, 0, 0, 15, 0, 0, 10, 5, 0];
    const faces = [...Array.from(sphere.triangles), ...[0, 1, 2].map((i) => sphere.positions.length / 3 + i)];
    const v = (i: number) => `v ${vertices[3 * i]} ${vertices[3 * i + 1]} ${vertices[3 * i + 2]}`;
    const lines = Array.from({ length: vertices.length / 3 }, (_, i) => v(i));
    const dir = mkdtempSync(path.join(tmpdir(), 'cscd-strays-'));
    try {
      const mesh = path.join(dir, 'mesh.obj'), cloud = path.join(dir, 'cloud.obj');
      writeFileSync(mesh, [...lines, ...Array.from({ length: faces.length / 3 }, (_, f) => `f ${faces.slice(3 * f, 3 * f + 3).map((i) => i + 1).join(' ')}`)].join('\n'));
      writeFileSync(cloud, lines.join('\n'));
      const asCloud = JSON.parse((await cscd('info', mesh, '--as-cloud')).stdout);
      expect(asCloud.points).toBe(vertices.length / 3);
      expect(asCloud.repairs).toEqual([]);
      const points = JSON.parse((await cscd('info', cloud)).stdout);
      expect(points.points).toBe(vertices.length / 3 - 3);
      expect(points.repairs[0]).toMatch(/^removed 3 stray points/);
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
});
