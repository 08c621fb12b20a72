/**
 * Refinement of coarse meshes by midpoint subdivision, so that a mesh of a few dozen faces gets a
 * skeleton: CSCD-M samples the surface at its vertices (sources, cut locus, loops shortened along
 * edges, pruning by mean edge length), and a genus-3 mesh of 100 faces has too few of them for any
 * loop to survive. Pure TypeScript (CLI, worker, tests).
 *
 * Every edge is split at its midpoint and every triangle into four, so the new vertices lie on the
 * piecewise-flat input: the surface is exactly the same, only sampled more densely (the paper's
 * multiscale point: the intrinsic triangulation makes CSCD-M independent of the meshing). The input's
 * vertices keep their indices 0..V-1 and new vertices follow in a fixed order, so per-vertex results
 * of the input are the first V entries of those of the refined mesh. See docs/refine.md.
 */
import type { MeshArrays, MeshFacts, Refinement, Simplification, Skeleton } from '../core/types.ts';

// Both are shares of the bounding-box diagonal taken by the mean edge length (scale-free, in the
// facts of every mesh), measured in docs/refine.md. The 26 shared meshes, which all get right
// skeletons as they are, lie at 0.0039-0.0374 (two_torus, 1,536 faces, the coarsest; median 0.010);
// decimated to 1,000 faces, fertility_9k (0.0529) already loses cycles; at 50-300 faces, dtorus,
// two_torus, fertility_9k, bob, torus and elephant_small lie at 0.080-0.253 and lose nearly everything.

/** A mesh is refined when its mean edge length exceeds this share of its bounding-box diagonal: 1.20x two_torus, 1/1.18 of fertility_9k at 1,000 faces. */
export const REFINE_ABOVE = 0.045;

/**
 * ... and then until it is at most this share, about the shared meshes' median: at 0.032 or less
 * every decimated mesh above but elephant_small has cycles = genus; its small handles need 0.011.
 */
export const REFINE_TO = 0.0125;

/** Refinement never goes beyond this many faces (each level multiplies them by 4): opening the solver stays under a second. */
export const REFINE_FACE_CAP = 50_000;

/**
 * What refining `facts`' mesh for computation does, or null when it is used as it is: it is fine
 * enough, or not an oriented manifold (the core then refuses it with the input's face and vertex numbers).
 */
export function refinementOf(facts: MeshFacts): Refinement | null {
  if (!facts.manifold || !facts.consistentlyOriented || !(facts.bboxDiagonal > 0)) return null;
  // Each level halves every edge (so the mean edge length exactly, on a closed mesh) and quadruples the faces.
  let ratio = facts.meanEdgeLength / facts.bboxDiagonal;
  if (ratio <= REFINE_ABOVE) return null;
  let levels = 0;
  while (ratio > REFINE_TO && facts.faces * 4 ** (levels + 1) <= REFINE_FACE_CAP) {
    ratio /= 2;
    levels++;
  }
  return levels === 0 ? null : { fromVertices: facts.vertices, fromFaces: facts.faces, toFaces: facts.faces * 4 ** levels, levels };
}

/**
 * A skeleton computed on the mesh `refined` made, for the mesh as given: `vertexToNode` cut to its
 * vertices (the refined mesh's first ones), `stats.refined` set, and `stats.simplified` (how stage 1's
 * copy was made, lib/mesh/simplify.ts).
 */
export function skeletonForInput(skeleton: Skeleton, refined: Refinement | null, simplified: Simplification | null = null): Skeleton {
  const vertexToNode = refined ? skeleton.vertexToNode.slice(0, refined.fromVertices) : skeleton.vertexToNode;
  return { ...skeleton, vertexToNode, stats: { ...skeleton.stats, refined, simplified } };
}

/**
 * One level of midpoint subdivision: every edge split at its midpoint, face f replaced by faces
 * 4f..4f+3 (the corner triangles at its first, second and third corner, then the middle one), all
 * oriented as f. Vertex i of the input is vertex i of the result; the midpoints follow in the order
 * their edges are first met, face by face and corner by corner. Boundary edges get a midpoint too.
 */
export function subdivide(mesh: MeshArrays): { positions: Float64Array; triangles: Uint32Array } {
  const vertices = mesh.positions.length / 3;
  const faces = mesh.triangles.length / 3;
  const t = mesh.triangles;
  // Midpoint of each undirected edge, by its smaller endpoint then the larger one.
  const midpoint = new Map<number, number>();
  const corners = new Uint32Array(3 * faces); // midpoints of edges (0,1), (1,2), (2,0) of each face
  let next = vertices;
  for (let f = 0; f < faces; f++) {
    for (let k = 0; k < 3; k++) {
      const a = t[3 * f + k], b = t[3 * f + ((k + 1) % 3)];
      const key = Math.min(a, b) * vertices + Math.max(a, b);
      let m = midpoint.get(key);
      if (m === undefined) {
        m = next++;
        midpoint.set(key, m);
      }
      corners[3 * f + k] = m;
    }
  }
  const positions = new Float64Array(3 * next);
  positions.set(mesh.positions);
  for (const [key, m] of midpoint) {
    const a = Math.floor(key / vertices), b = key - a * vertices;
    for (let c = 0; c < 3; c++) positions[3 * m + c] = (mesh.positions[3 * a + c] + mesh.positions[3 * b + c]) / 2;
  }
  const triangles = new Uint32Array(12 * faces);
  for (let f = 0; f < faces; f++) {
    const a = t[3 * f], b = t[3 * f + 1], c = t[3 * f + 2];
    const ab = corners[3 * f], bc = corners[3 * f + 1], ca = corners[3 * f + 2];
    triangles.set([a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca], 12 * f);
  }
  return { positions, triangles };
}

/** `levels` rounds of subdivide (the mesh itself for 0). */
export function refine(mesh: MeshArrays, levels: number): MeshArrays {
  let result = mesh;
  for (let level = 0; level < levels; level++) result = subdivide(result);
  return result;
}

/**
 * Where a point of face `face` (barycentric coordinates on its corners) lies on the mesh refined
 * `levels` times: the child face holding it and its barycentric coordinates there.
 */
export function refinedPoint(face: number, [w0, w1, w2]: [number, number, number], levels: number): { face: number; barycentric: [number, number, number] } {
  for (let level = 0; level < levels; level++) {
    if (w0 >= 0.5) [face, w0, w1, w2] = [4 * face, 2 * w0 - 1, 2 * w1, 2 * w2];
    else if (w1 >= 0.5) [face, w0, w1, w2] = [4 * face + 1, 2 * w0, 2 * w1 - 1, 2 * w2];
    else if (w2 >= 0.5) [face, w0, w1, w2] = [4 * face + 2, 2 * w0, 2 * w1, 2 * w2 - 1];
    // The middle face (ab, bc, ca).
    else [face, w0, w1, w2] = [4 * face + 3, 1 - 2 * w2, 1 - 2 * w0, 1 - 2 * w1];
  }
  return { face, barycentric: [w0, w1, w2] };
}
