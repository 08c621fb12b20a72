// The curve skeleton of every shared mesh with the default options, in one process (the core is loaded
// once), as a table in docs/results.md:
//
//   npx tsx scripts/results.ts [meshes...]
//
// Default meshes: every ../shared/data/meshes/*.ply. Per mesh: size and genus (core.inspect), N used,
// candidates, pruned, packed, skeleton nodes, edges, independent cycles and connected components, whether
// the cycles match the genus and the components the mesh's, and the wall-clock seconds of
// Surface.skeleton (one thread); then the candidates per fate, the shape of the graph (branch nodes,
// leaves, largest degree), the regions that contain a handle of the shape (which explains cycles < genus)
// and the core's milliseconds per stage. Exit code 1 if the core threw for any mesh, 0 otherwise (a skeleton
// whose cycles differ from the genus is a reported result, not a failure of the script).
import { createHash } from 'node:crypto';
import { readdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { CoreError, loadCoreNode, wasmPath, type CandidateFate, type Core, type MeshArrays, type MeshFacts, type Skeleton } from '../lib/core/node.ts';
import { defaultOptions } from '../lib/core/options.ts';
import { graphTopology } from '../lib/graph/topology.ts';
import { UnionFind } from '../lib/graph/union-find.ts';
import { parseMesh } from '../lib/io/index.ts';
import { SKELETON_WRITERS } from '../lib/io/skeleton.ts';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const sharedMeshes = path.resolve(repoRoot, '..', 'shared', 'data', 'meshes');
const OUT = path.join(repoRoot, 'docs', 'results.md');

/** Every candidate fate, in the order of the table (the Record makes the compiler check that none is missing). */
const FATES = Object.keys({ packed: 0, overlapping: 0, short: 0, outside: 0, failed: 0 } satisfies Record<CandidateFate, 0>) as CandidateFate[];

interface Row {
  mesh: string;
  facts: MeshFacts | null;
  skeleton: Skeleton | null;
  /** Connected components and independent cycles of the skeleton graph, counted here. */
  components: number | null;
  graphCycles: number | null;
  /** Node degrees of the skeleton graph. */
  degrees: number[];
  /** Regions (nodes) whose faces form a surface with handles: [node, genus]. */
  handles: [number, number][];
  seconds: number | null;
  error: string | null;
}

function describe(error: unknown): string {
  const text = error instanceof Error ? (error instanceof CoreError ? error.message : `${error.name}: ${error.message}`) : String(error);
  return text.split('\n')[0];
}

/** Why a skeleton looks wrong, beyond cycles != genus (reported in its own column). */
function oddities(row: Row): string[] {
  const { skeleton, facts } = row;
  if (!skeleton || !facts) return [];
  const odd: string[] = [];
  const nodes = skeleton.nodes.length / 3;
  if (row.components !== null && row.components !== facts.components) odd.push(`${row.components} skeleton components for ${facts.components} mesh components`);
  if (skeleton.radii.length !== nodes) odd.push(`${skeleton.radii.length} radii for ${nodes} nodes`);
  if (!skeleton.nodes.every(Number.isFinite)) odd.push('non-finite node positions');
  if (!skeleton.radii.every((r) => Number.isFinite(r) && r > 0)) odd.push('radii that are not positive finite numbers');
  if (skeleton.vertexToNode.length !== facts.vertices) odd.push(`vertexToNode has ${skeleton.vertexToNode.length} entries for ${facts.vertices} vertices`);
  if (!skeleton.vertexToNode.every((n) => n < nodes)) odd.push('vertexToNode refers to missing nodes');
  if (row.graphCycles !== null && row.graphCycles !== skeleton.stats.cycles) {
    odd.push(`stats.cycles is ${skeleton.stats.cycles} but the graph has ${row.graphCycles} independent cycles`);
  }
  if (skeleton.packed.length !== skeleton.stats.packed) odd.push(`packed has ${skeleton.packed.length} indices, stats.packed says ${skeleton.stats.packed}`);
  const selfLoops = Array.from({ length: skeleton.edges.length / 2 }, (_, k) => skeleton.edges[2 * k] === skeleton.edges[2 * k + 1]).filter(Boolean).length;
  if (selfLoops) odd.push(`${selfLoops} self-loop edges`);
  return odd;
}

/**
 * The genus of each region: the faces whose three vertices belong to one node, as a surface (cut open
 * at vertices where it is pinched, so that the genus is an integer). A region with a handle swallows a
 * cycle of the shape: the skeleton then has fewer cycles than the genus. Needs consistently oriented
 * faces (the core checks that the mesh is); returns [node, genus] for the regions with genus > 0.
 */
function regionHandles(mesh: MeshArrays, vertexToNode: Uint32Array): [number, number][] {
  const { triangles } = mesh;
  const vertexCount = mesh.positions.length / 3;
  const faceCount = triangles.length / 3;
  const region = (f: number) => {
    const r = vertexToNode[triangles[3 * f]];
    return vertexToNode[triangles[3 * f + 1]] === r && vertexToNode[triangles[3 * f + 2]] === r ? r : -1;
  };
  const faceRegion = Int32Array.from({ length: faceCount }, (_, f) => region(f));
  /** Face of the half-edge u -> v. */
  const faceOf = new Map<number, number>();
  for (let f = 0; f < faceCount; f++) {
    for (let k = 0; k < 3; k++) faceOf.set(triangles[3 * f + k] * vertexCount + triangles[3 * f + (k + 1) % 3], f);
  }
  const corner = (f: number, v: number) => (triangles[3 * f] === v ? 0 : triangles[3 * f + 1] === v ? 1 : 2);
  const after = (f: number, v: number) => triangles[3 * f + (corner(f, v) + 1) % 3];
  const isBoundary = (f: number, u: number, v: number) => {
    const twin = faceOf.get(v * vertexCount + u);
    return twin === undefined || faceRegion[twin] !== faceRegion[f];
  };

  interface Patch { faces: number[]; boundary: [number, number, number][] }
  const patches = new Map<number, Patch>();
  for (let f = 0; f < faceCount; f++) {
    const r = faceRegion[f];
    if (r < 0) continue;
    if (!patches.has(r)) patches.set(r, { faces: [], boundary: [] });
    const patch = patches.get(r)!;
    patch.faces.push(f);
    for (let k = 0; k < 3; k++) {
      const u = triangles[3 * f + k], v = triangles[3 * f + (k + 1) % 3];
      if (isBoundary(f, u, v)) patch.boundary.push([f, u, v]);
    }
  }

  const handles: [number, number][] = [];
  // Faces join only faces of their own region: one union-find serves every region.
  const pieces = new UnionFind(faceCount);
  for (const [node, { faces, boundary }] of patches) {
    // Boundary loops: from u -> v, turn around v inside the patch to the next boundary half-edge.
    const index = new Map<number, number>(boundary.map(([, u, v], i) => [u * vertexCount + v, i]));
    const seen = new Uint8Array(boundary.length);
    let loops = 0;
    for (let start = 0; start < boundary.length; start++) {
      if (seen[start]) continue;
      loops++;
      for (let h = start; !seen[h];) {
        seen[h] = 1;
        let [f, , v] = boundary[h];
        let w = after(f, v);
        for (let guard = 0; !isBoundary(f, v, w) && guard < 1000; guard++) {
          f = faceOf.get(w * vertexCount + v)!;
          w = after(f, v);
        }
        const next = index.get(v * vertexCount + w);
        if (next === undefined) break;
        h = next;
      }
    }
    // Vertices counted once per fan: a pinched vertex (k outgoing boundary half-edges) counts k times.
    const fans = new Map<number, number>();
    for (const f of faces) for (let k = 0; k < 3; k++) fans.set(triangles[3 * f + k], 1);
    const outgoing = new Map<number, number>();
    for (const [, u] of boundary) outgoing.set(u, (outgoing.get(u) ?? 0) + 1);
    let vertices = 0;
    for (const v of fans.keys()) vertices += Math.max(1, outgoing.get(v) ?? 0);
    const edges = (3 * faces.length + boundary.length) / 2;
    // Components of the faces (through shared edges).
    for (const f of faces) {
      for (let k = 0; k < 3; k++) {
        const twin = faceOf.get(triangles[3 * f + (k + 1) % 3] * vertexCount + triangles[3 * f + k]);
        if (twin !== undefined && faceRegion[twin] === node) pieces.union(f, twin);
      }
    }
    const components = new Set(faces.map((f) => pieces.find(f))).size;
    const genus = (2 * components - (vertices - edges + faces.length) - loops) / 2;
    if (genus !== 0) handles.push([node, genus]);
  }
  return handles.sort((a, b) => a[0] - b[0]);
}

async function run(file: string, state: { core: Core }): Promise<Row> {
  const row: Row = {
    mesh: path.basename(file), facts: null, skeleton: null, components: null, graphCycles: null, degrees: [], handles: [], seconds: null, error: null,
  };
  try {
    const mesh = parseMesh(new Uint8Array(readFileSync(file)), file);
    row.facts = state.core.inspect(mesh);
    const surface = state.core.openSurface(mesh);
    try {
      const start = performance.now();
      row.skeleton = surface.skeleton({ ...defaultOptions });
      row.seconds = (performance.now() - start) / 1000;
    } finally {
      surface.dispose();
    }
    const { components, cycleRank } = graphTopology(row.skeleton.nodes.length / 3, row.skeleton.edges);
    row.components = components;
    row.graphCycles = cycleRank;
    row.degrees = new Array<number>(row.skeleton.nodes.length / 3).fill(0);
    for (const node of row.skeleton.edges) row.degrees[node]++;
    row.handles = regionHandles(mesh, row.skeleton.vertexToNode);
    // What the CLI does with a skeleton, so that a crash there is found here too.
    for (const write of Object.values(SKELETON_WRITERS)) write(row.skeleton, { mesh: row.mesh, options: { ...defaultOptions } });
  } catch (error) {
    row.error = describe(error);
    if (!(error instanceof CoreError)) {
      // A WASM trap or abort can leave the module unusable: the next mesh gets a fresh core.
      state.core = await loadCoreNode();
    }
    throw Object.assign(new Error(row.error), { row });
  }
  return row;
}

/** Which build of the core ran: the date and hash of the WASM file (read just before loading it). */
function describeBuild(): string {
  const date = statSync(wasmPath).mtime.toISOString().slice(0, 16).replace('T', ' ');
  return `build/wasm/cscd.wasm of ${date} UTC, sha256 ${createHash('sha256').update(readFileSync(wasmPath)).digest('hex').slice(0, 12)}`;
}

function markdown(rows: Row[], argv: string[], loads: [number, number], total: number, build: string): string {
  const cell = (value: number | string | null | undefined) => (value === null || value === undefined ? '-' : String(value));
  const line = (cells: (number | string | null | undefined)[]) => `| ${cells.map(cell).join(' | ')} |`;
  const header = ['mesh', 'V', 'F', 'genus', 'N', 'candidates', 'pruned', 'packed', 'nodes', 'edges', 'cycles', 'cycles = genus',
    'components (mesh)', 'seconds'];
  const table = [
    line(header),
    line(header.map((_, i) => (i === 0 ? '---' : i === 11 ? ':---:' : '---:'))),
    ...rows.map(({ mesh, facts, skeleton: s, components, seconds }) => line([
      mesh, facts?.vertices, facts?.faces, facts?.genus, s?.stats.n, s?.stats.candidates, s?.stats.pruned, s?.stats.packed,
      s ? s.nodes.length / 3 : null, s ? s.edges.length / 2 : null, s?.stats.cycles,
      s && facts ? (s.stats.cycles === facts.genus ? 'yes' : '**no**') : null,
      components === null ? null : `${components === facts?.components ? components : `**${components}**`} (${facts?.components ?? '-'})`,
      seconds?.toFixed(2),
    ])),
  ];

  const count = (values: number[], test: (value: number) => boolean) => values.filter(test).length;
  const shapeHeader = ['mesh', 'genus', ...FATES.map((fate) => `${fate}`), 'nodes owning vertices', 'branch nodes', 'leaves', 'max degree',
    'regions with a handle'];
  const shapeTable = [
    '',
    '## What became of the candidates, and the shape of the graph',
    '',
    'Candidates per fate (`candidates.fates`); nodes that own mesh vertices (regions) and the others (branch nodes of stage 2\'s',
    'clique-to-star step); leaves (degree 1) and the largest degree; regions whose faces (those with all three vertices in',
    'the region) form a surface with handles: a handle inside one region is a cycle of the shape that the skeleton cannot',
    'have, so these explain cycles < genus.',
    '',
    line(shapeHeader),
    line(shapeHeader.map((_, i) => (i === 0 ? '---' : '---:'))),
    ...rows.map(({ mesh, facts, skeleton: s, degrees, handles }) => {
      if (!s) return line([mesh, facts?.genus, ...shapeHeader.slice(2).map(() => null)]);
      const owners = new Set(s.vertexToNode).size;
      return line([
        mesh, facts?.genus, ...FATES.map((fate) => s.candidates.fates.filter((f) => f === fate).length),
        owners, s.nodes.length / 3 - owners, count(degrees, (d) => d === 1), Math.max(0, ...degrees),
        handles.length ? handles.map(([node, genus]) => `${node}${genus === 1 ? '' : ` (genus ${genus})`}`).join(', ') : 0,
      ]);
    }),
  ];

  const stages = [...new Set(rows.flatMap((r) => Object.keys(r.skeleton?.stats.timings ?? {})))];
  const stageTable = stages.length === 0 ? [] : [
    '',
    '## Milliseconds per stage (the core\'s `stats.timings`)',
    '',
    line(['mesh', ...stages]),
    line(['---', ...stages.map(() => '---:')]),
    ...rows.map((r) => line([r.mesh, ...stages.map((s) => r.skeleton?.stats.timings[s]?.toFixed(1))])),
  ];
  const notes = rows.flatMap((r) => [
    ...(r.error ? [`- ${r.mesh}: **error** ${r.error}`] : []),
    ...(r.skeleton && r.facts && r.skeleton.stats.cycles !== r.facts.genus
      ? [`- ${r.mesh}: ${r.skeleton.stats.cycles} cycles for genus ${r.facts.genus}`
        + `${r.handles.length ? `; regions with a handle: ${r.handles.map(([node, genus]) => `node ${node} (genus ${genus})`).join(', ')}` : ''}`]
      : []),
    ...oddities(r).map((odd) => `- ${r.mesh}: ${odd}`),
  ]);
  const matching = rows.filter((r) => r.skeleton && r.facts && r.skeleton.stats.cycles === r.facts.genus).length;
  const cpu = /^model name\s*:\s*(.*)$/m.exec(safeRead('/proc/cpuinfo'))?.[1].trim() ?? os.cpus()[0]?.model.trim() ?? 'unknown CPU';
  return [
    '# Curve skeletons of the shared meshes',
    '',
    `Made by \`npx tsx scripts/results.ts${argv.length ? ` ${argv.join(' ')}` : ''}\` on ${new Date().toISOString().slice(0, 10)}: `
      + `${os.availableParallelism()} cores (nproc; ${cpu}), Node ${process.version}, WASM core (one thread; ${build}); `
      + `load average ${loads[0].toFixed(2)} before, ${loads[1].toFixed(2)} after (times are only comparable on an idle machine); `
      + `${total.toFixed(0)} s in all.`,
    `Default options (\`${JSON.stringify(defaultOptions)}\`): N is the number of sources the auto mode settled on.`,
    'V, F and genus come from `core.inspect`; candidates are the separators stage 1 found, pruned those too short to enclose',
    'a feature, packed those kept. Cycles are the independent cycles of the skeleton graph (E - V + components): one per',
    'handle, so they should equal the genus; components are those of the skeleton graph, the mesh\'s in parentheses.',
    'Seconds: wall clock of one `Surface.skeleton` call (stages 1 and 2).',
    '',
    ...table,
    '',
    `Cycles = genus on ${matching} of ${rows.length} meshes.`,
    ...shapeTable,
    ...stageTable,
    ...(notes.length ? ['', '## Notes', '', ...notes] : []),
    '',
  ].join('\n');
}

function safeRead(file: string): string {
  try {
    return readFileSync(file, 'utf8');
  } catch {
    return '';
  }
}

async function main(): Promise<void> {
  const argv = process.argv.slice(2);
  const meshes = argv.length > 0 ? argv
    : readdirSync(sharedMeshes).filter((name) => name.endsWith('.ply')).sort().map((name) => path.join(sharedMeshes, name));
  const loadBefore = os.loadavg()[0];
  const started = performance.now();
  const build = describeBuild();
  const state = { core: await loadCoreNode() };
  const rows: Row[] = [];
  let failed = false;
  for (const file of meshes) {
    let row: Row;
    try {
      row = await run(file, state);
    } catch (error) {
      failed = true;
      row = (error as { row?: Row }).row ?? {
        mesh: path.basename(file), facts: null, skeleton: null, components: null, graphCycles: null, degrees: [], handles: [], seconds: null,
        error: describe(error),
      };
    }
    rows.push(row);
    const s = row.skeleton;
    process.stderr.write(`${row.mesh}: ${!s || row.error ? `error: ${row.error}` : `${s.nodes.length / 3} nodes, ${s.edges.length / 2} edges, `
      + `${s.stats.cycles} cycles (genus ${row.facts?.genus}), N = ${s.stats.n}, ${row.seconds?.toFixed(1)} s`}\n`);
  }
  const text = markdown(rows, argv, [loadBefore, os.loadavg()[0]], (performance.now() - started) / 1000, build);
  writeFileSync(OUT, text);
  process.stdout.write(text);
  process.stderr.write(`wrote ${path.relative(process.cwd(), OUT)}\n`);
  process.exitCode = failed ? 1 : 0;
}

await main();
