// Shapes made here, outside the shared data set, so that a change tuned to the shared meshes shows:
// an ellipsoid (a blob), a flattened torus, a bent, a tapered and a twisted flat capsule. Prints the
// reconstruction error (radii from the mesh, as the bench scores), the cycles against the genus and the
// node count of each default skeleton.
//
//   node --import tsx scripts/made-shapes.ts
import { loadCoreNode } from '../lib/core/node.ts';
import type { MeshArrays } from '../lib/core/types.ts';
import { capsule, icosphere, torus } from '../tests/unit/support/meshes.ts';
/** The mesh with every vertex moved by f (f must keep the orientation: no reflection). */
const map = (m: MeshArrays, f: (x: number, y: number, z: number) => [number, number, number]): MeshArrays => {
  const p = Float64Array.from(m.positions);
  for (let i = 0; i < p.length; i += 3) [p[i], p[i + 1], p[i + 2]] = f(p[i], p[i + 1], p[i + 2]);
  return { positions: p, triangles: m.triangles };
};
const shapes: [string, MeshArrays, number][] = [
  ['ellipsoid 3:1.5:1', map(icosphere(4), (x, y, z) => [3 * x, 1.5 * y, z]), 0],
  ['flat torus (tube 1:0.35)', map(torus(3, 1, 96, 32), (x, y, z) => [x, y, 0.35 * z]), 1],
  ['bent capsule', map(capsule(6, 0.6, 32), (x, y, z) => { const a = x / 4; return [(4 - y) * Math.sin(a), 4 - (4 - y) * Math.cos(a), z]; }), 0],
  ['tapered capsule', map(capsule(6, 0.8, 32), (x, y, z) => { const s = 1 - 0.08 * (x + 3); return [x, s * y, s * z]; }), 0],
  ['twisted flat bar', map(capsule(8, 0.8, 32), (x, y, z) => { const a = 0.3 * x; const yy = y, zz = 0.3 * z; return [x, yy * Math.cos(a) - zz * Math.sin(a), yy * Math.sin(a) + zz * Math.cos(a)]; }), 0],
];
const core = await loadCoreNode();
for (const [name, mesh, genus] of shapes) {
  const surface = core.openRefinedSurface(mesh);
  const sk = surface.skeleton({});
  surface.dispose();
  const e = core.evaluate(mesh, { nodes: sk.nodes, edges: sk.edges, radii: null });
  console.log(`${name.padEnd(26)} error ${e.reconError.toPrecision(3)} cycles ${e.cycles}/${genus} nodes ${sk.nodes.length / 3}`);
}
