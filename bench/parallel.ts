// Stage 1 on one and on two threads (issue: all cores): CSCD on each mesh with `--round-size R`, once
// with one thread and once with K, each in a process of its own (bench/runners/cscd.ts), the order of
// the two alternating from mesh to mesh so that drift of the machine affects both alike. Reports the
// times, their ratio and whether the two skeletons are the same (they must be), as a table in
// bench/results/<date>-parallel.md.
//
//   node --import tsx bench/parallel.ts [--round-size 8] [--workers 2] [--min-vertices 10000] [meshes...]
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { parseMesh } from '../lib/io/index.ts';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const { positionals, values } = parseArgs({
  allowPositionals: true,
  options: { 'round-size': { type: 'string', default: '8' }, workers: { type: 'string', default: '2' }, 'min-vertices': { type: 'string', default: '10000' } },
});
const roundSize = values['round-size'], workers = values.workers, minVertices = Number(values['min-vertices']);
const folder = path.resolve(repoRoot, '..', 'shared', 'data', 'meshes');
const synthetic = path.resolve(repoRoot, '..', 'shared', 'data', 'synthetic');
const all = [folder, synthetic].flatMap((d) => readdirSync(d).filter((f) => f.endsWith('.ply')).map((f) => path.join(d, f)));
const files = (positionals.length ? all.filter((f) => positionals.includes(path.basename(f, '.ply'))) : all)
  .map((file) => ({ file, vertices: parseMesh(readFileSync(file), file).positions.length / 3 }))
  .filter((m) => m.vertices > minVertices);
const tmp = mkdtempSync(path.join(os.tmpdir(), 'cscd-parallel-'));
const loadBefore = os.loadavg();

function run(file: string, threads: string): { seconds: number; stage1Seconds: number; memoryMB: number; json: string } {
  const out = path.join(tmp, `${path.basename(file)}-${threads}.json`);
  const result = spawnSync(process.execPath, ['--import', 'tsx', 'bench/runners/cscd.ts', file, out, '--workers', threads, '--round-size', roundSize], {
    cwd: repoRoot,
    encoding: 'utf8',
  });
  if (result.status !== 0) throw new Error(`${path.basename(file)} on ${threads}: ${result.stderr.trim().split('\n').pop()}`);
  const times = JSON.parse(result.stdout.trim().split('\n').pop()!) as { seconds: number; stage1Seconds: number; memoryMB: number };
  return { ...times, json: readFileSync(out, 'utf8').replace(/"timings":\{[^{}]*\}/, '"timings":{}') };
}

const rows: string[] = [];
const ratios: number[] = [];
files.forEach(({ file, vertices }, i) => {
  const order = i % 2 === 0 ? ['1', workers] : [workers, '1'];
  const [a, b] = order.map((k) => run(file, k));
  const [one, many] = order[0] === '1' ? [a, b] : [b, a];
  const n = (JSON.parse(one.json) as { stats: { n: number } }).stats.n;
  ratios.push(one.stage1Seconds / many.stage1Seconds);
  rows.push(`| ${path.basename(file, '.ply')} | ${vertices} | ${n} | ${one.seconds.toFixed(2)} | ${many.seconds.toFixed(2)} | ${one.stage1Seconds.toFixed(2)} | ${many.stage1Seconds.toFixed(2)} | ${(one.stage1Seconds / many.stage1Seconds).toFixed(2)} | ${Math.round(many.memoryMB)} | ${one.json === many.json ? 'yes' : '**no**'} |`);
  process.stdout.write(`${rows.at(-1)}\n`);
});
const geomean = Math.exp(ratios.reduce((s, r) => s + Math.log(r), 0) / ratios.length);
const date = new Date().toISOString().slice(0, 10);
const cpu = os.cpus()[0]?.model ?? 'unknown CPU';
const table = [
  `# Stage 1 on 1 and ${workers} threads, roundSize ${roundSize}`,
  '',
  `Machine: ${os.cpus().length} × ${cpu}, Node ${process.version}; load average (1, 5, 15 min) before the run ${loadBefore.map((l) => l.toFixed(2)).join(' ')}, after it ${os.loadavg().map((l) => l.toFixed(2)).join(' ')}.`,
  `Command: \`node --import tsx bench/parallel.ts --round-size ${roundSize} --workers ${workers} --min-vertices ${minVertices}\`; default options otherwise (n auto).`,
  'Seconds: from the parsed mesh to the skeleton (the pool\'s opening included); stage 1: the rounds alone. MB per core: the peak memory of the calling thread\'s core in the pool run, which bounds each pool thread\'s (they hold the same mesh and solver and do less). Same: the skeleton JSON, timings aside.',
  '',
  `| mesh | vertices | N | seconds, 1 | seconds, ${workers} | stage 1, 1 | stage 1, ${workers} | stage-1 speedup | MB per core | same |`,
  '|---|---|---|---|---|---|---|---|---|---|',
  ...rows,
  '',
  `Geometric mean of the stage-1 speedup: ${geomean.toFixed(2)} over ${ratios.length} meshes.`,
  '',
].join('\n');
const out = path.join(repoRoot, 'bench', 'results', `${date}-parallel.md`);
writeFileSync(out, table);
process.stdout.write(`wrote ${path.relative(repoRoot, out)}\n`);
