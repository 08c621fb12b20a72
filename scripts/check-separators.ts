// Acceptance check of stage 1: `separator` from N seeded-random sources on every mesh, in one
// process (the core is loaded once and each mesh opened once, so this is fast), never throwing.
//
//   npx tsx scripts/check-separators.ts [--sources 20] [--seed 1] [--out docs/separators-check.md]
//                                       [separator options, e.g. --target geodesic --no-sphere] [meshes...]
//
// Default meshes: every ../shared/data/meshes/*.ply. Prints a markdown table (and writes it to --out):
// per mesh the sources that gave a separator, the failures per status, the exceptions (crashes),
// time per source and the median loop length over the bounding-box diagonal. Exit code 1 if any
// exception, 0 otherwise: a failure status is a reported result, not a crash.
// The sources are those of `cscd separator` without --source: with the same --seed, the first one is
// the CLI's, and any listed source can be rerun with `npx cscd separator <mesh> --source V`.
import { readdirSync, readFileSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs, type ParseArgsConfig } from 'node:util';
import { optionFlagSpecs, optionsFromFlags, randomSources, separatorJson, type SeparatorJson } from '../cli/commands/separator.ts';
import { CoreError, loadCoreNode, type Core, type MeshArrays, type Options, type SeparatorStatus, type Surface } from '../lib/core/node.ts';
import { defaultOptions } from '../lib/core/options.ts';
import { parseMesh } from '../lib/io/index.ts';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const sharedMeshes = path.resolve(repoRoot, '..', 'shared', 'data', 'meshes');

/** Every failure status, in the order of the table (the Record makes the compiler check that none is missing). */
const FAILURES = Object.keys({
  'no-cut-locus': 0, 'no-target': 0, 'trace-failed': 0, 'degenerate-loop': 0, 'shorten-failed': 0, 'not-separating': 0,
} satisfies Record<Exclude<SeparatorStatus, 'ok'>, 0>);

interface MeshReport {
  mesh: string;
  vertices: number | null;
  sources: number;
  ok: number;
  /** Per failure status, the sources and the core's messages. */
  failures: Map<string, { source: number; message: string }[]>;
  exceptions: string[];
  /** ok results that break an invariant of the contract (loop not closed, length > approxLength...). */
  suspects: string[];
  ms: number[];
  relativeLengths: number[];
  /** Per stage of `timings`, the times of every source. */
  stages: Map<string, number[]>;
}

function usage(message: string): never {
  process.stderr.write(`check-separators: ${message}\n`);
  process.exit(2);
}

function parseCommandLine() {
  const config: ParseArgsConfig = {
    allowPositionals: true,
    strict: true,
    options: {
      sources: { type: 'string', default: '20' },
      out: { type: 'string', default: path.join('docs', 'separators-check.md') },
      ...Object.fromEntries(Object.entries(optionFlagSpecs()).map(([flag, spec]) => [flag, { type: spec.type }])),
    },
  };
  let parsed;
  try {
    parsed = parseArgs(config);
  } catch (error) {
    usage((error as Error).message);
  }
  const { values, positionals } = parsed;
  const sources = /^\d+$/.test(String(values.sources)) ? Number(values.sources) : NaN;
  if (!(sources >= 1)) usage(`--sources must be a positive integer, got '${String(values.sources)}'`);
  let options: Options;
  try {
    options = optionsFromFlags(values);
  } catch (error) {
    usage((error as Error).message);
  }
  const meshes = positionals.length > 0 ? positionals
    : readdirSync(sharedMeshes).filter((name) => name.endsWith('.ply')).sort().map((name) => path.join(sharedMeshes, name));
  return { sources, options, meshes, out: String(values.out) };
}

function describe(error: unknown): string {
  const text = error instanceof Error ? (error instanceof CoreError ? error.message : `${error.name}: ${error.message}`) : String(error);
  return text.split('\n')[0];
}

/** What an 'ok' result promises; the empty list when it keeps every promise. */
function brokenPromises(json: SeparatorJson, options: Options, vertexCount: number): string[] {
  const broken: string[] = [];
  const finite = (points: number[][]) => points.every((p) => p.length === 3 && p.every(Number.isFinite));
  if (json.loop.length < 3) broken.push(`loop has ${json.loop.length} points`);
  if (!finite(json.loop) || !finite(json.approxLoop) || !finite(json.paths.flat())) broken.push('non-finite points');
  if (!(json.length > 0 && Number.isFinite(json.length))) broken.push(`length ${json.length}`);
  if (!(json.length <= json.approxLength * (1 + 1e-9))) broken.push(`length ${json.length} > approxLength ${json.approxLength}`);
  if (!json.areas.every((a) => Number.isFinite(a) && a >= 0) || !(json.areas[0] <= json.areas[1])) broken.push(`areas ${JSON.stringify(json.areas)}`);
  if (!Number.isFinite(json.score)) broken.push(`score ${json.score}`);
  if ((json.sphere !== null) !== options.sphere) broken.push(`sphere ${json.sphere === null ? 'missing' : 'present'} with sphere=${options.sphere}`);
  if (json.target === null) broken.push('no target point');
  if (json.distance.length !== vertexCount) broken.push(`${json.distance.length} distances for ${vertexCount} vertices`);
  return broken;
}

const loadAtStart = os.loadavg()[0];

const median = (values: number[]) => {
  if (values.length === 0) return NaN;
  const sorted = [...values].sort((a, b) => a - b);
  const middle = sorted.length >> 1;
  return sorted.length % 2 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2;
};

async function checkMesh(file: string, state: { core: Core }, count: number, options: Options): Promise<MeshReport> {
  const report: MeshReport = {
    mesh: path.basename(file), vertices: null, sources: 0, ok: 0, failures: new Map(), exceptions: [], suspects: [],
    ms: [], relativeLengths: [], stages: new Map(),
  };
  let mesh: MeshArrays;
  let surface: Surface;
  try {
    mesh = parseMesh(new Uint8Array(readFileSync(file)), file);
    report.vertices = mesh.positions.length / 3;
    surface = state.core.openSurface(mesh);
  } catch (error) {
    report.exceptions.push(`opening the mesh: ${describe(error)}`);
    return report;
  }
  const diagonal = surface.facts.bboxDiagonal;
  const sources = randomSources(mesh, options.seed, count);
  report.sources = sources.length;
  for (const source of sources) {
    try {
      const start = performance.now();
      const result = surface.separator(source, options);
      report.ms.push(performance.now() - start);
      // What the CLI does with the result, so that a crash there is found here too.
      const json = separatorJson(result, options);
      JSON.stringify(json);
      for (const [stage, ms] of Object.entries(json.timings)) {
        if (!report.stages.has(stage)) report.stages.set(stage, []);
        report.stages.get(stage)!.push(ms);
      }
      if (json.status === 'ok') {
        report.ok++;
        report.relativeLengths.push(json.length / diagonal);
        const broken = brokenPromises(json, options, report.vertices);
        if (broken.length > 0) report.suspects.push(`source ${source}: ${broken.join('; ')}`);
      } else {
        if (!report.failures.has(json.status)) report.failures.set(json.status, []);
        report.failures.get(json.status)!.push({ source, message: json.message.split('\n')[0] });
      }
    } catch (error) {
      report.exceptions.push(`source ${source}: ${describe(error)}`);
      if (!(error instanceof CoreError)) {
        // A WASM trap or abort can leave the module unusable: start from a fresh core.
        try {
          state.core = await loadCoreNode();
          surface = state.core.openSurface(mesh);
        } catch (reload) {
          report.exceptions.push(`reloading the core: ${describe(reload)}`);
          return report;
        }
      }
    }
  }
  try {
    surface.dispose();
  } catch (error) {
    report.exceptions.push(`dispose: ${describe(error)}`);
  }
  return report;
}

function format(value: number, digits: number): string {
  return Number.isFinite(value) ? value.toFixed(digits) : '-';
}

function markdown(reports: MeshReport[], count: number, options: Options, argv: string[]): string {
  const statuses = [...FAILURES, ...new Set(reports.flatMap((r) => [...r.failures.keys()]).filter((s) => !FAILURES.includes(s)))];
  const header = ['mesh', 'V', 'sources', 'ok', ...statuses, 'exceptions', 'suspect ok', 'median ms', 'max ms', 'median length / diag'];
  const row = (cells: (string | number)[]) => `| ${cells.join(' | ')} |`;
  const sum = (f: (r: MeshReport) => number) => reports.reduce((total, r) => total + f(r), 0);
  const allMs = reports.flatMap((r) => r.ms);
  const lines = [
    row(header),
    row(header.map((_, i) => (i === 0 ? '---' : '---:'))),
    ...reports.map((r) => row([
      r.mesh, r.vertices ?? '-', r.sources, r.ok, ...statuses.map((s) => r.failures.get(s)?.length ?? 0), r.exceptions.length,
      r.suspects.length, format(median(r.ms), 1), format(Math.max(...r.ms), 1), format(median(r.relativeLengths), 3),
    ])),
    row([
      `**all (${reports.length} meshes)**`, '', sum((r) => r.sources), sum((r) => r.ok),
      ...statuses.map((s) => sum((r) => r.failures.get(s)?.length ?? 0)), sum((r) => r.exceptions.length), sum((r) => r.suspects.length),
      format(median(allMs), 1), format(Math.max(...allMs), 1), format(median(reports.flatMap((r) => r.relativeLengths)), 3),
    ]),
  ];

  const stageNames = [...new Set(reports.flatMap((r) => [...r.stages.keys()]))];
  const stageLines = stageNames.length === 0 ? [] : [
    '',
    '## Median ms per stage (the core\'s `timings`)',
    '',
    row(['mesh', ...stageNames]),
    row(['---', ...stageNames.map(() => '---:')]),
    ...reports.map((r) => row([r.mesh, ...stageNames.map((s) => format(median(r.stages.get(s) ?? []), 1))])),
  ];

  const notes: string[] = [];
  for (const r of reports) {
    for (const [status, failed] of r.failures) {
      for (const { source, message } of failed) notes.push(`- ${r.mesh}, source ${source}: ${status}: ${message}`);
    }
    for (const e of r.exceptions) notes.push(`- ${r.mesh}: **exception** ${e}`);
    for (const s of r.suspects) notes.push(`- ${r.mesh}: suspect ok result, ${s}`);
  }

  const changed = (Object.keys(options) as (keyof Options)[]).filter((k) => options[k] !== defaultOptions[k]);
  return [
    '# Stage 1 separators on the shared meshes',
    '',
    `Made by \`npx tsx scripts/check-separators.ts${argv.length ? ` ${argv.join(' ')}` : ''}\` on ${new Date().toISOString().slice(0, 10)}, `
      + `${os.availableParallelism()} cores (${os.cpus()[0]?.model.trim() ?? 'unknown CPU'}), Node ${process.version}, WASM core; `
      + `load average ${loadAtStart.toFixed(1)} at the start, ${os.loadavg()[0].toFixed(1)} at the end (times are only comparable on an idle machine).`,
    `${count} seeded-random sources per mesh (seed ${options.seed}, the sources of \`cscd separator\` without \`--source\`); `
      + `options: ${changed.length ? changed.map((k) => `${k}=${String(options[k])}`).join(', ') : 'defaults'}.`,
    'Failure columns count sources whose status says why there is no separator; *exceptions* are crashes (the core threw);',
    '*suspect ok* are `ok` results that break a promise of the contract (loop under 3 points, non-finite values,',
    'length > approxLength, bad areas, sphere present/absent against the option, no target, distance count).',
    'Times are wall-clock per `Surface.separator` call; length is the shortened loop over the bounding-box diagonal.',
    '',
    ...lines,
    ...stageLines,
    ...(notes.length ? ['', '## Failed sources (rerun one with `npx cscd separator <mesh> --source V`)', '', ...notes] : []),
    '',
  ].join('\n');
}

async function main(): Promise<void> {
  const { sources, options, meshes, out } = parseCommandLine();
  const state = { core: await loadCoreNode() };
  const reports: MeshReport[] = [];
  for (const file of meshes) {
    const started = performance.now();
    const report = await checkMesh(file, state, sources, options);
    reports.push(report);
    process.stderr.write(`${report.mesh}: ${report.ok}/${report.sources} ok, ${report.exceptions.length} exceptions, `
      + `${((performance.now() - started) / 1000).toFixed(1)} s\n`);
  }
  const text = markdown(reports, sources, options, process.argv.slice(2));
  process.stdout.write(text);
  writeFileSync(path.resolve(out), text);
  process.stderr.write(`wrote ${out}\n`);
  process.exitCode = reports.some((r) => r.exceptions.length > 0) ? 1 : 0;
}

await main();
