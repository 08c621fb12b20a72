// What must not move when the draw of sources changes, over many seeds: the cycles of meshes of genus
// ≥ 1 (cycles = genus) and the ground-truth tips of the synthetic shapes (a tip is missed without a
// skeleton leaf of its own within 1% of the diagonal; the tip gap is its distance to the skeleton), as
// bench/run.ts scores them. Each run is `cscd skeleton` in a process of its own, with the flags after --.
//
//   node --import tsx scripts/seed-sweep.ts [--seeds 8] [meshes...] [-- cscd skeleton flags, e.g. --draw-ahead 4]
//
// Default meshes: the six of genus ≥ 1 and the four synthetic shapes of docs/parallel.md's table.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { leafIndices, tipGap } from '../bench/metrics.ts';
import { loadCoreNode } from '../lib/core/node.ts';
import { parseMesh } from '../lib/io/index.ts';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const data = path.resolve(repoRoot, '..', 'shared', 'data');
const DEFAULT_MESHES = ['dtorus', 'bob', 'fertility_9k', 'elephant_small', 'two_torus', 'hanger', 'star8_coarse', 'tree_coarse', 'star8', 'tree'];
/** Ground-truth leaves that are not tips (bench/run.ts): the top of star8's body, the base of tree's trunk. */
const NOT_TIPS: Record<string, number[]> = { star8: [0], star8_coarse: [0], tree: [0], tree_coarse: [0] };

const dash = process.argv.indexOf('--');
const flags = dash < 0 ? [] : process.argv.slice(dash + 1);
const { positionals, values } = parseArgs({
  args: process.argv.slice(2, dash < 0 ? undefined : dash),
  allowPositionals: true,
  options: { seeds: { type: 'string', default: '8' } },
});
const seeds = Number(values.seeds);
const meshFile = (name: string) => [path.join(data, 'meshes', `${name}.ply`), path.join(data, 'synthetic', `${name}.ply`)].find((f) => existsSync(f));

const core = await loadCoreNode();
const scratch = mkdtempSync(path.join(os.tmpdir(), 'seed-sweep-'));
process.stdout.write(`Seeds 1-${seeds}, \`cscd skeleton${flags.length ? ` ${flags.join(' ')}` : ''}\`\n\n`);
process.stdout.write('| mesh | cycles = genus | tips missed | mean tip gap, % of the diagonal | mean N |\n| --- | ---: | ---: | ---: | ---: |\n');
try {
  for (const name of positionals.length ? positionals : DEFAULT_MESHES) {
    const file = meshFile(name);
    if (!file) throw new Error(`${name}: not in ${data}/meshes or synthetic`);
    const facts = core.inspect(parseMesh(readFileSync(file), file));
    const gtFile = path.join(path.dirname(file), `${name}__GT.json`);
    const gt = existsSync(gtFile) ? (JSON.parse(readFileSync(gtFile, 'utf8')) as { nodes: number[][]; edges: number[][] }) : null;
    const tips = gt ? leafIndices(gt.nodes.length, gt.edges.flat(), NOT_TIPS[name] ?? []).map((i) => gt.nodes[i]) : [];
    let rightCycles = 0, missed = 0, gapSum = 0, sources = 0;
    for (let seed = 1; seed <= seeds; seed++) {
      const out = path.join(scratch, `${name}-${seed}.json`);
      execFileSync(process.execPath, [path.join(repoRoot, 'cli', 'cscd.mjs'), 'skeleton', file, '--seed', String(seed), ...flags, '--out', out], { stdio: 'ignore' });
      const skeleton = JSON.parse(readFileSync(out, 'utf8')) as { nodes: number[][]; edges: number[][]; stats: { cycles: number; n: number } };
      if (skeleton.stats.cycles === facts.genus) rightCycles++;
      sources += skeleton.stats.n;
      const gap = tipGap(tips, { nodes: skeleton.nodes.flat(), edges: skeleton.edges.flat() }, facts.bboxDiagonal);
      if (gap) {
        missed += tips.length - gap.ownLeaves;
        gapSum += 100 * gap.mean;
      }
    }
    const tipCells = tips.length ? `${missed} of ${tips.length * seeds} | ${(gapSum / seeds).toFixed(3)}` : ' | ';
    process.stdout.write(`| ${name} | ${rightCycles} of ${seeds} (genus ${facts.genus}) | ${tipCells} | ${Math.round(sources / seeds)} |\n`);
  }
} finally {
  rmSync(scratch, { recursive: true, force: true });
}
