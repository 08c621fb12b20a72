/**
 * Multiscale stage 1 (docs/multiscale.md): a mesh with more vertices than the option `stage1Vertices`
 * (lib/core/options.ts) runs stage 1 (sources, cut loci, loops) on a copy simplified to about that
 * many vertices by quadric edge collapse (lib/mesh/decimate.ts: genus, components and boundary loops
 * kept); its separators are mapped back onto the mesh as given, where stage 2 (packing, regions,
 * nodes, radii) and the skeleton's vertexToNode are computed. A separator's cost grows with the vertices (two heat solves, the cut
 * locus and the ridge tree over the whole mesh) while the features it finds are no smaller on the
 * copy. Pure TypeScript (CLI, workers, tests).
 */
import type { MeshArrays, MeshFacts, Simplification } from '../core/types.ts';
import { decimate } from './decimate.ts';
import { refinementOf } from './refine.ts';

/** What stage 1 runs on for `facts`' mesh (as given, never a refined one) with at most `vertices` (0: no limit): a simplified copy, or null (the mesh itself). */
export function simplificationOf(facts: MeshFacts, vertices: number): { fromVertices: number; fromFaces: number; targetFaces: number } | null {
  // A mesh coarse enough to be refined (lib/mesh/refine.ts) is never also simplified.
  if (!facts.manifold || !facts.consistentlyOriented || vertices <= 0 || facts.vertices <= vertices || refinementOf(facts)) return null;
  return { fromVertices: facts.vertices, fromFaces: facts.faces, targetFaces: Math.round((facts.faces * vertices) / facts.vertices) };
}

const made = new WeakMap<MeshArrays, Map<number, { mesh: MeshArrays; simplified: Simplification }>>();

/**
 * The mesh stage 1 runs on for the option `stage1Vertices` and how it was made, or null when it is
 * `mesh` itself (`mesh` as given, its facts). Made once per mesh and limit (Core.stage1Input makes it
 * for a pool's threads, and the caller's pipeline then takes the same copy); deterministic.
 */
export function stage1Mesh(mesh: MeshArrays, facts: MeshFacts, stage1Vertices: number): { mesh: MeshArrays; simplified: Simplification } | null {
  const plan = simplificationOf(facts, stage1Vertices);
  if (!plan) return null;
  const byLimit = made.get(mesh) ?? new Map<number, { mesh: MeshArrays; simplified: Simplification }>();
  made.set(mesh, byLimit);
  let result = byLimit.get(stage1Vertices);
  if (!result) {
    const copy = decimate(mesh, plan.targetFaces);
    const simplified = { fromVertices: plan.fromVertices, fromFaces: plan.fromFaces, toVertices: copy.positions.length / 3, toFaces: copy.triangles.length / 3 };
    result = { mesh: copy, simplified };
    byLimit.set(stage1Vertices, result);
  }
  return result;
}
