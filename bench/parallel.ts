// Stage 1 on one thread and on K worker threads (issue: all cores): CSCD on each mesh with
// `--draw-ahead R`, once alone and once on a pool of K, each in a process of its own
// (bench/runners/cscd.ts), the order of the two alternating from mesh to mesh so that drift of the
// machine affects both alike. Reports the times, their ratio, the caller's part and whether the two
// skeletons are the same (they must be), as a table in bench/results/<date>-parallel.md.
//
//   npm run bench:parallel -- [--draw-ahead 4] [--workers 2] [--min-vertices 10000] [--repeats 1] [meshes...]
//
// With --repeats R each mesh runs R pairs (one thread, K threads, back to back) and each figure is the
// median over its pairs: on a shared machine one pair moves by up to ±0.15 in speedup.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { defaultOptions } from '../lib/core/options.ts';
import { parseMesh } from '../lib/io/index.ts';
import { geometricMean, median } from './metrics.ts';
import { COMPILED_CORE, repoRoot } from './process.ts';
import { claimResultName } from './result-name.ts';

const { positionals, values } = parseArgs({
  allowPositionals: true,
  options: {
    'draw-ahead': { type: 'string', default: String(defaultOptions.drawAhead) },
    workers: { type: 'string', default: '2' },
    'min-vertices': { type: 'string', default: '10000' },
    repeats: { type: 'string', default: '1' },
  },
});
const drawAhead = values['draw-ahead'], workers = values.workers, minVertices = Number(values['min-vertices']), repeats = Number(values.repeats);
if (!Number.isInteger(repeats) || repeats < 1) throw new Error('--repeats must be a positive integer');
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
  const result = spawnSync(process.execPath, [...COMPILED_CORE, '--import', 'tsx', 'bench/runners/cscd.ts', file, out, '--workers', threads, '--draw-ahead', drawAhead], {
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
  const pairs = Array.from({ length: repeats }, (_, r) => {
    const order = (i + r) % 2 === 0 ? ['1', workers] : [workers, '1'];
    const [a, b] = order.map((k) => run(file, k));
    return order[0] === '1' ? { one: a, many: b } : { one: b, many: a };
  });
  const mid = (f: (pair: (typeof pairs)[number]) => number) => median(pairs.map(f))!;
  const n = (JSON.parse(pairs[0].one.json) as { stats: { n: number } }).stats.n;
  const same = pairs.every(({ one, many }) => one.json === pairs[0].one.json && many.json === pairs[0].one.json);
  const pairSpeedups = pairs.map(({ one, many }) => one.stage1Seconds / many.stage1Seconds);
  const speedup = median(pairSpeedups)!;
  ratios.push(speedup);
  wholeRatios.push(mid(({ one, many }) => one.seconds / many.seconds));
  // The caller's part (draw and accept), over the one-thread stage 1: serial only while the workers wait for it.
  serialShares.push(mid(({ one, many }) => many.serialSeconds / one.stage1Seconds));
  // Karp-Flatt: the serial fraction that would explain the measured speedup, the workers' waits included.
  karpFlatt.push((1 / speedup - 1 / k) / (1 - 1 / k));
  const spread = repeats > 1 ? ` (${Math.min(...pairSpeedups).toFixed(2)}-${Math.max(...pairSpeedups).toFixed(2)})` : '';
  rows.push(`| ${path.basename(file, '.ply')} | ${vertices} | ${n} | ${mid((p) => p.one.seconds).toFixed(2)} | ${mid((p) => p.many.seconds).toFixed(2)} | ${mid((p) => p.one.stage1Seconds).toFixed(2)} | ${mid((p) => p.many.stage1Seconds).toFixed(2)} | ${speedup.toFixed(2)}${spread} | ${wholeRatios.at(-1)!.toFixed(2)} | ${(100 * serialShares.at(-1)!).toFixed(1)} | ${(100 * karpFlatt.at(-1)!).toFixed(1)} | ${Math.round(Math.max(...pairs.map((p) => p.many.memoryMB)))} | ${same ? 'yes' : '**no**'} |`);
  process.stdout.write(`${rows.at(-1)}\n`);
});
const amdahl = (serial: number, threads: number) => 1 / (serial + (1 - serial) / threads);
const [serial, measured] = [median(serialShares)!, median(karpFlatt)!];
const projection = (threads: number) =>
  `${threads} threads: ${amdahl(serial, Math.min(threads, Number(drawAhead))).toFixed(1)}x by the caller's part as serial, ${amdahl(measured, Math.min(threads, Number(drawAhead))).toFixed(1)}x by Karp-Flatt`;
const date = new Date().toISOString().slice(0, 10);
const cpu = os.cpus()[0]?.model ?? 'unknown CPU';
const table = [
  `# Stage 1 on 1 and ${workers} threads, drawAhead ${drawAhead}`,
  '',
  `Machine: ${os.cpus().length} × ${cpu}, Node ${process.version}; load average (1, 5, 15 min) before the run ${loadBefore.map((l) => l.toFixed(2)).join(' ')}, after it ${os.loadavg().map((l) => l.toFixed(2)).join(' ')}.`,
  `Command: \`node --import tsx bench/parallel.ts --draw-ahead ${drawAhead} --workers ${workers} --min-vertices ${minVertices} --repeats ${repeats}\`; default options otherwise (n auto); each run a process \`node ${COMPILED_CORE.join(' ')}\`, as in the main bench (the WebAssembly compiled whole before the clock starts: tiered up while it runs, its compiling would take a core from the workers).`,
  ...(repeats > 1 ? [`Each mesh ran ${repeats} pairs (one thread and ${workers}, back to back, which first alternating); every figure is the median over its pairs, the stage-1 speedup with the pairs' lowest and highest.`] : []),
  'Seconds: from the parsed mesh to the skeleton (the pool\'s opening included); stage 1: from the first draw to the last accept. MB per core: the peak memory of the calling thread\'s core in the pool run, which bounds each pool thread\'s (they hold the same mesh and solver and do less). Same: the skeleton JSON, timings aside.',
  '',
  `| mesh | vertices | N | seconds, 1 | seconds, ${workers} | stage 1, 1 | stage 1, ${workers} | stage-1 speedup | whole speedup | caller % | Karp-Flatt % | MB per core | same |`,
  '|---|---|---|---|---|---|---|---|---|---|---|---|---|',
  ...rows,
  '',
  `Geometric mean of the stage-1 speedup: ${geometricMean(ratios)!.toFixed(2)} over ${ratios.length} meshes; of the whole run's (seconds): ${geometricMean(wholeRatios)!.toFixed(2)}.`,
  '',
  `Caller %: the time the pool's caller spent drawing and accepting, over stage 1 on one thread; it runs beside the workers, serial only when they wait for a draw, so as a serial part it is a bound. Karp-Flatt %: the serial fraction e = (1/S − 1/K) / (1 − 1/K) that explains the measured speedup S on K = ${workers}, which also counts every wait of a worker (for a draw, or when all the sources drawn ahead are taken) and their slowing each other down. Projected stage-1 speedup (Amdahl, the medians ${(100 * serial).toFixed(1)}% and ${(100 * measured).toFixed(1)}%; never more threads than sources drawn ahead, ${drawAhead}): ${projection(8)}; ${projection(16)}.`,
  '',
].join('\n');
const resultsDir = path.join(repoRoot, 'bench', 'results');
const out = path.join(resultsDir, `${claimResultName(resultsDir, `${date}-parallel`, ['md'])}.md`);
writeFileSync(out, table);
process.stdout.write(`wrote ${path.relative(repoRoot, out)}\n`);
