// A point cloud with stray points added, as a scan's outliers, for measuring what they do to a skeleton
// and what the checks on load remove (lib/cloud/outliers.ts; docs/pointcloud.md, "Stray points"):
//
//   node --import tsx scripts/add-strays.ts CLOUD OUT.ply [--count 100] [--where box|near] [--seed 1]
//
// box: drawn uniformly over the cloud's bounding box grown by 10% of its size on each side; near: each a
// point of the cloud drawn at random, moved by isotropic Gaussian noise of 3% of the diagonal. The cloud's
// points come first, as they were, without normals (a stray has none), the strays after them; binary
// little-endian PLY, float32 x y z. Strays that the checks would merge as duplicates are not avoided.
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { gaussian, random } from '../lib/core/random.ts';
import { parseShape } from '../lib/io/index.ts';
import { boundingBoxDiagonal } from '../lib/io/repair.ts';
import { cloudPly } from '../tests/unit/support/clouds.ts';

/** The share of the diagonal by which `near` strays are moved (the deviation of their Gaussian). */
const NEAR_DEVIATION = 0.03;
/** How far the box strays are drawn beyond the bounding box, as a share of its size along each axis. */
const BOX_MARGIN = 0.1;

const { values, positionals } = parseArgs({
  allowPositionals: true,
  options: { count: { type: 'string', default: '100' }, where: { type: 'string', default: 'box' }, seed: { type: 'string', default: '1' } },
});
const [cloudFile, outFile] = positionals;
const count = Number(values.count), where = values.where, seed = Number(values.seed);
if (!cloudFile || !outFile || !Number.isInteger(count) || count < 0 || (where !== 'box' && where !== 'near') || !Number.isInteger(seed)) {
  console.error('usage: add-strays.ts CLOUD OUT.ply [--count N] [--where box|near] [--seed S]');
  process.exit(2);
}
const cloud = parseShape(new Uint8Array(readFileSync(cloudFile)), path.basename(cloudFile));
if (cloud.kind !== 'cloud') throw new Error(`${cloudFile} is a mesh, not a point cloud`);
const p = cloud.positions, n = p.length / 3;
const points = Array.from({ length: n }, (_, i) => [p[3 * i], p[3 * i + 1], p[3 * i + 2]]);

const low = [Infinity, Infinity, Infinity], high = [-Infinity, -Infinity, -Infinity];
for (const q of points) {
  for (let k = 0; k < 3; k++) {
    low[k] = Math.min(low[k], q[k]);
    high[k] = Math.max(high[k], q[k]);
  }
}
const sigma = NEAR_DEVIATION * boundingBoxDiagonal(p);
const next = random(seed);
for (let j = 0; j < count; j++) {
  if (where === 'box') {
    points.push([0, 1, 2].map((k) => low[k] + (high[k] - low[k]) * ((1 + 2 * BOX_MARGIN) * next() - BOX_MARGIN)));
  } else {
    const from = points[Math.floor(next() * n)];
    points.push(from.map((x) => x + sigma * gaussian(next)));
  }
}
const comment = `${path.basename(cloudFile)} and ${count} stray points (${where}) by scripts/add-strays.ts, seed ${seed}`;
writeFileSync(outFile, cloudPly(points, null, 'binary_little_endian', 'float', comment));
console.log(`${path.basename(outFile)}: ${n} points and ${count} strays (${where})`);
