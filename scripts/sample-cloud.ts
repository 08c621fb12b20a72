// A point cloud sampled from a mesh, as the shared clouds were (../shared/data/MANIFEST.md): points spread
// evenly over the surface with the normals of their triangles, or with isotropic Gaussian noise of a
// share of the bounding-box diagonal and no normals. For clouds outside the shared set, so that a change
// tuned to the shared clouds shows (docs/pointcloud.md, "Clouds from other meshes"):
//
//   node --import tsx scripts/sample-cloud.ts MESH OUT.ply [--points 20000] [--noise PERCENT] [--seed 1]
//
// Even spread: three times the points drawn uniformly by area, then thinned Poisson-disk style to the
// count (lib/cloud/subsample.ts), in place of trimesh's sample_surface_even. Binary little-endian PLY,
// float32 x y z (+ nx ny nz without noise).
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { subsampleCloud } from '../lib/cloud/subsample.ts';
import { gaussian, random } from '../lib/core/random.ts';
import { parseShape } from '../lib/io/index.ts';
import { boundingBoxDiagonal } from '../lib/io/repair.ts';
import { cloudPly } from '../tests/unit/support/clouds.ts';

const { values, positionals } = parseArgs({
  allowPositionals: true,
  options: { points: { type: 'string', default: '20000' }, noise: { type: 'string', default: '0' }, seed: { type: 'string', default: '1' } },
});
const [meshFile, outFile] = positionals;
const pointCount = Number(values.points), noisePercent = Number(values.noise), seed = Number(values.seed);
if (!meshFile || !outFile || !(pointCount > 0) || !(noisePercent >= 0) || !Number.isInteger(seed)) {
  console.error('usage: sample-cloud.ts MESH OUT.ply [--points N] [--noise PERCENT] [--seed S]');
  process.exit(2);
}
const mesh = parseShape(new Uint8Array(readFileSync(meshFile)), path.basename(meshFile));
if (mesh.kind !== 'mesh') throw new Error(`${meshFile} holds no triangles`);
const { positions: p, triangles: t } = mesh;

// Each triangle's unit normal and its share of the area, summed for drawing by area.
const faces = t.length / 3;
const cumulativeArea = new Float64Array(faces), normal = new Float64Array(3 * faces);
let area = 0;
for (let f = 0; f < faces; f++) {
  const [a, b, c] = [3 * t[3 * f], 3 * t[3 * f + 1], 3 * t[3 * f + 2]];
  const u = [p[b] - p[a], p[b + 1] - p[a + 1], p[b + 2] - p[a + 2]], v = [p[c] - p[a], p[c + 1] - p[a + 1], p[c + 2] - p[a + 2]];
  const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
  const twiceArea = Math.hypot(n[0], n[1], n[2]);
  area += twiceArea / 2;
  cumulativeArea[f] = area;
  if (twiceArea > 0) for (let k = 0; k < 3; k++) normal[3 * f + k] = n[k] / twiceArea;
}

const next = random(seed);
const drawn = 3 * pointCount;
const positions = new Float64Array(3 * drawn), normals = new Float32Array(3 * drawn);
for (let i = 0; i < drawn; i++) {
  const at = next() * area;
  let lo = 0, hi = faces - 1;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (cumulativeArea[mid] < at) lo = mid + 1;
    else hi = mid;
  }
  let s = next(), r = next();
  if (s + r > 1) [s, r] = [1 - s, 1 - r];
  const [a, b, c] = [3 * t[3 * lo], 3 * t[3 * lo + 1], 3 * t[3 * lo + 2]];
  for (let k = 0; k < 3; k++) {
    positions[3 * i + k] = p[a + k] + s * (p[b + k] - p[a + k]) + r * (p[c + k] - p[a + k]);
    normals[3 * i + k] = normal[3 * lo + k];
  }
}
const cloud = subsampleCloud({ positions, normals }, pointCount, seed);

const count = cloud.positions.length / 3, withNormals = noisePercent === 0;
const sigma = (noisePercent / 100) * boundingBoxDiagonal(cloud.positions);
const triple = (values: ArrayLike<number>, i: number) => [values[3 * i], values[3 * i + 1], values[3 * i + 2]];
const points = Array.from({ length: count }, (_, i) => triple(cloud.positions, i).map((x) => (withNormals ? x : x + sigma * gaussian(next))));
const pointNormals = withNormals ? Array.from({ length: count }, (_, i) => triple(cloud.normals!, i)) : null;
const comment = `sampled from ${path.basename(meshFile)} by scripts/sample-cloud.ts, seed ${seed}, noise ${noisePercent}%`;
writeFileSync(outFile, cloudPly(points, pointNormals, 'binary_little_endian', 'float', comment));
console.log(`${path.basename(outFile)}: ${count} points${withNormals ? ' with normals' : `, noise ${noisePercent}% of the diagonal`}`);
