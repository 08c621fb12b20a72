// The cscd command in-process (run(argv, io)): JSON on stdout, one `cscd:` line on stderr and exit
// code 2 (usage) or 1 (anything else) on errors. The same through the bin: cli-smoke.test.ts.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, describe, expect, it, vi } from 'vitest';
import { getCore } from '../../cli/command.ts';
import { fixture, repoRoot, sharedMesh } from '../paths.ts';
import { cscd } from './support/cli.ts';

const tmp = mkdtempSync(path.join(tmpdir(), 'cscd-cli-'));
afterAll(() => rmSync(tmp, { recursive: true, force: true }));

/** Checks the error contract and returns the message after "cscd: ". */
function expectError(result: Awaited<ReturnType<typeof cscd>>, status: 1 | 2): string {
  expect(result.status).toBe(status);
  expect(result.stdout).toBe('');
  const lines = result.stderr.split('\n').filter((line) => line !== '');
  expect(lines).toHaveLength(1);
  expect(lines[0]).toMatch(/^cscd: /);
  return lines[0].slice('cscd: '.length);
}

describe('cscd', () => {
  it('--help lists the commands and exits 0', async () => {
    const result = await cscd('--help');
    expect(result.status).toBe(0);
    expect(result.stdout).toMatch(/info <mesh\|cloud>/);
    expect(result.stdout).toMatch(/distance <mesh\|cloud> \[options\]/);
    expect(result.stdout).toMatch(/separator <mesh\|cloud> \[options\]/);
    expect((await cscd('help', 'distance')).stdout).toMatch(/--source V\s+source vertex index/);
  });

  it('--version prints the package version', async () => {
    const { version } = JSON.parse(readFileSync(path.join(repoRoot, 'package.json'), 'utf8')) as { version: string };
    expect(await cscd('--version')).toEqual({ status: 0, stdout: `${version}\n`, stderr: '' });
  });

  it('info reports the topology of fertility (genus 4) as pretty JSON', async () => {
    const file = sharedMesh('fertility.ply');
    const result = await cscd('info', file);
    expect(result.status).toBe(0);
    expect(result.stdout).toMatch(/^\{\n {2}"file": /);
    expect(JSON.parse(result.stdout)).toMatchObject({
      file, format: 'ply', vertices: 12448, faces: 24908, genus: 4, components: 1, boundaryLoops: 0, warnings: [],
    });
  });

  it('info counts the boundary loops of torus_two_holes_open', async () => {
    expect(JSON.parse((await cscd('info', sharedMesh('torus_two_holes_open.ply'))).stdout)).toMatchObject({ boundaryLoops: 3, genus: 1 });
  });

  it('info includes parser warnings', async () => {
    const report = JSON.parse((await cscd('info', fixture('formats', 'cube.obj'))).stdout);
    expect(report).toMatchObject({ format: 'obj', vertices: 8, faces: 12, genus: 0 });
    expect(report.warnings).toEqual(['split 6 polygons with more than 3 vertices into triangles']);
  });

  it('distance --out writes one finite distance per vertex, 0 at the source', async () => {
    const out = path.join(tmp, 'd.json');
    const result = await cscd('distance', sharedMesh('fertility_9k.ply'), '--source', '0', '--out', out);
    expect(result).toEqual({ status: 0, stdout: '', stderr: '' });
    const { distance } = JSON.parse(readFileSync(out, 'utf8')) as { distance: number[] };
    expect(distance).toHaveLength(4494);
    expect(distance.every(Number.isFinite)).toBe(true);
    expect(distance[0]).toBeCloseTo(0, 6);
    expect(Math.max(...distance)).toBeGreaterThan(100); // the bbox diagonal is 256
  });

  it('distance without --out writes the JSON to stdout', async () => {
    const result = await cscd('distance', sharedMesh('two_torus.ply'), '--source', '5');
    expect(result.status).toBe(0);
    const { distance } = JSON.parse(result.stdout) as { distance: number[] };
    expect(distance).toHaveLength(766);
    expect(distance[5]).toBeCloseTo(0, 6);
  });

  it('rejects a bad source index with a usage error', async () => {
    const mesh = sharedMesh('two_torus.ply');
    expect(expectError(await cscd('distance', mesh, '--source', '766'), 2)).toBe("--source must be a vertex index from 0 to 765, got '766'");
    expect(expectError(await cscd('distance', mesh, '--source', 'abc'), 2)).toMatch(/^--source must be a vertex index/);
    expect(expectError(await cscd('distance', mesh), 2)).toMatch(/^distance: --source is required/);
  });

  it('reports a malformed or missing file on one line with exit code 1', async () => {
    const broken = path.join(tmp, 'broken.ply');
    writeFileSync(broken, readFileSync(sharedMesh('two_torus.ply')).subarray(0, 5000));
    expect(expectError(await cscd('info', broken), 1)).toBe('PLY: header claims 766 vertices but the file has only 4798 bytes of data');
    expect(expectError(await cscd('distance', broken, '--source', '0'), 1)).toMatch(/^PLY: /);
    expect(expectError(await cscd('info', path.join(tmp, 'missing.obj')), 1)).toMatch(/^cannot read '.*missing\.obj': no such file$/);
  });

  it('reports usage errors with exit code 2', async () => {
    expect(expectError(await cscd('frobnicate'), 2)).toBe("unknown command 'frobnicate' (see cscd --help)");
    expect(expectError(await cscd('info'), 2)).toMatch(/^info: expected <mesh\|cloud>, got 0 arguments/);
    expect(expectError(await cscd('info', 'a.ply', '--bogus'), 2)).toMatch(/^info: Unknown option '--bogus'/);
  });

  it('shares one core across runs; a WASM abort is one line, exit 1, and the next run loads a fresh core', async () => {
    const mesh = sharedMesh('two_torus.ply');
    const core = await getCore();
    expect((await cscd('info', mesh)).status).toBe(0);
    expect(await getCore()).toBe(core);
    // What emscripten's abort() throws.
    const inspect = vi.spyOn(core, 'inspect').mockImplementation(() => {
      throw new WebAssembly.RuntimeError('Aborted(simulated)');
    });
    try {
      expect(expectError(await cscd('info', mesh), 1)).toBe('RuntimeError: Aborted(simulated)');
    } finally {
      inspect.mockRestore();
    }
    expect(await getCore()).not.toBe(core);
    expect(JSON.parse((await cscd('info', mesh)).stdout)).toMatchObject({ vertices: 766, genus: 2 });
  });
});
