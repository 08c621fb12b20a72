// Loop shortening on clouds, for docs/pointcloud.md: per cloud, the approximate loops of `--sources`
// sources drawn with the seed are shortened in the paper's sphere (as PointCloudRealization does: centred
// at the source, through the approximate loop's farthest point), each timed alone after a warm-up; then,
// with `--skeletons`, the skeleton at `--n` and the seed, its cycles and its error against the source
// mesh (meshes/<name without _clean>.ply beside the clouds' folder).
//
//   node --import tsx scripts/time-cloud-shortening.ts [--sources 10] [--seed 1] cloud.ply...
//   node --import tsx scripts/time-cloud-shortening.ts --skeletons [--n 60] [--seed 1] cloud.ply...
//
// For before/after tables, alternate runs with the two builds' build/wasm/cscd.js and cscd.wasm copied in
// (the pair: the glue's import names change from build to build).
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { loadCoreNode } from '../lib/core/node.ts';
import { random } from '../lib/core/random.ts';
import { parseMesh, parseShape } from '../lib/io/index.ts';

const { positionals, values } = parseArgs({
  allowPositionals: true,
  options: {
    sources: { type: 'string', default: '10' },
    seed: { type: 'string', default: '1' },
    n: { type: 'string', default: '60' },
    skeletons: { type: 'boolean', default: false },
  },
});
const core = await loadCoreNode();

function cloudOf(file: string) {
  const shape = parseShape(new Uint8Array(readFileSync(file)), path.basename(file));
  if (shape.kind !== 'cloud') throw new Error(`${file} holds a mesh`);
  return shape;
}

function shortening(file: string) {
  const parsed = cloudOf(file);
  const cloud = core.openCloud(parsed);
  try {
    const points = cloud.facts.points;
    const next = random(Number(values.seed));
    let total = 0, cpu = 0, steps = 0, count = 0;
    const lengths: string[] = [];
    for (let k = 0; k < Number(values.sources); k++) {
      const source = Math.floor(next() * points);
      const stages = cloud.separatorStages(source);
      if (stages.status !== 'ok') continue;
      const loop = stages.approxLoop;
      const p = parsed.positions;
      const centre: [number, number, number] = [p[3 * source], p[3 * source + 1], p[3 * source + 2]];
      let radius = 0;
      for (let i = 0; i < loop.length; i += 3)
        radius = Math.max(radius, Math.hypot(loop[i] - centre[0], loop[i + 1] - centre[1], loop[i + 2] - centre[2]));
      if (k === 0) cloud.shortenLoop(loop, { sphere: { center: centre, radius } }); // warm-up
      const started = performance.now(), startedCpu = process.cpuUsage();
      const shortened = cloud.shortenLoop(loop, { sphere: { center: centre, radius } });
      total += performance.now() - started;
      const used = process.cpuUsage(startedCpu);
      cpu += (used.user + used.system) / 1000;
      steps += shortened.iterations;
      count++;
      lengths.push(shortened.status === 'ok' ? shortened.length.toFixed(2) : shortened.status);
    }
    process.stdout.write(
      `| ${path.basename(file)} | ${count} | ${(total / count).toFixed(1)} | ${(cpu / count).toFixed(1)} | ${(steps / count).toFixed(1)} | ${lengths.join(' ')} |\n`,
    );
  } finally {
    cloud.dispose();
  }
}

function skeleton(file: string) {
  const name = path.basename(file, '.ply').replace(/_clean$/, '');
  const meshFile = path.join(path.dirname(file), '..', 'meshes', `${name}.ply`);
  const cloud = core.openCloud(cloudOf(file));
  try {
    const started = performance.now();
    const s = cloud.skeleton({ n: Number(values.n), seed: Number(values.seed) });
    const seconds = (performance.now() - started) / 1000;
    let error = 'no mesh';
    if (existsSync(meshFile)) {
      const mesh = parseMesh(new Uint8Array(readFileSync(meshFile)), path.basename(meshFile));
      error = core.evaluate(mesh, { nodes: s.nodes, edges: s.edges, radii: null }).reconError.toFixed(4);
    }
    process.stdout.write(`| ${path.basename(file)} | ${s.stats.cycles} | ${error} | ${seconds.toFixed(1)} |\n`);
  } finally {
    cloud.dispose();
  }
}

if (values.skeletons) {
  process.stdout.write(`| cloud | cycles | error (x1e3) | seconds |\n| --- | ---: | ---: | ---: |\n`);
  for (const file of positionals) skeleton(file);
} else {
  process.stdout.write(`| cloud | loops | shortening, ms per loop | CPU ms per loop | steps per loop | lengths |\n| --- | ---: | ---: | ---: | ---: | --- |\n`);
  for (const file of positionals) shortening(file);
}
