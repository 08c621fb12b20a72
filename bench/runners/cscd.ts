// Method `cscd` of the bench: CSCD Studio's skeleton with the default options, the same WASM core and
// calls as `cscd skeleton` (cli/commands/skeleton.ts), in a process of its own so that it is timed and
// pinned like the baselines.
//
//   node --import tsx bench/runners/cscd.ts <mesh> <skeleton.json> [--workers K --draw-ahead R] [--subdivide L] [--seed S]
//
// --subdivide L runs on the mesh after L levels of midpoint subdivision (lib/mesh/refine.ts: the same
// surface, four times the faces a level), made before the clock starts: the point-cloud bench's CSCD-M at
// about a cloud's resolution.
//
// Writes the skeleton as our JSON and prints, as the last line of stdout, {"seconds": S, "stage1Seconds": T,
// "serialSeconds": D, "memoryMB": M} (D: on a pool, this thread's drawing and accepting; M: this
// thread's core at the end, its peak; it held every candidate and ran stage 2, so no pool thread's core
// needs more):
// the wall time of openRefinedSurface (refining a coarse mesh, as the CLI does, and the per-mesh geodesic
// solver) and skeleton, i.e. from the parsed mesh to the skeleton (reading the file, loading the WASM and
// writing excluded), and of stage 1 alone. With --workers K > 1 stage 1 runs on a pool of K threads
// (bench/parallel.ts), whose opening is part of S.
import { readFile, writeFile } from 'node:fs/promises';
import { parseArgs } from 'node:util';
import { loadCoreNode } from '../../lib/core/node.ts';
import { openNodePool } from '../../lib/core/node-pool.ts';
import { defaultOptions } from '../../lib/core/options.ts';
import { runStage1 } from '../../lib/core/pool.ts';
import { parseMesh } from '../../lib/io/index.ts';
import { refine } from '../../lib/mesh/refine.ts';
import { writeSkeletonJson } from '../../lib/io/skeleton.ts';
import { seedArgument } from '../process.ts';

const { positionals, values } = parseArgs({
  allowPositionals: true,
  options: {
    workers: { type: 'string', default: '1' },
    'draw-ahead': { type: 'string', default: String(defaultOptions.drawAhead) },
    subdivide: { type: 'string', default: '0' },
    seed: { type: 'string', default: String(defaultOptions.seed) },
  },
});
const [meshPath, outPath] = positionals;
const workers = Number(values.workers), levels = Number(values.subdivide);
const drawAhead = Number(values['draw-ahead']), seed = seedArgument(values.seed);
if (!meshPath || !outPath || !(workers >= 1) || !(drawAhead >= 1) || !Number.isInteger(levels) || levels < 0 || seed === null) {
  process.stderr.write('usage: node --import tsx bench/runners/cscd.ts <mesh> <skeleton.json> [--workers K --draw-ahead R] [--subdivide L] [--seed S]\n');
  process.exit(2);
}
const options = { ...defaultOptions, drawAhead, seed };

const mesh = refine(parseMesh(await readFile(meshPath), meshPath), levels);
const core = await loadCoreNode();

const started = performance.now();
// The pool's threads open the mesh while this one does (a failure of either ends the process).
const opening = workers > 1 ? openNodePool(core.stage1Input(mesh, options), options, { workers }) : null;
const surface = core.openRefinedSurface(mesh);
const pool = await opening;
let skeleton;
let stage1Seconds = 0;
/** On a pool: the time this thread spent drawing and accepting, beside the workers (serial only while they wait for it). */
let serialSeconds = 0;
const timed = <T extends object>(target: T, names: readonly string[]): T =>
  new Proxy(target, {
    get(object, name, receiver) {
      const value = Reflect.get(object, name, receiver) as unknown;
      if (typeof value !== 'function') return value;
      if (!names.includes(String(name))) return value.bind(object);
      return (...args: unknown[]) => {
        const t = performance.now();
        try {
          return value.apply(object, args);
        } finally {
          serialSeconds += (performance.now() - t) / 1000;
        }
      };
    },
  });
try {
  const threads = pool?.workers ?? [];
  const pipeline = surface.pipeline(options);
  try {
    const stage1 = performance.now();
    await runStage1(threads.length ? timed(pipeline, ['draw', 'accept']) : pipeline, threads);
    stage1Seconds = (performance.now() - stage1) / 1000;
    skeleton = pipeline.finish();
  } finally {
    pipeline.dispose();
  }
} finally {
  surface.dispose();
  await pool?.close();
}
const seconds = (performance.now() - started) / 1000;

await writeFile(outPath, writeSkeletonJson(skeleton, { mesh: meshPath, options }));
process.stdout.write(`${JSON.stringify({ seconds, stage1Seconds, serialSeconds, memoryMB: core.memoryMB() })}\n`);
