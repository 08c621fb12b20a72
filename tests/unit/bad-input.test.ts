// The bad-input corpus (tests/fixtures/bad, written by make.ts) through the CLI, in-process: every file
// ends in its expected outcome with one clear line per message, no stack trace and no hang (in a child
// process, killed when it hangs: cli-smoke.test.ts).
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { fixture, repoRoot } from '../paths.ts';
import { cscd } from './support/cli.ts';

interface Expected {
  what: string;
  outcome: 'error' | 'repaired' | 'ok';
  match: string;
  /** Error fragment of `cscd skeleton` on a file that loads but cannot be skeletonised. */
  skeleton?: string;
}

const folder = fixture('bad');
const expected = JSON.parse(readFileSync(path.join(folder, 'expected.json'), 'utf8')) as Record<string, Expected>;
const cases = Object.entries(expected);
/** Every run of a tiny file must end well within this, whatever the file claims. */
const BOUND_MS = 20_000;

async function run(...args: string[]) {
  const started = performance.now();
  const result = await cscd(...args);
  expect(performance.now() - started, `cscd ${args.join(' ')} finished within ${BOUND_MS} ms`).toBeLessThan(BOUND_MS);
  // Users see our messages, never a stack trace or a crash.
  expect(result.stderr).not.toMatch(/^\s+at |node:internal|RuntimeError|TypeError|Aborted/m);
  return result;
}

describe('the corpus', () => {
  it('holds at least 30 files, each with an expected outcome', () => {
    const files = readdirSync(folder).filter((name) => !['make.ts', 'README.md', 'expected.json', '.gitattributes'].includes(name));
    expect(files.length).toBeGreaterThanOrEqual(30);
    expect(files.sort()).toEqual(Object.keys(expected).sort());
    for (const outcome of ['error', 'repaired', 'ok']) expect(cases.filter(([, e]) => e.outcome === outcome).length).toBeGreaterThanOrEqual(8);
  });

  it('is what make.ts writes', () => {
    const out = mkdtempSync(path.join(tmpdir(), 'cscd-bad-'));
    const made = spawnSync(process.execPath, ['--import', 'tsx', path.join(folder, 'make.ts'), out], { cwd: repoRoot, encoding: 'utf8' });
    expect(made.status, made.stderr).toBe(0);
    for (const name of [...Object.keys(expected), 'expected.json']) {
      expect(readFileSync(path.join(out, name)), name).toEqual(readFileSync(path.join(folder, name)));
    }
  });
});

describe.each(cases)('%s', (file, e) => {
  const mesh = path.join(folder, file);

  it(`info: ${e.outcome}${e.match ? ` (${e.match})` : ''}`, async () => {
    const result = await run('info', mesh);
    if (e.outcome === 'error') {
      expect(result.status).toBe(1);
      expect(result.stdout).toBe('');
      expect(result.stderr).toMatch(/^cscd: [^\n]+\n$/);
      expect(result.stderr).toContain(e.match);
      return;
    }
    expect(result.status, result.stderr).toBe(0);
    expect(result.stderr).toBe('');
    const report = JSON.parse(result.stdout) as Record<string, unknown> & { repairs: string[]; warnings: string[] };
    if (e.outcome === 'repaired') expect(report.repairs.some((r) => r.includes(e.match)), report.repairs.join('; ')).toBe(true);
    else expect(report.repairs).toEqual([]);
    if (e.outcome === 'ok' && e.match) expect(report.warnings.some((w) => w.includes(e.match)), report.warnings.join('; ')).toBe(true);
    // After the repairs the core has what it needs, unless the file is beyond repair.
    if (!e.skeleton) {
      expect(report).toMatchObject({ manifold: true, consistentlyOriented: true, degenerateFaces: 0, unreferencedVertices: 0 });
    }
  });

  it.skipIf(e.outcome === 'error')(`skeleton --n 8: ${e.skeleton ? `fails (${e.skeleton})` : 'a skeleton'}`, async () => {
    const result = await run('skeleton', '--n', '8', mesh);
    // Every line on stderr is one of ours: warnings, repairs, or the error.
    for (const line of result.stderr.trimEnd().split('\n').filter(Boolean)) expect(line).toMatch(/^cscd: /);
    if (e.outcome === 'repaired') expect(result.stderr).toContain(`cscd: repaired: ${e.match}`);
    if (e.skeleton) {
      expect(result.status).toBe(1);
      expect(result.stderr.trimEnd().split('\n').at(-1)).toContain(e.skeleton);
      return;
    }
    expect(result.status, result.stderr).toBe(0);
    const skeleton = JSON.parse(result.stdout) as { nodes: number[][] };
    expect(skeleton.nodes.length).toBeGreaterThanOrEqual(1);
    expect(skeleton.nodes.flat().every(Number.isFinite)).toBe(true);
  });
});

describe('vertex numbering after a repair', () => {
  it('cscd distance keeps the numbering of the file', async () => {
    // seams.obj: the cube with four vertices per quad; welded copies are one vertex, so one distance.
    const seams = JSON.parse((await run('distance', path.join(folder, 'seams.obj'), '--source', '0')).stdout) as { distance: number[] };
    expect(seams.distance).toHaveLength(24);
    const lines = readFileSync(path.join(folder, 'seams.obj'), 'utf8').split('\n').filter((line) => line.startsWith('v '));
    const atOrigin = lines.flatMap((line, i) => (line === 'v 0 0 0' ? [i] : []));
    expect(atOrigin.length).toBeGreaterThan(1);
    for (const v of atOrigin) expect(seams.distance[v]).toBe(0);

    // nan_unused_vertex.obj: the fifth vertex is removed, so it has no distance and cannot be a source.
    const unused = path.join(folder, 'nan_unused_vertex.obj');
    const result = JSON.parse((await run('distance', unused, '--source', '0')).stdout) as { distance: (number | null)[] };
    expect(result.distance).toHaveLength(5);
    expect(result.distance[4]).toBeNull();
    expect(result.distance.slice(0, 4).every((d) => typeof d === 'number')).toBe(true);
    const removed = await run('distance', unused, '--source', '4');
    expect(removed.status).toBe(2);
    expect(removed.stderr.trimEnd().split('\n').at(-1)).toBe('cscd: --source 4 is a vertex used by no face, which the repair removed');
  });
});
