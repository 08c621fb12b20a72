// Method `cscd` of the bench: CSCD Studio's skeleton with the default options, the same WASM core and
// calls as `cscd skeleton` (cli/commands/skeleton.ts), in a process of its own so that it is timed and
// pinned like the baselines.
//
//   node --import tsx bench/runners/cscd.ts <mesh> <skeleton.json>
//
// Writes the skeleton as our JSON and prints, as the last line of stdout, {"seconds": S}: the wall time
// of openRefinedSurface (refining a coarse mesh, as the CLI does, and the per-mesh geodesic solver) and
// skeleton, i.e. from the parsed mesh to the skeleton (reading the file, loading the WASM and writing excluded).
import { readFile, writeFile } from 'node:fs/promises';
import { loadCoreNode } from '../../lib/core/node.ts';
import { defaultOptions } from '../../lib/core/options.ts';
import { parseMesh } from '../../lib/io/index.ts';
import { writeSkeletonJson } from '../../lib/io/skeleton.ts';

const [meshPath, outPath] = process.argv.slice(2);
if (!meshPath || !outPath) {
  process.stderr.write('usage: node --import tsx bench/runners/cscd.ts <mesh> <skeleton.json>\n');
  process.exit(2);
}

const mesh = parseMesh(await readFile(meshPath), meshPath);
const core = await loadCoreNode();

const started = performance.now();
const surface = core.openRefinedSurface(mesh);
let skeleton;
try {
  skeleton = surface.skeleton({});
} finally {
  surface.dispose();
}
const seconds = (performance.now() - started) / 1000;

await writeFile(outPath, writeSkeletonJson(skeleton, { mesh: meshPath, options: { ...defaultOptions } }));
process.stdout.write(`${JSON.stringify({ seconds })}\n`);
