// `npm run bench`: CSCD Studio against the skeletonisers people use instead, timed alike and scored by
// the same code (bench/README.md says what every column means and why the comparison is fair).
//
//   npm run bench [-- [--quick] [--methods cscd,ls,msls,mcf] [--meshes a,b] [--timeout S] [--cpu N] [--no-build] [folder...]]
//
// Meshes: every ../shared/data/meshes/*.ply and ../shared/data/synthetic/*.ply (the quick subset with
// --quick), plus every .ply/.obj/.off of the folders given; --meshes keeps only the named ones (with or
// without extension). For each mesh, the methods run one after the other in a fixed order, each in its
// own process pinned to one core; then each skeleton is read back and scored by core.evaluate under two
// radius rules (derived from the mesh; from the method's vertex map), and, where the mesh has a ground
// truth `<stem>__GT.json`, by its tip gap (bench/metrics.ts). The table, a CSV and an SVG go to
// bench/results/<date>[-quick][-N].{md,csv,svg} (rewritten after every mesh, so an interrupted run
// keeps what it did); skeletons and logs to .deps/bench/runs/<same name>/.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { CoreError, loadCoreNode, wasmPath, type Evaluation, type MeshArrays } from '../lib/core/node.ts';
import { parseMesh } from '../lib/io/index.ts';
import { parseSkeleton, SkeletonFormatError, type ParsedSkeleton } from '../lib/io/skeleton.ts';
import {
  compareErrors, leafIndices, mapByPosition, median, tipGap, VertexMapError, vertexMapRadii, type Comparison, type TipGap,
} from './metrics.ts';
import { errorVsSecondsSvg } from './plot.ts';
import { COMPILED_CORE, repoRoot, runPinned, shell, venvPython, type Run } from './process.ts';
import { claimResultName } from './result-name.ts';

const sharedData = path.resolve(repoRoot, '..', 'shared', 'data');
/** The default meshes: the shared collection, then the synthetic shapes with a known skeleton (`<stem>__GT.json`). */
const defaultFolders = [path.join(sharedData, 'meshes'), path.join(sharedData, 'synthetic')];
const resultsDir = path.join(repoRoot, 'bench', 'results');

/**
 * Small meshes of genus 0, 1, 3 and 4 on which every method finishes in well under the quick timeout:
 * LS is the slow one (5-60 s on these; hand.ply, 10k vertices, takes it about 170 s). The two coarse
 * synthetic shapes add thin tips with a ground truth.
 */
const QUICK_MESHES = ['elephant_small', 'fertility_9k', 'spot', 'torus', 'wolf', 'star8_coarse', 'tree_coarse'];
const MESH_EXTENSIONS = /\.(ply|obj|off)$/i; // what all four methods read
const stem = (file: string) => path.basename(file).replace(MESH_EXTENSIONS, '');
const DEFAULT_TIMEOUT = { full: 600, quick: 180 };

// ---------------------------------------------------------------------------------------------------
// Methods: how each is run. Every runner prints {"seconds": S} as the last line of stdout.

const METHODS = ['cscd', 'ls', 'msls', 'mcf'] as const;
type Method = (typeof METHODS)[number];

const RUNNERS: Record<Method, { ext: string; command: (mesh: string, out: string) => string[] }> = {
  cscd: { ext: 'json', command: (mesh, out) => [process.execPath, ...COMPILED_CORE, '--import', 'tsx', 'bench/runners/cscd.ts', mesh, out] },
  ls: { ext: 'obj', command: (mesh, out) => [venvPython, 'bench/runners/gel.py', 'ls', mesh, out] },
  msls: { ext: 'obj', command: (mesh, out) => [venvPython, 'bench/runners/gel.py', 'msls', mesh, out] },
  mcf: { ext: 'obj', command: (mesh, out) => [path.join(repoRoot, '.deps', 'bench', 'mcf'), mesh, out] },
};

// ---------------------------------------------------------------------------------------------------
// Command line

/** An error the bench reports as one line, without a stack (bad usage, a missing piece). */
class BenchError extends Error {}

interface Config {
  quick: boolean;
  /** Score the core as it is built (build/wasm), without running scripts/build-wasm.sh first. */
  noBuild: boolean;
  methods: Method[];
  timeout: number;
  /** The core every method is pinned to (two runs on two idle cores split a long bench). */
  cpu: number;
  meshes: string[];
  folders: string[];
  argv: string[];
}

function meshFiles(folder: string): string[] {
  return readdirSync(folder).filter((f) => MESH_EXTENSIONS.test(f)).sort().map((f) => path.join(folder, f));
}

function parseCommandLine(argv: string[]): Config {
  const { values, positionals } = parseArgs({
    args: argv,
    allowPositionals: true,
    options: {
      quick: { type: 'boolean', default: false },
      methods: { type: 'string' },
      meshes: { type: 'string' },
      timeout: { type: 'string' },
      cpu: { type: 'string' },
      'no-build': { type: 'boolean', default: false },
      help: { type: 'boolean', short: 'h', default: false },
    },
  });
  if (values.help) {
    process.stdout.write('usage: npm run bench -- [--quick] [--methods cscd,ls,msls,mcf] [--meshes a,b] [--timeout S] [--cpu N] [--no-build] [folder...]\n');
    process.exit(0);
  }
  const quick = values.quick === true;
  const list = (text: string | undefined) => (text ?? '').split(',').map((s) => s.trim()).filter(Boolean);

  const asked = list(values.methods);
  const unknown = asked.filter((m) => !(METHODS as readonly string[]).includes(m));
  if (unknown.length) throw new BenchError(`unknown method(s) ${unknown.join(', ')}: choose from ${METHODS.join(', ')}`);
  // Always the fixed order, whatever order they were given in.
  const methods = asked.length ? METHODS.filter((m) => asked.includes(m)) : [...METHODS];

  const timeout = values.timeout === undefined ? DEFAULT_TIMEOUT[quick ? 'quick' : 'full'] : Number(values.timeout);
  if (!(timeout > 0)) throw new BenchError(`--timeout must be a positive number of seconds, got '${values.timeout}'`);
  const cpu = values.cpu === undefined ? 0 : Number(values.cpu);
  if (!Number.isInteger(cpu) || cpu < 0 || cpu >= os.cpus().length) throw new BenchError(`--cpu must be a core number below ${os.cpus().length}, got '${values.cpu}'`);

  for (const folder of positionals) {
    if (!existsSync(folder) || !statSync(folder).isDirectory()) throw new BenchError(`'${folder}' is not a folder`);
  }
  for (const folder of defaultFolders) {
    if (!existsSync(folder)) throw new BenchError(`the shared meshes are not at ${folder}`);
  }

  const names = list(values.meshes);
  const shared = defaultFolders.flatMap(meshFiles).filter((f) => names.length > 0 || !quick || QUICK_MESHES.includes(stem(f)));
  let meshes = [...shared, ...positionals.flatMap((folder) => meshFiles(path.resolve(folder)))];
  if (names.length) {
    const missing = names.filter((n) => !meshes.some((f) => path.basename(f) === n || stem(f) === n));
    if (missing.length) throw new BenchError(`no mesh named ${missing.join(', ')} in ${[...defaultFolders, ...positionals].join(', ')}`);
    meshes = meshes.filter((f) => names.includes(path.basename(f)) || names.includes(stem(f)));
  }
  if (!meshes.length) throw new BenchError('no meshes to run on');
  return { quick, noBuild: values['no-build'] === true, methods, timeout, cpu, meshes, folders: positionals, argv };
}

// ---------------------------------------------------------------------------------------------------
// Running one method on one mesh


/** The line of a failed process's stderr that says why: the last that is not a stack frame or Node's version. */
function runMethod(method: Method, mesh: string, runDir: string, label: string, timeout: number, cpu: number): Run {
  const file = path.join(runDir, `${label}.${method}.${RUNNERS[method].ext}`);
  return runPinned(RUNNERS[method].command(mesh, file), file, path.join(runDir, `${label}.${method}.log`), timeout, cpu);
}

// ---------------------------------------------------------------------------------------------------
// Scoring

/** What the table keeps of an Evaluation (not its per-vertex arrays and surface, which are large). */
type Figures = Pick<Evaluation, 'reconError' | 'median' | 'p95' | 'nodes' | 'cycles'>;

const figures = ({ reconError, median, p95, nodes, cycles }: Evaluation): Figures => ({ reconError, median, p95, nodes, cycles });

type Score = { ok: true; evaluation: Figures } | { ok: false; reason: string; nodes: number | null };

/** The score with radii from the method's vertex map (rule 2), and how the radii were filled in. */
type MapScore =
  | { ok: true; evaluation: Figures; fromNeighbours: number; fromFallback: number; unmapped: number }
  | { ok: false; reason: string };

/**
 * Ground-truth leaves that are not tips (../shared/data/synthetic/README.md measures the tip gap "over
 * the arms/twigs"): star8's node 0 is the top of the body, not an arm; tree's node 0 is the base of the
 * trunk, its root, not a twig.
 */
const NOT_TIPS: Record<string, number[]> = { star8: [0], star8_coarse: [0], tree: [0], tree_coarse: [0] };

/** The tips of the mesh's ground-truth skeleton `<stem>__GT.json` beside it, or null when it has none. */
function groundTruthTips(meshFile: string): number[][] | null {
  const file = path.join(path.dirname(meshFile), `${stem(meshFile)}__GT.json`);
  if (!existsSync(file)) return null;
  let gt: { nodes: [number, number, number][]; edges: [number, number][] };
  try {
    gt = JSON.parse(readFileSync(file, 'utf8')) as typeof gt;
  } catch (error) {
    throw new BenchError(`${file}: ${describe(error)}`);
  }
  return leafIndices(gt.nodes.length, gt.edges.flat(), NOT_TIPS[stem(meshFile)] ?? []).map((i) => gt.nodes[i]);
}

/**
 * A method's vertex map in the mesh's vertex order. cscd's skeleton JSON has it; the baselines write it
 * beside the skeleton as `<skeleton>.map.json`, with the positions of the vertices it indexes (GEL and
 * CGAL number the vertices their own way), matched to the mesh's by position.
 */
function readVertexMap(method: Method, skeletonFile: string, positions: ArrayLike<number>): ArrayLike<number> {
  const file = method === 'cscd' ? skeletonFile : skeletonFile.replace(/\.[^./\\]+$/, '.map.json');
  if (!existsSync(file)) throw new VertexMapError(`no vertex map (${path.basename(file)})`);
  const map = JSON.parse(readFileSync(file, 'utf8')) as { vertexToNode?: number[]; positions?: number[] };
  if (!Array.isArray(map.vertexToNode)) throw new VertexMapError(`${path.basename(file)} has no vertexToNode`);
  return map.positions ? mapByPosition(positions, map.positions, map.vertexToNode) : map.vertexToNode;
}

function describe(error: unknown): string {
  const text = error instanceof Error ? (error instanceof CoreError || error instanceof BenchError || error instanceof VertexMapError ? error.message : `${error.name}: ${error.message}`) : String(error);
  return text.split('\n')[0];
}

// ---------------------------------------------------------------------------------------------------
// Output

interface Row {
  mesh: string;
  vertices: number | null;
  genus: number | null;
  method: Method;
  run: Run;
  /** Radii derived from the mesh (rule 1). */
  score: Score | null;
  /** Radii from the method's vertex map (rule 2). */
  mapScore: MapScore | null;
  /** How many tips the mesh's ground truth has (null: it has none). */
  tipCount: number | null;
  tips: TipGap | null;
}

/** The two radius rules every skeleton is scored by, as the summary names them. */
const RULES = { derived: 'radii derived from the mesh', map: 'radii from the vertex map' } as const;
type Rule = keyof typeof RULES;

function errorOf(row: Row | undefined, rule: Rule): number | null {
  const score = rule === 'derived' ? row?.score : row?.mapScore;
  return score?.ok ? score.evaluation.reconError : null;
}

/** cscd's error and another method's on one mesh under one rule, or null when either was not scored. */
function errorPair(rows: Row[], mesh: string, other: Method, rule: Rule): [number, number] | null {
  const [a, b] = [errorOf(rows.find((r) => r.mesh === mesh && r.method === 'cscd'), rule), errorOf(rows.find((r) => r.mesh === mesh && r.method === other), rule)];
  return a !== null && b !== null ? [a, b] : null;
}

function errorRatio(rows: Row[], mesh: string, other: Method, rule: Rule): number | null {
  const pair = errorPair(rows, mesh, other, rule);
  return pair && pair[0] / pair[1];
}

/** cscd against another method under one rule, over the meshes where both were scored. */
function comparison(rows: Row[], other: Method, rule: Rule): Comparison {
  return compareErrors([...new Set(rows.map((r) => r.mesh))].flatMap((mesh) => {
    const pair = errorPair(rows, mesh, other, rule);
    return pair ? [pair] : [];
  }));
}

const percent = (fraction: number) => `${(100 * fraction).toFixed(2)}`;

const num = (x: number) => String(Number(x.toPrecision(3)));
const cell = (text: string) => text.replace(/\|/g, '\\|');

function runCell(run: Run, timeout: number): string {
  if (run.status === 'timeout') return `timeout (> ${timeout} s)`;
  if (run.status === 'failed') return `failed: ${run.reason}`;
  return (run.seconds as number).toFixed(2);
}

/** cscd's seconds over msls's on the same mesh, or null when either has none. */
function ratio(rows: Row[], mesh: string): number | null {
  const seconds = (m: Method) => rows.find((r) => r.mesh === mesh && r.method === m)?.run.seconds ?? null;
  const cscd = seconds('cscd'), msls = seconds('msls');
  return cscd !== null && msls !== null && msls > 0 ? cscd / msls : null;
}

/** The page's responsiveness as tests/e2e/long-tasks.spec.ts last measured it, as one paragraph (null if never run). */
function pageLongTasks(): string | null {
  const file = path.join(repoRoot, '.deps', 'bench', 'page-long-tasks.json');
  if (!existsSync(file)) return null;
  const r = JSON.parse(readFileSync(file, 'utf8')) as {
    longestMs: number; longestCpuMs: number; longestReadbackMs: number; count: number; mesh: string; renderer: string; date: string;
  };
  return `Page (from \`tests/e2e/long-tasks.spec.ts\`, ${r.date}): during a whole-shape run on ${r.mesh}, the longest main-thread task `
    + `took ${r.longestCpuMs} ms of CPU (${r.longestMs} ms wall, of which up to ${r.longestReadbackMs} ms waiting for a frame to be read back `
    + `from ${r.renderer}); ${r.count} tasks over 50 ms.`;
}

/** The summary against the baselines and the issue's targets ("Skeletons that beat MSLS"), each with met / not met. */
function summary(rows: Row[], config: Config): string[] {
  if (!config.methods.includes('cscd')) return [];
  const others = config.methods.filter((m) => m !== 'cscd');
  const lines: string[] = [];
  if (others.length) {
    lines.push('', 'cscd against each baseline, per radius rule, over the meshes where both were scored: on how many meshes cscd\'s error '
      + 'is below the other\'s, and the geometric mean of cscd\'s error over the other\'s (below 1: cscd reconstructs the shape better).', '',
    '| against | radius rule | cscd below | geometric mean of cscd / other error |', '| --- | --- | ---: | ---: |');
    for (const other of others) {
      for (const rule of Object.keys(RULES) as Rule[]) {
        const c = comparison(rows, other, rule);
        lines.push(`| ${other} | ${RULES[rule]} | ${c.meshes ? `${c.below} of ${c.meshes} (${Math.round((100 * c.below) / c.meshes)}%)` : ''} `
          + `| ${c.geomean === null ? '' : c.geomean.toFixed(2)} |`);
      }
    }
  }

  const verdict = (met: boolean | null) => (met === null ? 'not measured' : met ? '**met**' : '**not met**');
  const targets: string[] = [];
  if (config.methods.includes('msls')) {
    const [derived, map] = [comparison(rows, 'msls', 'derived'), comparison(rows, 'msls', 'map')];
    const share = derived.meshes ? derived.below / derived.meshes : null;
    targets.push(
      `- cscd below msls on ≥ 80% of the meshes (${RULES.derived}): ${share === null ? 'n/a' : `${derived.below} of ${derived.meshes} (${Math.round(100 * share)}%)`}: ${verdict(share === null ? null : share >= 0.8)}`,
      `- geometric mean of cscd / msls error ≤ 0.8 (${RULES.derived}): ${derived.geomean?.toFixed(2) ?? 'n/a'}: ${verdict(derived.geomean === null ? null : derived.geomean <= 0.8)}`,
      `- geometric mean of cscd / msls error ≤ 1.0 (${RULES.map}): ${map.geomean?.toFixed(2) ?? 'n/a'}: ${verdict(map.geomean === null ? null : map.geomean <= 1)}`,
    );
  }
  const shapes = rows.filter((r) => r.method === 'cscd' && r.tipCount !== null);
  if (shapes.length) {
    const msls = (mesh: string) => rows.find((r) => r.mesh === mesh && r.method === 'msls')?.tips ?? null;
    const gaps = shapes.map((r) => `${r.mesh} ${r.tips ? `${percent(r.tips.mean)}%` : 'no skeleton'}`).join(', ');
    targets.push(`- mean tip gap ≤ 0.5% of the diagonal on each synthetic shape: ${gaps}: ${verdict(shapes.every((r) => r.tips !== null && r.tips.mean <= 0.005))}`);
    if (config.methods.includes('msls')) {
      const compared = shapes.filter((r) => msls(r.mesh) !== null);
      const against = compared.map((r) => `${r.mesh} ${r.tips ? percent(r.tips.mean) : '–'} vs ${percent((msls(r.mesh) as TipGap).mean)}`).join(', ');
      targets.push(`- mean tip gap no worse than msls's on each synthetic shape (cscd vs msls, %): ${against || 'no msls skeleton'}`
        + `${compared.length < shapes.length ? ` (${shapes.length - compared.length} shapes without an msls skeleton)` : ''}: `
        + `${verdict(compared.length ? compared.every((r) => r.tips !== null && r.tips.mean <= (msls(r.mesh) as TipGap).mean) : null)}`);
    }
    const leaves = shapes.map((r) => `${r.mesh} ${r.tips ? r.tips.ownLeaves : 0} / ${r.tipCount}`).join(', ');
    targets.push(`- every ground-truth tip has a leaf of its own: ${leaves}: ${verdict(shapes.every((r) => r.tips !== null && r.tips.ownLeaves === r.tipCount))}`);
  }
  if (targets.length) lines.push('', 'Targets of the issue "Skeletons that beat MSLS", on the meshes of this run:', '', ...targets);
  return lines;
}

function markdown(rows: Row[], config: Config, machine: string, meshesDone: number): string {
  const page = pageLongTasks();
  const withRatio = config.methods.includes('cscd') && config.methods.includes('msls');
  const lines: string[] = [
    `# Curve-skeleton bench: ${config.methods.join(', ')}`,
    '',
    machine,
    '',
    ...(page ? [page, ''] : []),
    `Options: \`npm run bench${config.argv.length ? ` -- ${config.argv.join(' ')}` : ''}\`; methods ${config.methods.join(', ')}; `
      + `${config.meshes.length} meshes${config.quick ? ' (quick)' : ''}; timeout ${config.timeout} s per method and mesh.`
      + (meshesDone < config.meshes.length ? ` **Partial: ${meshesDone} of ${config.meshes.length} meshes done.**` : ''),
    '',
    `Every method ran in its own process pinned to one core (\`taskset -c ${config.cpu}\`, \`OMP_NUM_THREADS=1\` and the like), `
      + 'the methods one after the other for each mesh in the order cscd, ls, msls, mcf, so that drift of the machine affects them alike. '
      + 'Seconds: wall time of the skeletonisation alone, as each runner measures it (cscd: `openSurface` + `skeleton`; ls/msls: '
      + '`graph.from_mesh` + `LS_skeleton_and_map`/`MSLS_skeleton_and_map`; mcf: `extract_mean_curvature_flow_skeleton`), reading and writing files excluded; '
      + `cscd's WebAssembly compiled whole by V8's optimising compiler before the clock starts (\`${COMPILED_CORE.join(' ')}\`), as the others' C++ is compiled ahead of time. `
      + 'Every skeleton was read back with `parseSkeleton` and scored by the same `core.evaluate` twice, by two radius rules the same for every method '
      + '(CSCD\'s own radii are not used): **radii: null**, derived from the mesh by one tube-fitting rule; and **vertex map**, a node\'s radius '
      + 'the median distance from it to the mesh vertices the method\'s vertex map gives it (nodes that own none: their neighbours\' mean). '
      + 'Error: the reconstruction error in the paper\'s unit (squared distance from the mesh vertices to the reconstructed surface, '
      + 'mesh scaled to unit bounding-box diagonal, ×1e3), mean, median and 95th percentile over the vertices; the vertex-map error is the mean. '
      + 'Tip gap (meshes with a ground truth `<stem>__GT.json`): per ground-truth tip, the distance to the skeleton\'s polyline in % of the '
      + 'bounding-box diagonal, mean / max; tips with own leaf: tips with a skeleton leaf of their own within 1% of the diagonal. '
      + 'Cycles: independent cycles of the skeleton graph, against the genus of the mesh (`core.inspect`). '
      + (withRatio ? 'cscd / msls: cscd\'s seconds over msls\'s on the same mesh (below 1: cscd is faster).' : ''),
    '',
    `| mesh | V | method | seconds | nodes | cycles / genus | error ×1e3 | median ×1e3 | p95 ×1e3 | error ×1e3, vertex map `
      + `| tip gap % (mean / max) | tips with own leaf |${withRatio ? ' cscd / msls |' : ''}`,
    `| --- | ---: | --- | ---: | ---: | :---: | ---: | ---: | ---: | ---: | ---: | ---: |${withRatio ? ' ---: |' : ''}`,
  ];
  for (const row of rows) {
    const genus = row.genus === null ? 'n/a' : String(row.genus);
    let nodes = '', cycles = '', error = '', med = '', p95 = '';
    if (row.score?.ok) {
      const e = row.score.evaluation;
      nodes = String(e.nodes);
      cycles = `${e.cycles} / ${genus}`;
      [error, med, p95] = [num(e.reconError), num(e.median), num(e.p95)];
    } else if (row.score) {
      nodes = row.score.nodes === null ? '' : String(row.score.nodes);
      error = `scoring failed: ${row.score.reason}`;
    }
    const mapError = row.mapScore === null ? '' : row.mapScore.ok ? num(row.mapScore.evaluation.reconError) : `n/a (${row.mapScore.reason})`;
    const gap = row.tips ? `${percent(row.tips.mean)} / ${percent(row.tips.max)}` : '';
    const own = row.tips ? `${row.tips.ownLeaves} / ${row.tipCount}` : '';
    const r = row.method === 'cscd' ? ratio(rows, row.mesh) : null;
    lines.push(`| ${cell(row.mesh)} | ${row.vertices ?? ''} | ${row.method} | ${cell(runCell(row.run, config.timeout))} | ${nodes} | ${cycles} `
      + `| ${cell(error)} | ${med} | ${p95} | ${cell(mapError)} | ${gap} | ${own} |${withRatio ? ` ${r === null ? '' : r.toFixed(2)} |` : ''}`);
  }

  lines.push('', 'Per method: meshes with a skeleton, timeouts and failures; median seconds and median error (both rules) over the meshes it finished; '
    + 'meshes where cycles = genus.', '',
  '| method | done | timeout | failed | median seconds | median error ×1e3 | median error ×1e3, vertex map | cycles = genus |',
  '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |');
  for (const method of config.methods) {
    const mine = rows.filter((r) => r.method === method);
    const scored = mine.flatMap((r) => (r.score?.ok ? [{ row: r, e: r.score.evaluation }] : []));
    const medSeconds = median(mine.flatMap((r) => (r.run.seconds === null ? [] : [r.run.seconds])));
    const medError = median(scored.map((s) => s.e.reconError));
    const medMapError = median(mine.flatMap((r) => errorOf(r, 'map') ?? []));
    lines.push(`| ${method} | ${mine.filter((r) => r.run.status === 'ok').length} | ${mine.filter((r) => r.run.status === 'timeout').length} `
      + `| ${mine.filter((r) => r.run.status === 'failed').length} | ${medSeconds === null ? '' : medSeconds.toFixed(2)} `
      + `| ${medError === null ? '' : num(medError)} | ${medMapError === null ? '' : num(medMapError)} | ${scored.filter((s) => s.e.cycles === s.row.genus).length} of ${scored.length} |`);
  }
  const ratios = [...new Set(rows.map((r) => r.mesh))].flatMap((mesh) => ratio(rows, mesh) ?? []);
  if (withRatio && ratios.length) {
    lines.push('', `cscd / msls time: median ${median(ratios)?.toFixed(2)} over ${ratios.length} meshes (from ${Math.min(...ratios).toFixed(2)} to ${Math.max(...ratios).toFixed(2)}).`);
  }
  lines.push(...summary(rows, config));
  return `${lines.join('\n')}\n`;
}

function csv(rows: Row[]): string {
  const quote = (v: string | number | null) => (v === null ? '' : typeof v === 'number' ? String(v) : /[",\n]/.test(v) ? `"${v.replace(/"/g, '""')}"` : v);
  const lines = ['mesh,vertices,genus,method,status,reason,seconds,nodes,cycles,recon_error,median,p95,'
    + 'map_recon_error,map_median,map_p95,map_reason,map_nodes_from_neighbours,map_nodes_from_fallback,map_unmapped_vertices,'
    + 'tips,tip_gap_mean_pct,tip_gap_max_pct,tips_own_leaf,cscd_over_msls,cscd_over_msls_error,cscd_over_msls_map_error'];
  for (const row of rows) {
    const e = row.score?.ok ? row.score.evaluation : null;
    const m = row.mapScore?.ok ? row.mapScore : null;
    const reason = row.run.reason || (row.score && !row.score.ok ? `scoring failed: ${row.score.reason}` : '');
    const cscd = row.method === 'cscd';
    lines.push([row.mesh, row.vertices, row.genus, row.method, row.run.status, reason, row.run.seconds,
      e ? e.nodes : row.score && !row.score.ok ? row.score.nodes : null, e?.cycles ?? null, e?.reconError ?? null, e?.median ?? null, e?.p95 ?? null,
      m?.evaluation.reconError ?? null, m?.evaluation.median ?? null, m?.evaluation.p95 ?? null, row.mapScore && !row.mapScore.ok ? row.mapScore.reason : null,
      m?.fromNeighbours ?? null, m?.fromFallback ?? null, m?.unmapped ?? null,
      row.tipCount, row.tips ? 100 * row.tips.mean : null, row.tips ? 100 * row.tips.max : null, row.tips?.ownLeaves ?? null,
      cscd ? ratio(rows, row.mesh) : null, cscd ? errorRatio(rows, row.mesh, 'msls', 'derived') : null,
      cscd ? errorRatio(rows, row.mesh, 'msls', 'map') : null].map(quote).join(','));
  }
  return `${lines.join('\n')}\n`;
}

/** bench/results/<date>[-quick], or the first of -2, -3... that no earlier run has written. */
function runName(quick: boolean): string {
  return claimResultName(resultsDir, `${new Date().toISOString().slice(0, 10)}${quick ? '-quick' : ''}`, ['md', 'csv', 'svg']);
}

function describeMachine(methods: Method[]): string {
  const cpu = /model name\s*:\s*(.*)/.exec(readFileSync('/proc/cpuinfo', 'utf8'))?.[1] ?? 'unknown CPU';
  const gel = methods.includes('ls') || methods.includes('msls');
  const python = shell(gel ? venvPython : 'python3', ['--version']).replace(/^Python /, '');
  const pygel = gel ? shell(venvPython, ['-c', 'from importlib.metadata import version; print(version("PyGEL3D"))']) : 'not used';
  const cgal = methods.includes('mcf') ? shell('dpkg-query', ['-W', '-f=${Version}', 'libcgal-dev']) : 'not used';
  const commit = shell('git', ['rev-parse', '--short', 'HEAD']);
  const dirty = shell('git', ['status', '--porcelain', '--untracked-files=no']) !== ''; // its own results file, claimed already, is untracked
  const load = os.loadavg().map((x) => x.toFixed(2)).join(' ');
  return `Run on ${new Date().toISOString().replace(/\.\d+Z$/, 'Z')}, commit ${commit}${dirty ? ' (with uncommitted changes in the work tree)' : ''}. `
      + `Machine: ${shell('nproc', [])} cores (nproc), ${cpu}; Node ${process.version}, Python ${python}, pygel3d ${pygel}, `
      + `CGAL ${cgal === 'unknown' || cgal === 'not used' ? cgal : `${cgal.replace(/-[^-]*$/, '')} (Debian libcgal-dev ${cgal})`}; load average ${load} at the start (times compare best on an idle machine).`;
}

// ---------------------------------------------------------------------------------------------------
// Main

function prepare(methods: Method[], noBuild: boolean): void {
  const steps: [string, string[]][] = noBuild ? [] : [['bash', ['scripts/build-wasm.sh']]];
  if (noBuild && !existsSync(wasmPath)) throw new BenchError(`--no-build: there is no core at ${path.relative(repoRoot, fileURLToPath(wasmPath))}`);
  const baselines = methods.filter((m) => m !== 'cscd');
  if (baselines.length) steps.push(['bash', ['bench/setup.sh', ...baselines]]);
  for (const [command, args] of steps) {
    process.stdout.write(`bench: ${command} ${args.join(' ')}\n`);
    const result = spawnSync(command, args, { cwd: repoRoot, stdio: ['ignore', 'inherit', 'inherit'] });
    if (result.status !== 0) throw new BenchError(`${args[0]} failed (exit code ${result.status ?? result.signal})`);
  }
}

async function main(): Promise<void> {
  const config = parseCommandLine(process.argv.slice(2));
  prepare(config.methods, config.noBuild);
  const machine = describeMachine(config.methods);
  const name = runName(config.quick);
  const runDir = path.join(repoRoot, '.deps', 'bench', 'runs', name);
  mkdirSync(runDir, { recursive: true });
  mkdirSync(resultsDir, { recursive: true });
  const out = path.join(resultsDir, name);
  process.stdout.write(`bench: ${config.meshes.length} meshes × ${config.methods.join(', ')}; results in ${path.relative(repoRoot, out)}.{md,csv,svg}, `
    + `skeletons and logs in ${path.relative(repoRoot, runDir)}/\n`);

  // Labels: file names, with the folder in front when two folders hold the same name.
  const labels = config.meshes.map((file, _, all) => {
    const base = path.basename(file);
    return all.filter((f) => path.basename(f) === base).length > 1 ? `${path.basename(path.dirname(file))}/${base}` : base;
  });

  let core = await loadCoreNode();
  /** Why scoring failed, one line; a WASM trap (not an error about the input) may leave the module unusable: start a fresh one. */
  const failure = async (error: unknown) => {
    if (!(error instanceof CoreError || error instanceof SkeletonFormatError || error instanceof VertexMapError)) core = await loadCoreNode();
    return describe(error);
  };
  const rows: Row[] = [];
  for (let i = 0; i < config.meshes.length; i++) {
    const file = config.meshes[i];
    const label = labels[i];
    const fileLabel = label.replace(/[/\\]/g, '_');
    let mesh: MeshArrays | null = null;
    let vertices: number | null = null;
    let genus: number | null = null;
    let diagonal = NaN;
    let meshError = '';
    const tips = groundTruthTips(file);
    try {
      mesh = parseMesh(readFileSync(file), file);
      const facts = core.inspect(mesh);
      [vertices, genus, diagonal] = [facts.vertices, facts.genus, facts.bboxDiagonal];
    } catch (error) {
      meshError = `mesh unreadable: ${describe(error)}`;
    }
    process.stdout.write(`[${i + 1}/${config.meshes.length}] ${label} (V ${vertices ?? '?'}, genus ${genus ?? 'n/a'})\n`);

    const mine: Row[] = [];
    for (const method of config.methods) {
      const run = mesh ? runMethod(method, file, runDir, fileLabel, config.timeout, config.cpu) : { status: 'failed' as const, seconds: null, reason: meshError, file: '' };
      process.stdout.write(`  ${method.padEnd(5)} ${runCell(run, config.timeout)}${run.status === 'ok' ? ' s' : ''}\n`);
      mine.push({ mesh: label, vertices, genus, method, run, score: null, mapScore: null, tipCount: tips?.length ?? null, tips: null });
    }

    for (const row of mine) {
      if (row.run.status !== 'ok' || !mesh) continue;
      const started = performance.now();
      let skeleton: ParsedSkeleton | null = null;
      let derivedRadii: Float64Array | null = null;
      try {
        skeleton = parseSkeleton(readFileSync(row.run.file), row.run.file);
        // Rule 1, radii: null for every method: one rule derives them from the mesh, whatever the method reports.
        const evaluation = core.evaluate(mesh, { nodes: skeleton.nodes, edges: skeleton.edges, radii: null });
        derivedRadii = evaluation.radii;
        row.score = { ok: true, evaluation: figures(evaluation) };
      } catch (error) {
        row.score = { ok: false, reason: await failure(error), nodes: skeleton ? skeleton.nodes.length / 3 : null };
      }
      if (skeleton) {
        row.tips = tips ? tipGap(tips, skeleton, diagonal) : null;
        try {
          // Rule 2: radii from the method's own vertex map; nodes of components that own no vertex keep rule 1's radius.
          const map = readVertexMap(row.method, row.run.file, mesh.positions);
          const { radii, fromNeighbours, fromFallback } = vertexMapRadii(mesh.positions, skeleton, map, derivedRadii);
          const evaluation = core.evaluate(mesh, { nodes: skeleton.nodes, edges: skeleton.edges, radii });
          const unmapped = Array.prototype.filter.call(map, (n: number) => n === -1).length;
          row.mapScore = { ok: true, evaluation: figures(evaluation), fromNeighbours, fromFallback, unmapped };
        } catch (error) {
          row.mapScore = { ok: false, reason: await failure(error) };
        }
      }
      const took = ((performance.now() - started) / 1000).toFixed(1);
      const mapText = row.mapScore === null ? '' : `; vertex map: ${row.mapScore.ok ? `error ${num(row.mapScore.evaluation.reconError)}` : `n/a (${row.mapScore.reason})`}`;
      const tipText = row.tips ? `; tip gap ${percent(row.tips.mean)}% / ${percent(row.tips.max)}%, own leaves ${row.tips.ownLeaves} / ${row.tipCount}` : '';
      process.stdout.write(`  scored ${row.method.padEnd(5)} ${row.score.ok ? `error ${num(row.score.evaluation.reconError)}, ${row.score.evaluation.nodes} nodes, `
        + `${row.score.evaluation.cycles} cycles` : `failed: ${row.score.reason}`}${mapText}${tipText} (${took} s)\n`);
    }
    rows.push(...mine);

    writeFileSync(`${out}.md`, markdown(rows, config, machine, i + 1));
    writeFileSync(`${out}.csv`, csv(rows));
    const points = rows.flatMap((r) => (r.score?.ok && r.run.seconds !== null
      ? [{ method: r.method, mesh: r.mesh, seconds: r.run.seconds, error: r.score.evaluation.reconError }] : []));
    writeFileSync(`${out}.svg`, errorVsSecondsSvg(points, config.methods, `Reconstruction error against time, ${name}`));
  }
  process.stdout.write(`bench: done; ${path.relative(repoRoot, out)}.md\n`);
}

main().catch((error: unknown) => {
  process.stderr.write(`bench: ${describe(error)}\n`);
  process.exit(1);
});
