// Method `cscd` of the point-cloud bench (bench/clouds.ts): CSCD-PC with the default options, the same
// WASM core and calls as `cscd skeleton <cloud>`, in a process of its own so that it is timed and pinned
// like the baseline.
//
//   node --import tsx bench/runners/cscd-cloud.ts <cloud> <skeleton.json> [--graph <graph.json>] [--seed S]
//
// Writes the skeleton as our JSON and prints, as the last line of stdout, {"seconds": S, "memoryMB": M}:
// the wall time of openCloud (neighbours, tufted triangulation, heat solver) and skeleton, from the
// checked cloud to the skeleton (reading, checking and writing excluded). --graph also writes the
// cloud's neighbourhood graph ({positions, edges}, untimed), which the MSLS baseline runs on.
import { readFile, writeFile } from 'node:fs/promises';
import { parseArgs } from 'node:util';
import { loadCoreNode } from '../../lib/core/node.ts';
import { defaultCloudOptions } from '../../lib/core/options.ts';
import { checkCloud } from '../../lib/io/cloud-check.ts';
import { parseShape } from '../../lib/io/index.ts';
import { writeSkeletonJson } from '../../lib/io/skeleton.ts';
import { seedArgument } from '../process.ts';

const { positionals, values } = parseArgs({
  allowPositionals: true,
  options: { graph: { type: 'string' }, seed: { type: 'string', default: String(defaultCloudOptions.seed) } },
});
const [cloudPath, outPath] = positionals;
const seed = seedArgument(values.seed);
if (!cloudPath || !outPath || seed === null) {
  process.stderr.write('usage: node --import tsx bench/runners/cscd-cloud.ts <cloud> <skeleton.json> [--graph <graph.json>] [--seed S]\n');
  process.exit(2);
}
const options = { ...defaultCloudOptions, seed };
const parsed = parseShape(await readFile(cloudPath), cloudPath);
if (parsed.kind !== 'cloud') throw new Error(`${cloudPath} is a mesh, not a point cloud`);
const { cloud: checked } = checkCloud(parsed, options.neighbours);
const core = await loadCoreNode();

const started = performance.now();
const cloud = core.openCloud(checked, options);
const skeleton = cloud.skeleton(options);
const seconds = (performance.now() - started) / 1000;

await writeFile(outPath, writeSkeletonJson(skeleton, { mesh: cloudPath, options }));
if (values.graph) {
  const { edges } = cloud.neighbourhood();
  await writeFile(values.graph, JSON.stringify({ positions: Array.from(checked.positions), edges: Array.from(edges) }));
}
cloud.dispose();
process.stdout.write(`${JSON.stringify({ seconds, memoryMB: core.memoryMB() })}\n`);
