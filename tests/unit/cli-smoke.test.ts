// The bin, cli/cscd.mjs, as users run it: a child process, its exit status and both output streams.
// Everything else about the commands is checked in-process (cli*.test.ts, bad-input.test.ts); these
// cover what only the process shows: start-up through tsx, process.exitCode, real stdout and stderr.
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import type { SkeletonJson } from '../../lib/io/skeleton.ts';
import { fixture, repoRoot, sharedMesh } from '../paths.ts';
import { cscdProcess } from './support/cli.ts';

const tmp = mkdtempSync(path.join(tmpdir(), 'cscd-smoke-'));
afterAll(() => rmSync(tmp, { recursive: true, force: true }));

/** A tiny file must be done with well within this, whatever it claims. */
const BOUND_MS = 20_000;

describe('cscd (child process)', () => {
  it('prints its help and version with exit 0, and exits 2 on an unknown command', () => {
    const help = cscdProcess(['--help']);
    expect(help.status).toBe(0);
    expect(help.stdout).toMatch(/^cscd \d+\.\d+\.\d+: curve skeletons/);
    expect(help.stdout).toMatch(/skeleton <mesh\|cloud> \[options\]/);
    expect(help.stderr).toBe('');
    const { version } = JSON.parse(readFileSync(path.join(repoRoot, 'package.json'), 'utf8')) as { version: string };
    expect(cscdProcess(['--version'])).toMatchObject({ status: 0, stdout: `${version}\n`, stderr: '' });
    expect(cscdProcess(['frobnicate'])).toMatchObject({ status: 2, stdout: '', stderr: "cscd: unknown command 'frobnicate' (see cscd --help)\n" });
  });

  it('writes a skeleton to --out with nothing on stdout or stderr', () => {
    const out = path.join(tmp, 'skel.json');
    expect(cscdProcess(['skeleton', sharedMesh('two_torus.ply'), '--n', '8', '--out', out])).toMatchObject({ status: 0, stdout: '', stderr: '' });
    const skeleton = JSON.parse(readFileSync(out, 'utf8')) as SkeletonJson;
    expect(skeleton.stats.n).toBe(8);
    expect(skeleton.vertexToNode).toHaveLength(766);
  });

  it('reports a bad file on one line with exit 1, without hanging on what its header claims', () => {
    const result = cscdProcess(['info', fixture('bad', 'huge_header_claim.ply')], { timeout: BOUND_MS });
    expect(result.timedOut).toBe(false);
    expect(result).toMatchObject({ status: 1, stdout: '', stderr: 'cscd: PLY: header claims 100000000 vertices but the file has only 100 bytes of data\n' });
  });

  it("reports the core's error on one line with exit 1, no stack trace", () => {
    // The core refuses a Moebius strip: no orientation is consistent (a CoreError of kind input).
    const result = cscdProcess(['skeleton', fixture('bad', 'moebius.obj'), '--n', '8'], { timeout: BOUND_MS });
    expect(result).toMatchObject({ status: 1, stdout: '', timedOut: false });
    expect(result.stderr).toMatch(/^cscd: the mesh is not a manifold surface: faces are not consistently oriented: [^\n]+\n$/);
  });
});
