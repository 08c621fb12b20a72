// Time to open point clouds in the core (kNN, tufted triangulation, prefactored heat solver) and per
// geodesic distance, for docs/pointcloud.md: each cloud checked as the CLI checks it, opened in a warm
// core (a first small cloud takes the module's first-call cost), then `--sources` distances from points
// drawn with the seed.
//
//   node --import tsx scripts/time-cloud.ts [--neighbours 30] [--sources 20] cloud.ply...
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { loadCoreNode } from '../lib/core/node.ts';
import { random } from '../lib/core/random.ts';
import { checkCloud } from '../lib/io/cloud-check.ts';
import { parseShape } from '../lib/io/index.ts';

const { positionals, values } = parseArgs({
  allowPositionals: true,
  options: { neighbours: { type: 'string', default: '30' }, sources: { type: 'string', default: '20' } },
});
const neighbours = Number(values.neighbours);
const sources = Number(values.sources);
const core = await loadCoreNode();

function cloudOf(file: string) {
  const shape = parseShape(readFileSync(file), file);
  if (shape.kind !== 'cloud') throw new Error(`${file} holds a mesh`);
  return checkCloud(shape, neighbours).cloud;
}

const warmUp = cloudOf(positionals[0]);
core.openCloud({ positions: warmUp.positions.slice(0, 3 * 500), normals: null }, { neighbours }).dispose();

process.stdout.write(`| cloud | points | open, s | first distance, s | each further distance, ms (mean of ${sources - 1}) |\n| --- | ---: | ---: | ---: | ---: |\n`);
for (const file of positionals) {
  const cloud = cloudOf(file);
  const points = cloud.positions.length / 3;
  const next = random(1);
  let started = performance.now();
  const opened = core.openCloud(cloud, { neighbours });
  const open = performance.now() - started;
  const times: number[] = [];
  for (let i = 0; i < sources; i++) {
    started = performance.now();
    opened.distance(Math.floor(next() * points));
    times.push(performance.now() - started);
  }
  opened.dispose();
  const further = times.slice(1).reduce((a, b) => a + b, 0) / (sources - 1);
  process.stdout.write(`| ${path.basename(file)} | ${points} | ${(open / 1000).toFixed(2)} | ${(times[0] / 1000).toFixed(3)} | ${further.toFixed(1)} |\n`);
}
