// `npm run bench:clouds`: CSCD-PC on the shared point clouds, against MSLS run on the same cloud's
// neighbourhood graph (pygel3d, the baseline people can run on points), against pc-skeletor's Laplacian-based
// contraction on the cloud (a tree by construction) and against CSCD-M on the mesh the cloud was sampled from.
//
//   npm run bench:clouds [-- [--clouds a,b] [--sampled] [--methods cscd-pc,cscd-m,...] [--seed S] [--timeout S] [--cpu N] [--no-build]]
//
// `--sampled` runs on clouds sampled from the shared meshes no shared cloud comes from (SAMPLED, made
// once into .deps/bench/sampled/) instead of the shared clouds; `--methods` runs only those named; `--seed`
// is CSCD-PC's and CSCD-M's (1, their default, unless given).
//
// Every method runs in its own process pinned to one core (bench/process.ts), with its default options.
// Each skeleton is scored by the paper's reconstruction error against the source mesh (`core.evaluate`,
// radii derived from the mesh by one rule for all) and against the cloud's points (`core.evaluateCloud`,
// radii derived around the points); cycles against the source mesh's genus; leaves; for the trees, the mean
// distance from the reference skeleton points shipped beside them to the skeleton. The table goes to
// bench/results/<date>-clouds[-N].md (rewritten after every cloud), skeletons and logs to
// .deps/bench/runs/<same name>/.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { loadCoreNode, type Core, type Evaluation, type MeshArrays } from '../lib/core/node.ts';
import { defaultCloudOptions } from '../lib/core/options.ts';
import type { CloudArrays } from '../lib/core/types.ts';
import { checkCloud } from '../lib/io/cloud-check.ts';
import { parseMesh, parseShape } from '../lib/io/index.ts';
import { boundingBoxDiagonal } from '../lib/io/repair.ts';
import { parseSkeleton } from '../lib/io/skeleton.ts';
import { refine } from '../lib/mesh/refine.ts';
import { geometricMean, leafIndices, meanDistanceToSkeleton, median } from './metrics.ts';
import { COMPILED_CORE, repoRoot, runPinned, seedArgument, shell, skeletorPython, venvPython, type Run } from './process.ts';
import { claimResultName } from './result-name.ts';

const sharedData = path.resolve(repoRoot, '..', 'shared', 'data');
const sharedClouds = path.join(sharedData, 'pointclouds');
const sampledClouds = path.join(repoRoot, '.deps', 'bench', 'sampled');
/**
 * `--sampled`: clouds of the shared meshes that no shared cloud comes from, sampled as the shared ones were
 * (scripts/sample-cloud.ts: 20,000 points with face normals, or with noise of 0.5% of the diagonal and no normals), so that
 * what is tuned to the shared clouds shows (docs/pointcloud.md, "Clouds from other meshes": these seeds).
 */
const SAMPLED: ReadonlyArray<{ mesh: string; noise: number; seed: number }> = [
  ...['two_torus', 'dtorus', 'rings', 'spider', 'dolphin', 'wolf', 'elk', 'cheburashka', 'spot', 'wrench', 'hanger', 'bunny', 'warrior',
    'thingi10k_37361_linkCupBase'].map((mesh, i) => ({ mesh, noise: 0, seed: i + 1 })),
  ...['two_torus', 'dtorus', 'spider', 'wolf', 'hanger'].map((mesh, i) => ({ mesh, noise: 0.5, seed: i + 15 })),
];
const resultsDir = path.join(repoRoot, 'bench', 'results');
const METHODS = ['cscd-pc', 'msls-graph', 'skeletor', 'cscd-m', 'cscd-m-dense'] as const;
type Method = (typeof METHODS)[number];

/** The reference skeleton points shipped beside a cloud (WoodSKE's trees), or null. */
function referencePoints(cloudFile: string): string | null {
  const file = path.join(sharedData, 'reference_skeletons', `${path.basename(cloudFile, '.ply')}_skeleton_points.ply`);
  return existsSync(file) ? file : null;
}

/**
 * Levels of midpoint subdivision (four times the faces, about four times the vertices, a level) that bring
 * a mesh of `vertices` vertices nearest a cloud of `points` points, on a log scale: CSCD-M at the cloud's
 * resolution, the same surface sampled as densely (0: the mesh as given is nearest).
 */
function levelsNear(vertices: number, points: number): number {
  let best = 0;
  for (let levels = 1; levels <= 3; levels++) {
    if (Math.abs(Math.log((vertices * 4 ** levels) / points)) < Math.abs(Math.log((vertices * 4 ** best) / points))) best = levels;
  }
  return best;
}

/** The shared mesh a cloud was sampled from (../shared/data/pointclouds/MANIFEST.md), or null (trees, external clouds). */
function sourceMesh(cloudFile: string): string | null {
  const stem = path.basename(cloudFile, '.ply').replace(/_(clean|noise[\d.]+|nonuniform|gel_pts)$/, '');
  const mesh = path.join(sharedData, 'meshes', `${stem}.ply`);
  return existsSync(mesh) ? mesh : null;
}

/** The `--sampled` clouds (those `wanted`, or all) made where missing, by scripts/sample-cloud.ts. */
function sampleClouds(wanted: string[] | undefined): void {
  mkdirSync(sampledClouds, { recursive: true });
  for (const { mesh, noise, seed } of SAMPLED) {
    const label = `${mesh}_${noise > 0 ? `noise${noise}` : 'clean'}`;
    const file = path.join(sampledClouds, `${label}.ply`);
    if (existsSync(file) || (wanted && !wanted.includes(label))) continue;
    process.stdout.write(`sampling ${label} from ${mesh}.ply (seed ${seed})\n`);
    const made = spawnSync(process.execPath, ['--import', 'tsx', 'scripts/sample-cloud.ts', path.join(sharedData, 'meshes', `${mesh}.ply`), file,
      '--noise', String(noise), '--seed', String(seed)], { cwd: repoRoot, stdio: ['ignore', 'inherit', 'inherit'] });
    if (made.status !== 0) throw new Error(`scripts/sample-cloud.ts failed on ${mesh}.ply`);
  }
}

interface Row {
  cloud: string;
  points: number;
  mesh: string | null;
  genus: number | null;
  method: Method;
  run: Run;
  nodes: number | null;
  cycles: number | null;
  leaves: number | null;
  againstMesh: number | null;
  againstCloud: number | null;
  /** Mean distance from the reference skeleton points to the skeleton, % of the cloud's bounding-box diagonal. */
  toReference: number | null;
  note: string;
}

const num = (x: number | null, digits = 3) => (x === null ? '–' : Number(x.toPrecision(digits)).toString());

function score(core: Core, row: Row, mesh: MeshArrays | null, cloud: CloudArrays, reference: Float64Array | null): void {
  if (row.run.status !== 'ok') return;
  try {
    const skeleton = parseSkeleton(readFileSync(row.run.file), row.run.file);
    const input = { nodes: skeleton.nodes, edges: skeleton.edges, radii: null };
    const atCloud: Evaluation = core.evaluateCloud(cloud, input);
    row.againstCloud = atCloud.reconError;
    row.nodes = atCloud.nodes;
    row.cycles = atCloud.cycles;
    row.leaves = leafIndices(skeleton.nodes.length / 3, skeleton.edges).length;
    if (mesh) row.againstMesh = core.evaluate(mesh, input).reconError;
    if (reference) row.toReference = meanDistanceToSkeleton(reference, skeleton, boundingBoxDiagonal(cloud.positions));
  } catch (error) {
    row.note = `not scored: ${error instanceof Error ? error.message : String(error)}`;
  }
}

function markdown(rows: Row[], machine: string, argv: string[], sampled: boolean): string {
  const lines = [
    '# Point-cloud bench: CSCD-PC, MSLS on the neighbourhood graph, pc-skeletor, CSCD-M on the source mesh (as given and at the cloud\'s resolution)',
    '',
    machine,
    '',
    sampled
      ? 'Clouds: sampled from the shared meshes that no shared cloud comes from, as the shared clouds were (`scripts/sample-cloud.ts`, 20,000 points with face normals, or noise of 0.5% of the diagonal; the seeds of docs/pointcloud.md, "Clouds from other meshes").'
      : 'Clouds: the shared ones (`../shared/data/pointclouds/`).',
    '',
    `Options: \`npm run bench:clouds -- ${argv.join(' ')}\`. Every method in its own process pinned to one core, default options `
      + '(CSCD-PC and CSCD-M: `n = auto`; MSLS: pygel3d\'s `MSLS_skeleton_and_map` on the edges of the cloud\'s neighbourhood graph, '
      + 'the local-triangulation edges CSCD-PC runs on; skeletor: pc-skeletor 1.0.0\'s LBC, Laplacian-based contraction of the cloud, its '
      + '`skeleton_graph`, a minimum spanning tree over points sampled from the contracted cloud; the cloud scaled to a unit diagonal for it, the skeleton scaled back; '
      + 'cscd-m-dense: CSCD-M on the source mesh after the levels of midpoint subdivision that bring its vertex count nearest the cloud\'s point count, '
      + 'the same surface at the cloud\'s resolution, where at least one level does; scored against the source mesh as given). Seconds: each runner\'s own wall time of the skeletonisation (reading, checking and '
      + `writing excluded; MSLS: building its graph excluded; CSCD's WebAssembly compiled whole before the clock starts, \`${COMPILED_CORE.join(' ')}\`). Error ×1e3, `
      + 'the paper\'s reconstruction error with radii derived by one rule '
      + 'for every method: against the source mesh (its vertices) and against the cloud (its points). Reference: for the trees, the mean '
      + 'distance from the reference skeleton points shipped beside them (WoodSKE) to the skeleton, % of the cloud\'s bounding-box diagonal.',
    '',
    '| cloud | points | source mesh (genus) | method | seconds | nodes | cycles | leaves | error vs mesh ×1e3 | error vs cloud ×1e3 | reference, % diag | note |',
    '| --- | ---: | --- | --- | ---: | ---: | :---: | ---: | ---: | ---: | ---: | --- |',
  ];
  for (const r of rows) {
    const seconds = r.run.status === 'ok' ? r.run.seconds!.toFixed(2) : r.run.status;
    const meshCell = r.mesh ? `${path.basename(r.mesh)} (${r.genus})` : '–';
    const cycles = r.cycles === null ? '–' : r.genus === null ? String(r.cycles) : `${r.cycles} / ${r.genus}`;
    lines.push(`| ${r.cloud} | ${r.points} | ${meshCell} | ${r.method} | ${seconds} | ${r.nodes ?? '–'} | ${cycles} | ${r.leaves ?? '–'} | `
      + `${num(r.againstMesh)} | ${num(r.againstCloud)} | ${num(r.toReference)} | ${r.run.reason || r.note} |`);
  }
  const of = (method: Method) => rows.filter((r) => r.method === method);
  const ratios = (a: Method, b: Method, key: 'againstMesh' | 'seconds') => of(a).flatMap((r) => {
    const other = of(b).find((o) => o.cloud === r.cloud);
    const x = key === 'seconds' ? r.run.seconds : r.againstMesh, y = key === 'seconds' ? other?.run.seconds : other?.againstMesh;
    return x !== null && x !== undefined && y !== null && y !== undefined && y > 0 ? [x / y] : [];
  });
  // CSCD-M on the mesh nearest the cloud's point count: subdivided (cscd-m-dense) or as given.
  const atResolution = of('cscd-pc').flatMap((r) => {
    const other = of('cscd-m-dense').find((o) => o.cloud === r.cloud) ?? of('cscd-m').find((o) => o.cloud === r.cloud);
    return r.run.seconds && other?.run.seconds ? [r.run.seconds / other.run.seconds] : [];
  });
  const topology = of('cscd-pc').filter((r) => r.genus !== null && r.cycles !== null);
  const mslsTopology = of('msls-graph').filter((r) => r.genus !== null && r.cycles !== null);
  const ran = (method: Method) => of(method).length > 0;
  // Rows only for the methods that ran (`--methods`).
  const summary: [boolean, string, string][] = [
    [ran('cscd-pc'), 'CSCD-PC clouds with cycles = genus of the source', `${topology.filter((r) => r.cycles === r.genus).length} of ${topology.length}`],
    [ran('msls-graph'), 'MSLS (graph) clouds with cycles = genus of the source', `${mslsTopology.filter((r) => r.cycles === r.genus).length} of ${mslsTopology.length}`],
    [ran('cscd-m'), 'error vs mesh, CSCD-PC / CSCD-M: geometric mean (median)', `${num(geometricMean(ratios('cscd-pc', 'cscd-m', 'againstMesh')))} (${num(median(ratios('cscd-pc', 'cscd-m', 'againstMesh')))})`],
    [ran('msls-graph'), 'error vs mesh, CSCD-PC / MSLS on the graph: geometric mean (median)', `${num(geometricMean(ratios('cscd-pc', 'msls-graph', 'againstMesh')))} (${num(median(ratios('cscd-pc', 'msls-graph', 'againstMesh')))})`],
    [ran('cscd-m'), 'seconds, CSCD-PC / CSCD-M: median', num(median(ratios('cscd-pc', 'cscd-m', 'seconds')))],
    [ran('cscd-m'), 'seconds, CSCD-PC / CSCD-M at the cloud\'s resolution (cscd-m-dense where there is one, else cscd-m): median', num(median(atResolution))],
    [ran('skeletor'), 'error vs mesh, CSCD-PC / pc-skeletor: geometric mean (median)', `${num(geometricMean(ratios('cscd-pc', 'skeletor', 'againstMesh')))} (${num(median(ratios('cscd-pc', 'skeletor', 'againstMesh')))})`],
    [ran('msls-graph'), 'seconds, CSCD-PC / MSLS on the graph: median', num(median(ratios('cscd-pc', 'msls-graph', 'seconds')))],
    [ran('skeletor'), 'seconds, CSCD-PC / pc-skeletor: median', num(median(ratios('cscd-pc', 'skeletor', 'seconds')))],
  ];
  lines.push('', '| summary | value |', '| --- | --- |', ...summary.filter(([shown]) => shown).map(([, what, value]) => `| ${what} | ${value} |`));
  return `${lines.join('\n')}\n`;
}

async function main(): Promise<void> {
  const { values } = parseArgs({
    options: {
      clouds: { type: 'string' },
      sampled: { type: 'boolean', default: false },
      methods: { type: 'string', default: METHODS.join(',') },
      seed: { type: 'string', default: String(defaultCloudOptions.seed) },
      timeout: { type: 'string', default: '1200' },
      cpu: { type: 'string', default: '1' },
      'no-build': { type: 'boolean', default: false },
    },
  });
  const timeout = Number(values.timeout), cpu = Number(values.cpu);
  if (seedArgument(values.seed) === null) throw new Error(`--seed: not a seed, '${values.seed}'`);
  const seed = ['--seed', values.seed];
  const wanted = values.clouds?.split(',').map((c) => c.replace(/\.ply$/, ''));
  const methods = values.methods.split(',') as Method[];
  const unknown = methods.filter((m) => !METHODS.includes(m));
  if (unknown.length) throw new Error(`unknown method ${unknown.join(', ')}; the methods are ${METHODS.join(', ')}`);
  if (methods.includes('msls-graph') && !methods.includes('cscd-pc')) throw new Error('msls-graph runs on the graph cscd-pc writes: add cscd-pc');
  const cloudFolder = values.sampled ? sampledClouds : sharedClouds;
  if (values.sampled) sampleClouds(wanted);
  const clouds = readdirSync(cloudFolder).filter((f) => f.endsWith('.ply') && (!wanted || wanted.includes(f.replace(/\.ply$/, '')))).sort();
  if (!values['no-build']) {
    const built = spawnSync('bash', ['scripts/build-wasm.sh'], { cwd: repoRoot, stdio: ['ignore', 'inherit', 'inherit'] });
    if (built.status !== 0) throw new Error('scripts/build-wasm.sh failed');
  }
  const baselines = (['msls', 'skeletor'] as const).filter((b) => methods.includes(b === 'msls' ? 'msls-graph' : 'skeletor'));
  if (baselines.length) {
    const bench = spawnSync('bash', ['bench/setup.sh', ...baselines], { cwd: repoRoot, stdio: ['ignore', 'inherit', 'inherit'] });
    if (bench.status !== 0) throw new Error(`bench/setup.sh ${baselines.join(' ')} failed`);
  }

  mkdirSync(resultsDir, { recursive: true });
  const name = claimResultName(resultsDir, `${new Date().toISOString().slice(0, 10)}-clouds`, ['md']);
  const runDir = path.join(repoRoot, '.deps', 'bench', 'runs', name);
  mkdirSync(runDir, { recursive: true });
  const pygel = methods.includes('msls-graph') ? shell(venvPython, ['-c', 'from importlib.metadata import version; print(version("PyGEL3D"))']) : null;
  const cpuName = /model name\s*:\s*(.*)/.exec(readFileSync('/proc/cpuinfo', 'utf8'))?.[1] ?? 'unknown CPU';
  const machine = `Run on ${new Date().toISOString().replace(/\.\d+Z$/, 'Z')}, commit ${shell('git', ['rev-parse', '--short', 'HEAD'])}`
    + `${shell('git', ['status', '--porcelain', '--untracked-files=no']) ? ' (with uncommitted changes in the work tree)' : ''}. Machine: ${os.cpus().length} cores, ${cpuName}; `
    + `Node ${process.version}${pygel ? `, pygel3d ${pygel}` : ''}; load average ${os.loadavg().map((x) => x.toFixed(2)).join(' ')} at the start.`;

  const core = await loadCoreNode();
  const rows: Row[] = [];
  const meshRuns = new Map<string, Run>();
  for (const [i, file] of clouds.entries()) {
    const cloudPath = path.join(cloudFolder, file);
    const label = file.replace(/\.ply$/, '');
    const parsed = parseShape(readFileSync(cloudPath), cloudPath);
    if (parsed.kind !== 'cloud') continue;
    const { cloud } = checkCloud(parsed, defaultCloudOptions.neighbours);
    const meshPath = sourceMesh(file);
    const mesh = meshPath ? parseMesh(readFileSync(meshPath), meshPath) : null;
    const genus = mesh ? core.inspect(mesh).genus : null;
    const referenceFile = referencePoints(file);
    const referenceShape = referenceFile ? parseShape(readFileSync(referenceFile), referenceFile) : null;
    const reference = referenceShape?.kind === 'cloud' ? referenceShape.positions : null;
    process.stdout.write(`[${i + 1}/${clouds.length}] ${label} (${cloud.positions.length / 3} points; ${meshPath ? `${path.basename(meshPath)}, genus ${genus}` : 'no source mesh'})\n`);

    const graph = path.join(runDir, `${label}.graph.json`);
    const cscdFile = path.join(runDir, `${label}.cscd-pc.json`);
    const runs: [Method, Run][] = [];
    if (methods.includes('cscd-pc')) {
      runs.push(['cscd-pc', runPinned([process.execPath, ...COMPILED_CORE, '--import', 'tsx', 'bench/runners/cscd-cloud.ts', cloudPath, cscdFile, '--graph', graph, ...seed], cscdFile, path.join(runDir, `${label}.cscd-pc.log`), timeout, cpu)]);
    }
    if (methods.includes('msls-graph')) {
      const mslsFile = path.join(runDir, `${label}.msls-graph.obj`);
      runs.push(['msls-graph', existsSync(graph)
        ? runPinned([venvPython, 'bench/runners/gel.py', 'msls', '--graph', graph, mslsFile], mslsFile, path.join(runDir, `${label}.msls-graph.log`), timeout, cpu)
        : { status: 'failed', seconds: null, reason: 'no neighbourhood graph (CSCD-PC failed)', file: mslsFile }]);
    }
    if (methods.includes('skeletor')) {
      const skeletorFile = path.join(runDir, `${label}.skeletor.obj`);
      runs.push(['skeletor', runPinned([skeletorPython, 'bench/runners/skeletor.py', cloudPath, skeletorFile], skeletorFile, path.join(runDir, `${label}.skeletor.log`), timeout, cpu)]);
    }
    // CSCD-M at the cloud's resolution: the source mesh subdivided `levels` times (none: the mesh as given is nearest).
    const levels = mesh ? levelsNear(mesh.positions.length / 3, cloud.positions.length / 3) : 0;
    const denseVertices = levels > 0 ? refine(mesh!, levels).positions.length / 3 : 0;
    if (meshPath && methods.includes('cscd-m')) {
      const meshLabel = path.basename(meshPath, '.ply');
      const meshFile = path.join(runDir, `${meshLabel}.cscd-m.json`);
      if (!meshRuns.has(meshPath)) {
        meshRuns.set(meshPath, runPinned([process.execPath, ...COMPILED_CORE, '--import', 'tsx', 'bench/runners/cscd.ts', meshPath, meshFile, ...seed], meshFile, path.join(runDir, `${meshLabel}.cscd-m.log`), timeout, cpu));
      }
      runs.push(['cscd-m', meshRuns.get(meshPath)!]);
      const denseKey = `${meshPath}@${levels}`;
      if (levels > 0 && methods.includes('cscd-m-dense') && !meshRuns.has(denseKey)) {
        const denseFile = path.join(runDir, `${meshLabel}.cscd-m-dense${levels}.json`);
        meshRuns.set(denseKey, runPinned([process.execPath, ...COMPILED_CORE, '--import', 'tsx', 'bench/runners/cscd.ts', meshPath, denseFile, '--subdivide', String(levels), ...seed],
          denseFile, path.join(runDir, `${meshLabel}.cscd-m-dense${levels}.log`), timeout, cpu));
      }
      if (levels > 0 && methods.includes('cscd-m-dense')) runs.push(['cscd-m-dense', meshRuns.get(denseKey)!]);
    }
    for (const [method, run] of runs) {
      const note = method === 'cscd-m-dense' ? `the mesh subdivided to ${denseVertices} vertices` : '';
      const row: Row = { cloud: label, points: cloud.positions.length / 3, mesh: meshPath, genus, method, run, nodes: null, cycles: null, leaves: null, againstMesh: null, againstCloud: null, toReference: null, note };
      score(core, row, mesh, cloud, reference);
      rows.push(row);
      process.stdout.write(`  ${method.padEnd(10)} ${run.status === 'ok' ? `${run.seconds!.toFixed(1)} s, ${row.cycles} cycles, error vs mesh ${num(row.againstMesh)}, vs cloud ${num(row.againstCloud)}${reference ? `, reference ${num(row.toReference)}% of the diagonal` : ''}` : `${run.status} ${run.reason}`}\n`);
    }
    writeFileSync(path.join(resultsDir, `${name}.md`), markdown(rows, machine, process.argv.slice(2), values.sampled));
  }
  process.stdout.write(`bench:clouds: done; ${path.relative(repoRoot, path.join(resultsDir, name))}.md\n`);
}

main().catch((error: unknown) => {
  process.stderr.write(`bench:clouds: ${error instanceof Error ? error.message : String(error)}\n`);
  process.exit(1);
});
