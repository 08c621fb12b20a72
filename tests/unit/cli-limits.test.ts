// The CLI (in-process) on large meshes: a 1M-face binary PLY through `info` in seconds (no solver is
// opened), --decimate on info and skeleton, and the size warning of a command that opens the solver.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { FACE_LIMIT } from '../../lib/mesh/limits.ts';
import { binaryPly, torusOfFaces } from './support/big-mesh.ts';
import { cscd } from './support/cli.ts';

let folder: string;
const file = (name: string) => path.join(folder, name);

beforeAll(() => {
  folder = mkdtempSync(path.join(tmpdir(), 'cscd-cli-limits-'));
  writeFileSync(file('torus-1m.ply'), binaryPly(torusOfFaces(1_000_000)));
  writeFileSync(file('torus-above.ply'), binaryPly(torusOfFaces(FACE_LIMIT + 10_000)));
});
afterAll(() => rmSync(folder, { recursive: true, force: true }));

describe('cscd on large meshes', () => {
  it('prints the facts of a 1M-face mesh within 30 s', async () => {
    const started = performance.now();
    const result = await cscd('info', file('torus-1m.ply'));
    expect(performance.now() - started).toBeLessThan(30_000);
    expect(result.status).toBe(0);
    const facts = JSON.parse(result.stdout);
    expect(facts).toMatchObject({ faces: 1_000_008, vertices: 500_004, genus: 1, manifold: true });
  }, 40_000);

  it('decimates with --decimate K, keeping the topology, and says so', async () => {
    const result = await cscd('info', file('torus-above.ply'), '--decimate', '4000');
    expect(result.status).toBe(0);
    expect(result.stderr).toMatch(/^cscd: decimated .*torus-above\.ply from 21\d{4} to 4000 faces in [\d.]+ s\n$/);
    const facts = JSON.parse(result.stdout);
    expect(facts).toMatchObject({ faces: 4000, genus: 1, components: 1, boundaryLoops: 0, manifold: true });
    expect(facts.decimatedFrom).toBeGreaterThan(FACE_LIMIT);
  }, 60_000);

  it('computes the skeleton of a decimated mesh without the size warning', async () => {
    const result = await cscd('skeleton', file('torus-above.ply'), '--decimate', '3000', '--n', '8');
    expect(result.status).toBe(0);
    expect(result.stderr).not.toMatch(/warning/);
    expect(JSON.parse(result.stdout).stats.cycles).toBe(1);
  }, 120_000);

  it('warns above the size limit, with the expected solver time and the way out', async () => {
    const result = await cscd('distance', file('torus-above.ply'), '--source', '0', '--out', file('d.json'));
    expect(result.status).toBe(0);
    expect(result.stderr).toMatch(/cscd: warning: .*torus-above\.ply: this mesh has 21\d{4} faces; preparing the geodesic solver takes about \d+ s \(--decimate 100000 makes it faster\)/);
  }, 120_000);

  it('refuses a --decimate that is not a face count', async () => {
    const result = await cscd('info', file('torus-above.ply'), '--decimate', 'many');
    expect(result.status).toBe(2);
    expect(result.stderr).toBe("cscd: --decimate must be a whole number of faces (at least 4), got 'many'\n");
  });
});
