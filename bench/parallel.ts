// Stage 1 on one thread and on K worker threads (issue: all cores): CSCD on each mesh with
// `--round-size R`, once alone and once on a pool of K, each in a process of its own
// (bench/runners/cscd.ts), the order of the two alternating from mesh to mesh so that drift of the
// machine affects both alike. Reports the times, their ratio, the serial part and whether the two
// skeletons are the same (they must be), as a table in bench/results/<date>-parallel.md.
//
//   npm run bench:parallel -- [--round-size 8] [--workers 2] [--min-vertices 10000] [meshes...]
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { parseMesh } from '../lib/io/index.ts';
import { geometricMean, median } from './metrics.ts';
import { COMPILED_CORE, repoRoot } from './process.ts';
import { claimResultName } from './result-name.ts';

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

interface Times {
  seconds: number;
  stage1Seconds: number;
  serialSeconds: number;
  memoryMB: number;
}

function run(file: string, threads: string): Times & { json: string } {
  const out = path.join(tmp, `${path.basename(file)}-${threads}.json`);
  const result = spawnSync(process.execPath, [...COMPILED_CORE, '--import', 'tsx', 'bench/runners/cscd.ts', file, out, '--workers', threads, '--round-size', roundSize], {
    cwd: repoRoot,
    encoding: 'utf8',
  });
  if (result.status !== 0) throw new Error(`${path.basename(file)} on ${threads}: ${result.stderr.trim().split('\n').pop()}`);
  const times = JSON.parse(result.stdout.trim().split('\n').pop()!) as Times;
  return { ...times, json: readFileSync(out, 'utf8').replace(/"timings":\{[^{}]*\}/, '"timings":{}') };
}

const rows: string[] = [];
const ratios: number[] = [];
const wholeRatios: number[] = [];
const serialShares: number[] = [];
const karpFlatt: number[] = [];
const k = Number(workers);
files.forEach(({ file, vertices }, i) => {
  const order = i % 2 === 0 ? ['1', workers] : [workers, '1'];
  const [a, b] = order.map((k) => run(file, k));
  const [one, many] = order[0] === '1' ? [a, b] : [b, a];
  const n = (JSON.parse(one.json) as { stats: { n: number } }).stats.n;
  const speedup = one.stage1Seconds / many.stage1Seconds;
  ratios.push(speedup);
  wholeRatios.push(one.seconds / many.seconds);
  // The serial part: what the pool's caller did alone (draw and accept), over the one-thread stage 1.
  serialShares.push(many.serialSeconds / one.stage1Seconds);
  // Karp-Flatt: the serial fraction that would explain the measured speedup, idle ends of rounds included.
  karpFlatt.push((1 / speedup - 1 / k) / (1 - 1 / k));
  rows.push(`| ${path.basename(file, '.ply')} | ${vertices} | ${n} | ${one.seconds.toFixed(2)} | ${many.seconds.toFixed(2)} | ${one.stage1Seconds.toFixed(2)} | ${many.stage1Seconds.toFixed(2)} | ${speedup.toFixed(2)} | ${wholeRatios.at(-1)!.toFixed(2)} | ${(100 * serialShares.at(-1)!).toFixed(1)} | ${(100 * karpFlatt.at(-1)!).toFixed(1)} | ${Math.round(many.memoryMB)} | ${one.json === many.json ? 'yes' : '**no**'} |`);
  process.stdout.write(`${rows.at(-1)}\n`);
});
const amdahl = (serial: number, threads: number) => 1 / (serial + (1 - serial) / threads);
const [serial, measured] = [median(serialShares)!, median(karpFlatt)!];
const projection = (threads: number) =>
  `${threads} threads: ${amdahl(serial, Math.min(threads, Number(roundSize))).toFixed(1)}x by the serial part alone, ${amdahl(measured, Math.min(threads, Number(roundSize))).toFixed(1)}x by Karp-Flatt`;
const date = new Date().toISOString().slice(0, 10);
const cpu = os.cpus()[0]?.model ?? 'unknown CPU';
const table = [
  `# Stage 1 on 1 and ${workers} threads, roundSize ${roundSize}`,
  '',
  `Machine: ${os.cpus().length} × ${cpu}, Node ${process.version}; load average (1, 5, 15 min) before the run ${loadBefore.map((l) => l.toFixed(2)).join(' ')}, after it ${os.loadavg().map((l) => l.toFixed(2)).join(' ')}.`,
  `Command: \`node --import tsx bench/parallel.ts --round-size ${roundSize} --workers ${workers} --min-vertices ${minVertices}\`; default options otherwise (n auto); each run a process \`node ${COMPILED_CORE.join(' ')}\`, as in the main bench (the WebAssembly compiled whole before the clock starts: tiered up while it runs, its compiling would take a core from the workers).`,
  'Seconds: from the parsed mesh to the skeleton (the pool\'s opening included); stage 1: the rounds alone. MB per core: the peak memory of the calling thread\'s core in the pool run, which bounds each pool thread\'s (they hold the same mesh and solver and do less). Same: the skeleton JSON, timings aside.',
  '',
  `| mesh | vertices | N | seconds, 1 | seconds, ${workers} | stage 1, 1 | stage 1, ${workers} | stage-1 speedup | whole speedup | serial % | Karp-Flatt % | MB per core | same |`,
  '|---|---|---|---|---|---|---|---|---|---|---|---|---|',
  ...rows,
  '',
  `Geometric mean of the stage-1 speedup: ${geometricMean(ratios)!.toFixed(2)} over ${ratios.length} meshes; of the whole run's (seconds): ${geometricMean(wholeRatios)!.toFixed(2)}.`,
  '',
  `Serial %: the time the pool's caller spent drawing and accepting rounds (the workers idle), over stage 1 on one thread. Karp-Flatt %: the serial fraction e = (1/S − 1/K) / (1 − 1/K) that explains the measured speedup S on K = ${workers}, which also counts the ends of rounds, when a worker waits for the round's slowest separator. Projected stage-1 speedup (Amdahl, the medians ${(100 * serial).toFixed(1)}% and ${(100 * measured).toFixed(1)}%; never more threads than a round has sources, ${roundSize}): ${projection(8)}; ${projection(16)}.`,
  '',
].join('\n');
const resultsDir = path.join(repoRoot, 'bench', 'results');
const out = path.join(resultsDir, `${claimResultName(resultsDir, `${date}-parallel`, ['md'])}.md`);
writeFileSync(out, table);
process.stdout.write(`wrote ${path.relative(repoRoot, out)}\n`);
