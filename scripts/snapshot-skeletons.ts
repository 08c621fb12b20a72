// Behaviour that a change must not alter, checked: the skeleton JSON of shared meshes at a fixed n,
// timings taken out, written to a folder; two folders compared file by file.
//
//   node --import tsx scripts/snapshot-skeletons.ts write <folder> [--n 40] [--set option=value ...] [meshes...]
//   node --import tsx scripts/snapshot-skeletons.ts compare <before> <after>
//
// Default meshes: every ../shared/data/meshes/*.ply and ../shared/data/synthetic/*.ply. Write the
// snapshot before a change (e.g. from a worktree of the previous commit) and after it; `compare` prints
// one line per mesh (same, differs, missing) and exits 1 unless all are the same.
import { existsSync, mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { loadCoreNode } from '../lib/core/node.ts';
import { defaultOptions, MESH_OPTIONS, optionsFromPairs } from '../lib/core/options.ts';
import type { Options } from '../lib/core/types.ts';
import { parseMesh } from '../lib/io/index.ts';
import { writeSkeletonJson } from '../lib/io/skeleton.ts';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const folders = ['meshes', 'synthetic'].map((f) => path.resolve(repoRoot, '..', 'shared', 'data', f));

const { positionals, values } = parseArgs({
  allowPositionals: true,
  options: { n: { type: 'string', default: '40' }, set: { type: 'string', multiple: true, default: [] } },
});
/** --set drawAhead=1 and the like: any option of a mesh. */
const overrides = optionsFromPairs(values.set, MESH_OPTIONS) as Partial<Options>;
const [command, ...rest] = positionals;

if (command === 'write') {
  const [out, ...names] = rest;
  if (!out) throw new Error('usage: snapshot-skeletons.ts write <folder> [--n 40] [meshes...]');
  const n = Number(values.n);
  mkdirSync(out, { recursive: true });
  const files = folders.flatMap((folder) => readdirSync(folder).filter((f) => f.endsWith('.ply')).map((f) => path.join(folder, f)));
  const core = await loadCoreNode();
  for (const file of files.filter((f) => !names.length || names.some((m) => path.basename(f) === m || path.basename(f) === `${m}.ply`))) {
    const mesh = parseMesh(readFileSync(file), file);
    const surface = core.openRefinedSurface(mesh);
    try {
      const skeleton = surface.skeleton({ ...overrides, n });
      skeleton.stats.timings = {};
      writeFileSync(path.join(out, `${path.basename(file)}.json`), writeSkeletonJson(skeleton, { mesh: path.basename(file), options: { ...defaultOptions, ...overrides, n } }));
      process.stdout.write(`wrote ${path.basename(file)}\n`);
    } finally {
      surface.dispose();
    }
  }
} else if (command === 'compare') {
  const [before, after] = rest;
  if (!before || !after) throw new Error('usage: snapshot-skeletons.ts compare <before> <after>');
  const names = [...new Set([...readdirSync(before), ...readdirSync(after)])].sort();
  let differing = 0;
  for (const name of names) {
    const [a, b] = [path.join(before, name), path.join(after, name)];
    const state = !existsSync(a) || !existsSync(b) ? 'missing' : readFileSync(a).equals(readFileSync(b)) ? 'same' : 'differs';
    if (state !== 'same') differing++;
    process.stdout.write(`${state.padEnd(8)} ${name}\n`);
  }
  process.stdout.write(`${names.length - differing} of ${names.length} the same\n`);
  process.exit(differing ? 1 : 0);
} else {
  throw new Error('usage: snapshot-skeletons.ts write <folder> [--n 40] [meshes...] | compare <before> <after>');
}
