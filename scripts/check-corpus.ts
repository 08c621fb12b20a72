// Whole-corpus checks, too long for the unit suite (which keeps a representative part of each):
//
//   npm run check:corpus [-- meshes...]
//
// 1. Skeleton topology in auto mode on every closed connected mesh of ../shared/data (MANIFEST.md):
//    one connected skeleton whose cycle rank is the genus, at least 98% of its nodes inside the shape
//    (the unit suite checks genus 0 to 4 on six small meshes: tests/unit/skeleton-topology.test.ts).
// 2. A million triangles parse in under 5 s in each of OBJ, binary PLY and binary STL.
// Prints one line per check; exit code 1 if any fails.
import { parseMesh } from '../lib/io/index.ts';
import { loadCoreNode } from '../lib/core/node.ts';
import { closedConnectedMeshes, topologyProblems } from '../tests/unit/support/topology.ts';
import { grid, toBinaryPly, toBinaryStl, toObj, TRIANGLES, VERTICES } from '../tests/unit/support/million.ts';

const PARSE_LIMIT_MS = 5000;
const only = process.argv.slice(2);
const failures: string[] = [];
const report = (name: string, problems: string[], seconds: number) => {
  process.stdout.write(`${problems.length ? 'FAIL' : 'ok  '} ${name.padEnd(48)} ${seconds.toFixed(1).padStart(6)} s${problems.length ? `  ${problems.join('; ')}` : ''}\n`);
  if (problems.length) failures.push(name);
};

const core = await loadCoreNode();
const meshes = closedConnectedMeshes().filter(({ file }) => !only.length || only.some((m) => file === m || file === `${m}.ply`));
for (const { file, genus } of meshes) {
  const start = performance.now();
  let problems: string[];
  try {
    problems = topologyProblems(core, file, genus);
  } catch (error) {
    problems = [`threw: ${error instanceof Error ? error.message : String(error)}`];
  }
  report(`topology of ${file} (genus ${genus})`, problems, (performance.now() - start) / 1000);
}

if (!only.length) {
  const mesh = grid();
  for (const [name, encode] of [['grid.obj', toObj], ['grid.ply', toBinaryPly], ['grid.stl', toBinaryStl]] as const) {
    const bytes = encode(mesh);
    const start = performance.now();
    const parsed = parseMesh(bytes, name);
    const elapsed = performance.now() - start;
    const problems: string[] = [];
    if (parsed.positions.length !== 3 * VERTICES || parsed.triangles.length !== 3 * TRIANGLES) problems.push('wrong counts');
    // === rather than a tolerance: OBJ keeps every digit (and -0 written as "0" matches).
    if (name.endsWith('.obj') && mesh.positions.some((x, i) => parsed.positions[i] !== x)) problems.push('coordinates changed');
    if (elapsed >= PARSE_LIMIT_MS) problems.push(`took over ${PARSE_LIMIT_MS / 1000} s`);
    report(`parse a million triangles: ${name}`, problems, elapsed / 1000);
  }
}

process.stdout.write(failures.length ? `check:corpus: ${failures.length} failed\n` : 'check:corpus: all passed\n');
process.exit(failures.length ? 1 : 0);
