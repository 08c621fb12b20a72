// A point cloud of a mesh scanned in parallel lines, as a scanner that sweeps a sheet of light across a
// shape sees it: the mesh's intersections with planes across one axis, `--gap` percent of the
// bounding-box diagonal apart (the first at a distance drawn from the seed), and points along them at
// random, one per `--step` percent on average. For the scan-line measurements of docs/pointcloud.md
// ("Scan lines"):
//
//   node --import tsx scripts/slice-cloud.ts MESH OUT.ply [--axis x|y|z] [--gap 1] [--step 0.1] [--seed 1]
//
// Binary little-endian PLY, float32 x y z, no normals.
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { random } from '../lib/core/random.ts';
import { parseShape } from '../lib/io/index.ts';
import { boundingBoxDiagonal } from '../lib/io/repair.ts';
import { cloudPly } from '../tests/unit/support/clouds.ts';

const { values, positionals } = parseArgs({
  allowPositionals: true,
  options: {
    axis: { type: 'string', default: 'z' },
    gap: { type: 'string', default: '1' },
    step: { type: 'string', default: '0.1' },
    seed: { type: 'string', default: '1' },
  },
});
const [meshFile, outFile] = positionals;
const axis = 'xyz'.indexOf(values.axis), gapPercent = Number(values.gap), stepPercent = Number(values.step), seed = Number(values.seed);
if (!meshFile || !outFile || axis < 0 || values.axis.length !== 1 || !(gapPercent > 0) || !(stepPercent > 0) || !Number.isInteger(seed)) {
  console.error('usage: slice-cloud.ts MESH OUT.ply [--axis x|y|z] [--gap PERCENT] [--step PERCENT] [--seed S]');
  process.exit(2);
}
const mesh = parseShape(new Uint8Array(readFileSync(meshFile)), path.basename(meshFile));
if (mesh.kind !== 'mesh') throw new Error(`${meshFile} holds no triangles`);
const { positions: p, triangles: t } = mesh;
const diagonal = boundingBoxDiagonal(Float64Array.from(p));
const gap = (gapPercent / 100) * diagonal, step = (stepPercent / 100) * diagonal;

let low = Infinity, high = -Infinity;
for (let v = axis; v < p.length; v += 3) low = Math.min(low, p[v]), high = Math.max(high, p[v]);
const next = random(seed);
const points: number[][] = [];
for (let level = low + next() * gap; level < high; level += gap) {
  for (let f = 0; f < t.length / 3; f++) {
    // Where the plane crosses the triangle's edges: two points on a triangle it cuts.
    const ends: number[][] = [];
    for (let k = 0; k < 3; k++) {
      const a = 3 * t[3 * f + k], b = 3 * t[3 * f + ((k + 1) % 3)];
      const da = p[a + axis] - level, db = p[b + axis] - level;
      if (da * db >= 0) continue;
      const u = da / (da - db);
      ends.push([0, 1, 2].map((c) => p[a + c] + u * (p[b + c] - p[a + c])));
    }
    if (ends.length !== 2) continue;
    const [e0, e1] = ends;
    const length = Math.hypot(e1[0] - e0[0], e1[1] - e0[1], e1[2] - e0[2]);
    // length / step points on average: its whole part, and one more with the chance of its fraction.
    const count = Math.floor(length / step + next());
    for (let i = 0; i < count; i++) {
      const u = next();
      points.push([0, 1, 2].map((c) => e0[c] + u * (e1[c] - e0[c])));
    }
  }
}
writeFileSync(outFile, cloudPly(points, null, 'binary_little_endian', 'float', `${path.basename(meshFile)} sliced across ${values.axis} every ${gapPercent}% of the diagonal, a point every ${stepPercent}% along, seed ${seed}`));
console.log(`${outFile}: ${points.length} points on planes ${gap.toPrecision(3)} apart`);
