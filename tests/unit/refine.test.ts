// Refinement of coarse meshes (lib/mesh/refine.ts): midpoint subdivision keeps the surface, its
// topology and the input's vertices; the criterion leaves every shared mesh as it is and refines
// decimated ones; through openRefinedSurface (what the CLI, the bench and the page use) a decimated
// genus-2 and genus-4 mesh of a few hundred faces get a skeleton with cycles = genus, inside the shape.
import { readdirSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { CoreError, loadCoreNode, type Core, type MeshArrays } from '../../lib/core/node.ts';
import { decimate } from '../../lib/mesh/decimate.ts';
import { REFINE_ABOVE, REFINE_FACE_CAP, REFINE_TO, refine, refinedPoint, refinementOf, subdivide } from '../../lib/mesh/refine.ts';
import { windingNumber } from '../../lib/mesh/winding.ts';
import { readMesh } from './support/meshes.ts';
import { point } from './support/skeletons.ts';
import { sharedData, sharedMesh } from '../paths.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

function area(mesh: MeshArrays): number {
  let total = 0;
  for (let f = 0; f < mesh.triangles.length / 3; f++) {
    const [a, b, c] = [0, 1, 2].map((k) => point(mesh.positions, mesh.triangles[3 * f + k]));
    const u = [0, 1, 2].map((k) => b[k] - a[k]), v = [0, 1, 2].map((k) => c[k] - a[k]);
    total += Math.hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]) / 2;
  }
  return total;
}

/** The point with barycentric coordinates w on face f. */
function at(mesh: MeshArrays, f: number, w: number[]): number[] {
  const corners = [0, 1, 2].map((k) => point(mesh.positions, mesh.triangles[3 * f + k]));
  return [0, 1, 2].map((c) => w[0] * corners[0][c] + w[1] * corners[1][c] + w[2] * corners[2][c]);
}

const TOPOLOGY = ['genus', 'components', 'boundaryLoops', 'eulerCharacteristic', 'manifold', 'consistentlyOriented', 'bboxMin', 'bboxMax'] as const;

describe('subdivide', () => {
  const CASES = [
    { file: 'two_torus.ply', levels: 2, what: 'closed, genus 2' },
    { file: 'torus_two_holes_open.ply', levels: 1, what: 'open, three boundary loops' },
    { file: 'rings.ply', levels: 1, what: 'three components' },
  ];
  for (const { file, levels, what } of CASES) {
    it(`keeps the surface of ${file} (${what}), its topology and its vertices, ${levels} level(s)`, () => {
      const mesh = readMesh(sharedMesh(file));
      const before = core.inspect(mesh);
      const result = refine(mesh, levels);
      const after = core.inspect(result);
      expect(after.faces).toBe(before.faces * 4 ** levels);
      for (const key of TOPOLOGY) expect(after[key], key).toEqual(before[key]);
      expect(after.degenerateFaces).toBe(0);
      expect(area(result)).toBeCloseTo(area(mesh), 9 - Math.ceil(Math.log10(area(mesh))));
      expect(Array.from(result.positions.subarray(0, mesh.positions.length))).toEqual(Array.from(mesh.positions));
      // Each level halves every edge: the mean exactly on a closed mesh.
      if (before.boundaryLoops === 0) expect(after.meanEdgeLength).toBeCloseTo(before.meanEdgeLength / 2 ** levels, 9);
    });
  }

  it('is deterministic', () => {
    const mesh = readMesh(sharedMesh('two_torus.ply'));
    const a = subdivide(mesh), b = subdivide(mesh);
    expect(b.positions).toEqual(a.positions);
    expect(b.triangles).toEqual(a.triangles);
  });

  it('places a point of an input face at the same place on the refined mesh (refinedPoint)', () => {
    const mesh = readMesh(sharedMesh('two_torus.ply'));
    const refined = refine(mesh, 3);
    const weights = [[1, 0, 0], [0, 0, 1], [0.5, 0.5, 0], [0.2, 0.3, 0.5], [0.05, 0.9, 0.05], [0.4, 0.4, 0.2], [1 / 3, 1 / 3, 1 / 3]];
    for (const f of [0, 17, 1000]) {
      for (const w of weights) {
        const p = refinedPoint(f, w as [number, number, number], 3);
        expect(p.barycentric.every((x) => x >= -1e-12 && x <= 1 + 1e-12)).toBe(true);
        const [x, y, z] = at(refined, p.face, p.barycentric), [x0, y0, z0] = at(mesh, f, w);
        expect(Math.hypot(x - x0, y - y0, z - z0)).toBeLessThan(1e-12);
      }
    }
  });
});

describe('refinementOf', () => {
  it('leaves every shared mesh as it is', () => {
    const files = readdirSync(`${sharedData}/meshes`).filter((f) => f.endsWith('.ply'));
    expect(files.length).toBeGreaterThanOrEqual(26);
    for (const file of files) expect(refinementOf(core.inspect(readMesh(sharedMesh(file)))), file).toBeNull();
  });

  it('refines decimated meshes of 50-300 faces to at most REFINE_TO or the face cap, idempotently', () => {
    for (const file of ['bob.ply', 'elephant_small.ply']) {
      for (const target of [50, 300]) {
        const mesh = decimate(readMesh(sharedMesh(file)), target);
        const facts = core.inspect(mesh);
        expect(facts.meanEdgeLength / facts.bboxDiagonal).toBeGreaterThan(REFINE_ABOVE);
        const refined = refinementOf(facts);
        expect(refined).toMatchObject({ fromVertices: facts.vertices, fromFaces: facts.faces });
        const after = core.inspect(refine(mesh, refined!.levels));
        expect(after.faces).toBe(refined!.toFaces);
        const fine = after.meanEdgeLength / after.bboxDiagonal <= REFINE_TO;
        expect(fine || after.faces * 4 > REFINE_FACE_CAP, `${file} at ${target} faces`).toBe(true);
        expect(after.faces).toBeLessThanOrEqual(REFINE_FACE_CAP);
        expect(refinementOf(after)).toBeNull();
      }
    }
  });

  it('leaves a mesh the core will refuse as it is, so that its error names the input', () => {
    const mesh = readMesh(sharedMesh('two_torus.ply'));
    const coarse = decimate(mesh, 100);
    const facts = core.inspect(coarse);
    expect(refinementOf(facts)).not.toBeNull();
    expect(refinementOf({ ...facts, consistentlyOriented: false })).toBeNull();
    expect(refinementOf({ ...facts, manifold: false })).toBeNull();
  });
});

describe('openRefinedSurface', () => {
  it('answers per vertex of the mesh as given', () => {
    const mesh = decimate(readMesh(sharedMesh('two_torus.ply')), 100);
    const vertices = mesh.positions.length / 3;
    const surface = core.openRefinedSurface(mesh);
    try {
      expect(surface.refined).toEqual(refinementOf(core.inspect(mesh)));
      expect(surface.facts.vertices).toBe(vertices);
      const distance = surface.distanceFromVertex(3);
      expect(distance).toHaveLength(vertices);
      expect(distance[3]).toBeCloseTo(0, 9);
      // A point at corner 0 of face 5 is that vertex: the same distances.
      const corner = mesh.triangles[15];
      const fromPoint = surface.distanceFromPoints([{ face: 5, barycentric: [1, 0, 0] }]);
      const fromVertex = surface.distanceFromVertex(corner);
      for (let v = 0; v < vertices; v++) expect(fromPoint[v]).toBeCloseTo(fromVertex[v], 6);
      const separator = surface.separator(3);
      expect(separator.distance).toHaveLength(vertices);
      expect(separator.cutLocus.laplacian).toHaveLength(vertices);
      expect(separator.refined).toEqual(surface.refined);
      // The refined mesh's own vertices cannot be named.
      expect(() => surface.distanceFromVertex(vertices)).toThrow(CoreError);
    } finally {
      surface.dispose();
    }
  });

  it('opens a shared mesh as it is', () => {
    const surface = core.openRefinedSurface(readMesh(sharedMesh('two_torus.ply')));
    expect(surface.refined).toBeNull();
    surface.dispose();
  });
});

describe('skeletons of coarse meshes', () => {
  const CASES = [
    { file: 'two_torus.ply', faces: 100, genus: 2 },
    { file: 'fertility_9k.ply', faces: 300, genus: 4 },
  ];
  for (const { file, faces, genus } of CASES) {
    it(`of ${file} decimated to ${faces} faces have ${genus} cycles (the genus), nodes inside the shape`, () => {
      const mesh = decimate(readMesh(sharedMesh(file)), faces);
      const surface = core.openRefinedSurface(mesh);
      const skeleton = surface.skeleton({ n: 40, seed: 1 });
      surface.dispose();
      expect(skeleton.stats.refined).toEqual(surface.refined);
      expect(skeleton.stats.refined!.levels).toBeGreaterThan(0);
      expect(skeleton.stats.cycles).toBe(genus);
      expect(skeleton.vertexToNode).toHaveLength(mesh.positions.length / 3);
      const nodeCount = skeleton.radii.length;
      expect(nodeCount).toBeGreaterThan(2 * genus);
      let inside = 0;
      for (let i = 0; i < nodeCount; i++) if (windingNumber(mesh, point(skeleton.nodes, i)) > 0.5) inside++;
      expect(inside / nodeCount).toBeGreaterThanOrEqual(0.98);
    }, 60_000);
  }
});
