// A mesh run as a point cloud of its vertices (lib/cloud/from-mesh.ts, the CLI's --as-cloud, the page's
// asCloud box): the points and their normals, and the CLI's commands on the shared spot mesh.
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { meshAsCloud } from '../../lib/cloud/from-mesh.ts';
import { fixture, sharedMesh } from '../paths.ts';
import { cscd } from './support/cli.ts';

/** A closed tetrahedron, outward faces, and a fifth vertex used by no face. */
const tetrahedron = {
  positions: new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 5, 5]),
  triangles: new Uint32Array([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]),
};

describe('meshAsCloud', () => {
  it('makes the vertices of the faces points, with outward unit normals, and leaves the others out', () => {
    const { cloud, pointOfVertex, note } = meshAsCloud(tetrahedron);
    expect(Array.from(pointOfVertex)).toEqual([0, 1, 2, 3, -1]);
    expect(Array.from(cloud.positions)).toEqual(Array.from(tetrahedron.positions.subarray(0, 12)));
    const normals = cloud.normals!;
    const centre = [0.25, 0.25, 0.25];
    for (let p = 0; p < 4; p++) {
      const n = Array.from(normals.subarray(3 * p, 3 * p + 3));
      expect(Math.hypot(...n)).toBeCloseTo(1, 6);
      const out = n.reduce((sum, c, k) => sum + c * (cloud.positions[3 * p + k] - centre[k]), 0);
      expect(out, `point ${p}'s normal points out`).toBeGreaterThan(0);
    }
    // The corner at the origin: its three faces' normals (-x, -y, -z, equal areas) sum to the diagonal.
    expect(Array.from(normals.subarray(0, 3)).map((c) => c * Math.sqrt(3))).toEqual([-1, -1, -1].map((c) => expect.closeTo(c, 5)));
    expect(note).toBe('the mesh runs as a point cloud: its 4 vertices (1 used by no face left out), with their faces’ normals');
  });

  it('gives no normals at all when the normals of some vertex\'s faces cancel out', () => {
    // A double-sided triangle: the same three vertices wound both ways, whose normals sum to 0 at each.
    const folded = { positions: tetrahedron.positions.subarray(0, 9), triangles: new Uint32Array([0, 1, 2, 0, 2, 1]) };
    const { cloud, note } = meshAsCloud(folded);
    expect(cloud.normals).toBeNull();
    expect(note).toContain('without normals');
  });
});

describe('cscd --as-cloud', () => {
  const spot = sharedMesh('spot.ply'); // 2930 vertices, genus 0

  it('info: the mesh\'s vertices as a cloud, with the note', async () => {
    const { status, stdout } = await cscd('info', spot, '--as-cloud');
    expect(status).toBe(0);
    const info = JSON.parse(stdout);
    expect(info).toMatchObject({ format: 'ply', points: 2930, normalsFromFile: true, components: 1 });
    expect(info.warnings).toEqual(['the mesh runs as a point cloud: its 2930 vertices, with their faces’ normals']);
    expect(info.faces).toBeUndefined();
  });

  it('distance and skeleton run on the points, numbered as the file\'s vertices', async () => {
    const distance = await cscd('distance', spot, '--as-cloud', '--source', '7');
    expect(distance.status).toBe(0);
    const d = JSON.parse(distance.stdout).distance as number[];
    expect(d).toHaveLength(2930);
    expect(d[7]).toBe(0);
    expect(Math.min(...d.filter((_, i) => i !== 7))).toBeGreaterThan(0);

    const dir = mkdtempSync(path.join(tmpdir(), 'cscd-as-cloud-'));
    try {
      const out = path.join(dir, 'spot.json');
      const { status, stderr } = await cscd('skeleton', spot, '--as-cloud', '--n', '12', '--out', out);
      expect(status).toBe(0);
      expect(stderr).toContain('the mesh runs as a point cloud');
      const skeleton = JSON.parse(readFileSync(out, 'utf8'));
      expect(skeleton.vertexToNode).toHaveLength(2930);
      expect(skeleton.stats.cycles).toBe(0);
      const onMesh = await cscd('evaluate', spot, out);
      expect(onMesh.status).toBe(0);
      expect(JSON.parse(onMesh.stdout).reconError).toBeGreaterThan(0);
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  }, 60_000);

  it('is refused on a cloud file and takes --neighbours, not a mesh\'s --decimate', async () => {
    const onCloud = await cscd('info', fixture('clouds', 'bob_subsample.ply'), '--as-cloud');
    expect(onCloud.status).toBe(2);
    expect(onCloud.stderr).toContain('--as-cloud does not apply to');
    expect(onCloud.stderr).toContain('it is a point cloud already');
    expect((await cscd('info', spot, '--as-cloud', '--neighbours', '12')).status).toBe(0);
    const decimated = await cscd('info', spot, '--as-cloud', '--decimate', '1000');
    expect(decimated.status).toBe(2);
    expect(decimated.stderr).toContain('--decimate does not apply');
  });
});
