// Measures what docs/limits.md reports: for generated tori of several sizes, the time to read a binary PLY
// (parse + repair), inspect it, open the geodesic solver (heat-method prefactorisation) and compute one
// distance, and the process's peak memory; the time to decimate the largest one. One child process per
// size, so peak memory is that size's own. Run: node --import tsx scripts/measure-limits.ts [faces...]
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { loadCoreNode } from '../lib/core/node.ts';
import { parseMesh } from '../lib/io/index.ts';
import { repairMesh } from '../lib/io/repair.ts';
import { decimate } from '../lib/mesh/decimate.ts';
import { binaryPly, torusOfFaces } from '../tests/unit/support/big-mesh.ts';

interface Row {
  faces: number;
  vertices: number;
  readMs: number;
  inspectMs: number;
  solverMs: number | null;
  distanceMs: number | null;
  decimateMs: number | null;
  decimatedFaces: number | null;
  peakMB: number;
}

async function measure(faces: number, withSolver: boolean, decimateTo: number | null): Promise<Row> {
  const bytes = binaryPly(torusOfFaces(faces));
  let t = performance.now();
  const mesh = repairMesh(parseMesh(bytes, 'torus.ply')).mesh;
  const readMs = performance.now() - t;
  const core = await loadCoreNode();
  t = performance.now();
  const facts = core.inspect(mesh);
  const inspectMs = performance.now() - t;
  let solverMs = null, distanceMs = null, decimateMs = null, decimatedFaces = null;
  if (decimateTo !== null) {
    t = performance.now();
    decimatedFaces = decimate(mesh, decimateTo).triangles.length / 3;
    decimateMs = performance.now() - t;
  }
  if (withSolver) {
    t = performance.now();
    const surface = core.openSurface(mesh);
    solverMs = performance.now() - t;
    t = performance.now();
    surface.distanceFromVertex(0);
    distanceMs = performance.now() - t;
  }
  const peakMB = process.resourceUsage().maxRSS / 1024;
  return { faces: facts.faces, vertices: facts.vertices, readMs, inspectMs, solverMs, distanceMs, decimateMs, decimatedFaces, peakMB };
}

const args = process.argv.slice(2);
if (args[0] === '--child') {
  const [faces, withSolver, decimateTo] = args.slice(1).map(Number);
  process.stdout.write(JSON.stringify(await measure(faces, withSolver === 1, decimateTo > 0 ? decimateTo : null)));
} else {
  const sizes = args.length > 0 ? args.map(Number) : [50_000, 100_000, 200_000, 400_000];
  const runs: [number, number, number][] = [...sizes.map((f): [number, number, number] => [f, 1, Math.round(f / 4)]), [1_000_000, 0, 100_000]];
  const script = fileURLToPath(import.meta.url);
  const s = (ms: number | null) => (ms === null ? '–' : (ms / 1000).toFixed(1));
  console.log('| faces | vertices | read (s) | inspect (s) | solver open (s) | one distance (s) | decimate to | decimate (s) | peak memory (MB) |');
  console.log('|---|---|---|---|---|---|---|---|---|');
  for (const [faces, withSolver, decimateTo] of runs) {
    const out = execFileSync(process.execPath, ['--import', 'tsx', script, '--child', String(faces), String(withSolver), String(decimateTo)], { encoding: 'utf8', maxBuffer: 1 << 20 });
    const r = JSON.parse(out) as Row;
    console.log(`| ${r.faces} | ${r.vertices} | ${s(r.readMs)} | ${s(r.inspectMs)} | ${s(r.solverMs)} | ${s(r.distanceMs)} | ${r.decimatedFaces ?? '–'} | ${s(r.decimateMs)} | ${Math.round(r.peakMB)} |`);
  }
}
