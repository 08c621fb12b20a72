// A core's peak memory (Core.memoryMB) per mesh, for the rule that sizes the page's pool
// (lib/core/pool-size.ts, docs/parallel.md): each mesh in a fresh core, the skeleton's
// (n sources, drawAhead of them drawn ahead, then stage 2) and a pool worker's (the surface opened and the
// separators of the same sources, nothing kept), with the vertices of the mesh computed on (refined).
//
//   node --import tsx scripts/core-memory.ts [--n 12] [--draw-ahead 4] mesh.ply...
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { loadCoreNode } from '../lib/core/node.ts';
import { defaultOptions } from '../lib/core/options.ts';
import { parseMesh } from '../lib/io/index.ts';
import { refine } from '../lib/mesh/refine.ts';

const { positionals, values } = parseArgs({ allowPositionals: true, options: { n: { type: 'string', default: '12' }, 'draw-ahead': { type: 'string', default: '4' } } });
const options = { ...defaultOptions, n: values.n === 'auto' ? ('auto' as const) : Number(values.n), drawAhead: Number(values['draw-ahead']) };
process.stdout.write('| mesh | vertices computed on | skeleton core, MB | pool worker core, MB |\n| --- | ---: | ---: | ---: |\n');
for (const file of positionals) {
  const mesh = parseMesh(readFileSync(file), file);
  const whole = await loadCoreNode();
  const surface = whole.openRefinedSurface(mesh);
  const vertices = refine(mesh, surface.refined?.levels ?? 0).positions.length / 3;
  const pipeline = surface.pipeline(options);
  const sources: Uint32Array[] = [];
  for (let drawn = pipeline.draw(); drawn.length > 0; drawn = pipeline.draw()) {
    sources.push(drawn);
    if (pipeline.accept(pipeline.separators(drawn)).finished) break;
  }
  pipeline.finish();
  pipeline.dispose();
  surface.dispose();
  const worker = await loadCoreNode();
  const workerPipeline = worker.openRefinedSurface(mesh).pipeline(options);
  for (const drawn of sources) workerPipeline.separators(drawn);
  process.stdout.write(`| ${path.basename(file, '.ply')} | ${vertices} | ${whole.memoryMB()} | ${worker.memoryMB()} |\n`);
}
