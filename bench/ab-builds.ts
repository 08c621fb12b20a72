// Two builds of the core against each other, in one process: each checkout's lib/core (and so its own
// build/wasm) is loaded, both open the same mesh's stage-1 surface, and the same sources are computed by
// one then the other, the order alternating from source to source, so that the drift of the machine's
// speed (+-15% from run to run here, and more over hours) falls on both alike. Reports the time per
// source of each and their ratio, and whether every candidate came out the same (length and score).
//
//   npm run bench:ab -- <checkout A> <checkout B> [--sources 150] [--note text] [meshes...]
//
// A checkout: a clone or `git worktree` with its core built (node_modules may be a link). Writes
// bench/results/<date>-ab.md (-2, -3... when taken).
import { readFileSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { defaultOptions } from '../lib/core/options.ts';
import type { Core } from '../lib/core/types.ts';
import { parseMesh } from '../lib/io/index.ts';
import { geometricMean } from './metrics.ts';
import { repoRoot, shell } from './process.ts';
import { claimResultName } from './result-name.ts';

const { positionals, values } = parseArgs({
  allowPositionals: true,
  options: { sources: { type: 'string', default: '150' }, note: { type: 'string', default: '' } },
});
const [rootA, rootB, ...meshNames] = positionals;
const sources = Number(values.sources);
if (!rootA || !rootB || !(sources >= 1)) {
  process.stderr.write('usage: npm run bench:ab -- <checkout A> <checkout B> [--sources 150] [--note text] [meshes...]\n');
  process.exit(2);
}
const meshes = meshNames.length ? meshNames : ['bob', 'hand', 'fertility', 'armadillo'];

async function loadFrom(root: string): Promise<Core> {
  const node = (await import(path.resolve(root, 'lib', 'core', 'node.ts'))) as { loadCoreNode(): Promise<Core> };
  return node.loadCoreNode();
}

const describe = (root: string) => `${path.resolve(root)} at ${shell('git', ['-C', root, 'rev-parse', '--short', 'HEAD'])}`
  + `${shell('git', ['-C', root, 'status', '--porcelain', '--untracked-files=no']) ? ' with uncommitted changes' : ''}`;
const cores = [await loadFrom(rootA), await loadFrom(rootB)];
const loadBefore = os.loadavg();
const rows: string[] = [];
const ratios: number[] = [];
for (const name of meshes) {
  const file = path.resolve(repoRoot, '..', 'shared', 'data', 'meshes', `${name}.ply`);
  const mesh = parseMesh(new Uint8Array(readFileSync(file)), file);
  const surfaces = cores.map((core) => core.openStage1Surface(mesh, defaultOptions));
  const pipelines = surfaces.map((surface) => surface.pipeline(defaultOptions));
  const vertices = surfaces[0].facts.vertices;
  const ms = [0, 0];
  let same = 0;
  for (let i = 0; i < sources; i++) {
    // Sources spread over the mesh by a stride coprime to any mesh size here.
    const source = Uint32Array.of((i * 7919) % vertices);
    const records = [];
    for (const k of i % 2 ? [1, 0] : [0, 1]) {
      const started = performance.now();
      records[k] = pipelines[k].separators(source)[0];
      ms[k] += performance.now() - started;
    }
    if (records[0].length === records[1].length && records[0].score === records[1].score) same++;
  }
  for (const p of pipelines) p.dispose();
  for (const s of surfaces) s.dispose();
  ratios.push(ms[1] / ms[0]);
  rows.push(`| ${name} | ${vertices} | ${(ms[0] / sources).toFixed(2)} | ${(ms[1] / sources).toFixed(2)} | ${(ms[1] / ms[0]).toFixed(3)} | ${same} of ${sources} |`);
  process.stdout.write(`${rows[rows.length - 1]}\n`);
}

const resultsDir = path.join(repoRoot, 'bench', 'results');
const name = claimResultName(resultsDir, `${new Date().toISOString().slice(0, 10)}-ab`, ['md']);
const cpu = /model name\s*:\s*(.*)/.exec(readFileSync('/proc/cpuinfo', 'utf8'))?.[1] ?? 'unknown CPU';
writeFileSync(path.join(resultsDir, `${name}.md`), [
  '# Two builds of the core, source by source',
  '',
  ...(values.note ? [values.note, ''] : []),
  `A: ${describe(rootA)}. B: ${describe(rootB)}.`,
  '',
  `Run on ${new Date().toISOString().replace(/\.\d+Z$/, 'Z')}. Machine: ${os.cpus().length} cores, ${cpu}; Node ${process.version}; load average ${loadBefore.map((x) => x.toFixed(2)).join(' ')} at the start.`,
  '',
  `\`npm run bench:ab -- ${process.argv.slice(2).join(' ')}\`: both cores in one process, each mesh's stage-1 surface (default options) opened in both, ${sources} sources computed by A and B in turn (\`pipeline.separators\`, the order alternating), ms per source; same: the candidates of A and B of equal length and score.`,
  '',
  '| mesh | stage-1 vertices | A, ms per source | B, ms per source | B / A | same |',
  '| --- | ---: | ---: | ---: | ---: | --- |',
  ...rows,
  '',
  `Geometric mean of B / A: ${geometricMean(ratios)?.toFixed(3)}.`,
  '',
].join('\n'));
process.stdout.write(`bench:ab: ${path.relative(repoRoot, path.join(resultsDir, name))}.md\n`);
