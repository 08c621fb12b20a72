// The cut locus and approximate loop on point clouds, for docs/pointcloud.md: per cloud, the
// neighbourhood graph (edges, bridges left out, components), then over `--sources` points drawn with
// the seed: the points passing both tests and the pieces they form before the ridge tree bridges them,
// (with the file's outward normals: the graph edges that join points whose normals point against each
// other, i.e. across a gap between two parts), the cut locus's nodes and pieces after, how far out it lies (share of points nearer the source than
// its median node), the targets tried and the loops traced, and the time per stage.
//
//   node --import tsx scripts/measure-cloud-cut-locus.ts [--sources 20] [--set option=value ...] cloud.ply...
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { loadCoreNode } from '../lib/core/node.ts';
import { optionsFromPairs } from '../lib/core/options.ts';
import { random } from '../lib/core/random.ts';
import { checkCloud } from '../lib/io/cloud-check.ts';
import { parseShape } from '../lib/io/index.ts';

const { positionals, values } = parseArgs({
  allowPositionals: true,
  options: { sources: { type: 'string', default: '20' }, set: { type: 'string', multiple: true, default: [] } },
});
const options = optionsFromPairs(values.set);
const core = await loadCoreNode();

const mean = (xs: number[]) => xs.reduce((a, b) => a + b, 0) / Math.max(xs.length, 1);
const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)] ?? NaN;
const fixed = (x: number, digits = 1) => x.toFixed(digits);

/** Connected pieces of a graph given as flat index pairs over `nodes` nodes. */
function pieces(nodes: number, edges: Uint32Array): number {
  const parent = Array.from({ length: nodes }, (_, i) => i);
  const find = (x: number): number => (parent[x] === x ? x : (parent[x] = find(parent[x])));
  for (let e = 0; e < edges.length; e += 2) parent[find(edges[e])] = find(edges[e + 1]);
  return parent.filter((_, i) => find(i) === i).length;
}

process.stdout.write('| cloud | points | graph edges | bridges left out | edges across a gap | graph components | passing points | pieces before bridging (mean, max) | cut-locus nodes | pieces after | points nearer than its median node | loops (of sources) | targets tried (mean) | cut locus, ms | loop, ms |\n');
process.stdout.write('| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n');
for (const file of positionals) {
  const shape = parseShape(readFileSync(file), file);
  if (shape.kind !== 'cloud') throw new Error(`${file} holds a mesh`);
  const arrays = checkCloud(shape, options.neighbours ?? 30).cloud;
  const cloud = core.openCloud(arrays, options);
  try {
    const graph = cloud.neighbourhood();
    const n = cloud.facts.points;
    const normals = arrays.normals;
    let acrossGap = 0;
    for (let e = 0; normals && e < graph.edges.length; e += 2) {
      const [a, b] = [3 * graph.edges[e], 3 * graph.edges[e + 1]];
      if (normals[a] * normals[b] + normals[a + 1] * normals[b + 1] + normals[a + 2] * normals[b + 2] < 0) acrossGap++;
    }
    const next = random(1);
    const rows = { passing: [] as number[], before: [] as number[], nodes: [] as number[], after: [] as number[], farOut: [] as number[], attempts: [] as number[], cut: [] as number[], loop: [] as number[] };
    let loops = 0;
    const sources = Number(values.sources);
    for (let s = 0; s < sources; s++) {
      const source = Math.floor(next() * n);
      const stages = cloud.separatorStages(source, options);
      const { cutLocus, distance } = stages;
      rows.passing.push(cutLocus.passingPoints);
      rows.before.push(cutLocus.passingPieces);
      rows.nodes.push(cutLocus.vertices.length);
      rows.after.push(pieces(cutLocus.vertices.length, cutLocus.edges));
      const nodeDistance = median(Array.from(cutLocus.vertices, (v) => distance[v]));
      rows.farOut.push(Array.from(distance).filter((d) => d < nodeDistance).length / n);
      rows.attempts.push(stages.attempts);
      rows.cut.push(stages.timings.cutLocus);
      rows.loop.push((stages.timings.target ?? 0) + (stages.timings.loop ?? 0));
      if (stages.status === 'ok') loops++;
    }
    process.stdout.write(`| ${path.basename(file)} | ${n} | ${graph.edges.length / 2} | ${graph.bridgesRemoved} | ${normals ? acrossGap : '-'} | ${graph.components} | ${fixed(mean(rows.passing))} `
      + `| ${fixed(mean(rows.before))}, ${Math.max(...rows.before)} | ${fixed(mean(rows.nodes))} | ${fixed(mean(rows.after))}, ${Math.max(...rows.after)} `
      + `| ${fixed(100 * mean(rows.farOut), 0)}% | ${loops} of ${sources} | ${fixed(mean(rows.attempts))} | ${fixed(mean(rows.cut))} | ${fixed(mean(rows.loop))} |\n`);
  } finally {
    cloud.dispose();
  }
}
