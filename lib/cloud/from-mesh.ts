/**
 * A mesh run as a point cloud, by choice (issue 15: "a mesh can also be run as a point cloud (its
 * vertices), to compare CSCD-M and CSCD-PC on the same shape"): the vertices its faces use, with the
 * area-weighted normals of those faces, as the shared clean clouds carry their mesh's face normals.
 * A vertex whose faces' normals cancel out has none, and then no point has one (a cloud has normals for
 * every point or for none): the core takes PCA normals instead.
 */
import type { CloudArrays, MeshArrays } from '../core/types.ts';

/** The choice, declared once: the page's checkbox and the worker's open request use the key, the CLI the flag. */
export const AS_CLOUD = Object.freeze({
  key: 'asCloud',
  flag: 'as-cloud',
  help: 'run a mesh as a point cloud: its vertices (those of its faces) with their area-weighted face normals, through CSCD-PC',
});

/**
 * The cloud of a mesh's vertices, the point each vertex became (-1: a vertex of no face, left out), and
 * what was done, in a sentence for the notes.
 */
export function meshAsCloud(mesh: MeshArrays): { cloud: CloudArrays; pointOfVertex: Int32Array; note: string } {
  const vertexCount = mesh.positions.length / 3;
  const { positions: x, triangles } = mesh;
  // Twice each face's area times its unit normal, summed at its corners.
  const sums = new Float64Array(3 * vertexCount);
  const used = new Uint8Array(vertexCount);
  for (let f = 0; f < triangles.length; f += 3) {
    const [a, b, c] = [triangles[f], triangles[f + 1], triangles[f + 2]];
    const u = [0, 1, 2].map((k) => x[3 * b + k] - x[3 * a + k]), v = [0, 1, 2].map((k) => x[3 * c + k] - x[3 * a + k]);
    const normal = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    for (const corner of [a, b, c]) {
      used[corner] = 1;
      for (let k = 0; k < 3; k++) sums[3 * corner + k] += normal[k];
    }
  }
  const pointOfVertex = new Int32Array(vertexCount).fill(-1);
  let points = 0;
  for (let v = 0; v < vertexCount; v++) if (used[v]) pointOfVertex[v] = points++;
  const positions = new Float64Array(3 * points);
  let normals: Float32Array | null = new Float32Array(3 * points);
  for (let v = 0; v < vertexCount; v++) {
    const p = pointOfVertex[v];
    if (p < 0) continue;
    positions.set(x.subarray(3 * v, 3 * v + 3), 3 * p);
    const length = Math.hypot(sums[3 * v], sums[3 * v + 1], sums[3 * v + 2]);
    if (normals && length > 0 && Number.isFinite(length)) normals.set([sums[3 * v] / length, sums[3 * v + 1] / length, sums[3 * v + 2] / length], 3 * p);
    else normals = null;
  }
  const leftOut = vertexCount - points;
  const note = `the mesh runs as a point cloud: its ${points} vertices${leftOut ? ` (${leftOut} used by no face left out)` : ''}, ${normals ? 'with their faces’ normals' : 'without normals (faces whose normals cancel out at a vertex)'}`;
  return { cloud: { positions, normals }, pointOfVertex, note };
}
