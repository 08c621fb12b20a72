// The core's answers to arrays that are not a usable surface: clear errors naming elements, never a crash.
import { beforeAll, describe, expect, it } from 'vitest';
import { CoreError, loadCoreNode, type Core } from '../../lib/core/node.ts';
import { TETRAHEDRON, icosphere, meshOf as mesh, readMesh } from './support/meshes.ts';
import { sharedMesh } from '../paths.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

const { positions: tetPositions, triangles: tetTriangles } = TETRAHEDRON;

function expectCoreError(action: () => unknown, fragment: RegExp) {
  let error: unknown;
  try {
    action();
  } catch (e) {
    error = e;
  }
  expect(error).toBeInstanceOf(CoreError);
  expect((error as Error).message).toMatch(fragment);
}

describe('input checks', () => {
  it('rejects arrays that are not a mesh', () => {
    expectCoreError(() => core.inspect(mesh([], [])), /no vertices/);
    expectCoreError(() => core.inspect(mesh(tetPositions, [])), /no faces/);
    expectCoreError(() => core.inspect(mesh([0, 0], [0, 1, 2])), /three coordinates per vertex/);
    expectCoreError(() => core.inspect(mesh(tetPositions, [0, 1])), /three vertex indices per face/);
    expectCoreError(() => core.inspect(mesh(tetPositions, [0, 1, 7])), /face 0 refers to vertex 7.*only 4 vertices/);
    const withNaN = [...tetPositions];
    withNaN[4] = NaN;
    expectCoreError(() => core.inspect(mesh(withNaN, tetTriangles)), /vertex 1 has a non-finite coordinate/);
    const withInf = [...tetPositions];
    withInf[9] = Infinity;
    expectCoreError(() => core.openSurface(mesh(withInf, tetTriangles)), /vertex 3 has a non-finite coordinate/);
  });

  it('reports a bow-tie vertex and refuses to open it', () => {
    // Two triangles that touch only at vertex 0.
    const bowTie = mesh([0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0], [0, 1, 2, 0, 3, 4]);
    const facts = core.inspect(bowTie);
    expect(facts.manifold).toBe(false);
    expect(facts.nonManifoldVertices).toBe(1);
    expect(facts.nonManifoldEdges).toBe(0);
    expect(facts.genus).toBeNull();
    expect(facts.components).toBe(1);
    expectCoreError(() => core.openSurface(bowTie), /non-manifold vertices.*vertex 0/);
  });

  it('reports a fin edge with three faces', () => {
    const fin = mesh([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1], [0, 1, 2, 1, 0, 3, 0, 1, 4]);
    const facts = core.inspect(fin);
    expect(facts.nonManifoldEdges).toBe(1);
    expect(facts.manifold).toBe(false);
    expectCoreError(() => core.openSurface(fin), /edge 0-1 in faces 0 1 2/);
  });

  it('reports flipped faces, repeated vertices, unused vertices and zero-area faces', () => {
    const flipped = [...tetTriangles];
    [flipped[1], flipped[2]] = [flipped[2], flipped[1]];
    expect(core.inspect(mesh(tetPositions, flipped)).consistentlyOriented).toBe(false);
    expectCoreError(() => core.openSurface(mesh(tetPositions, flipped)), /not consistently oriented/);

    const repeated = mesh(tetPositions, [...tetTriangles, 0, 0, 1]);
    expect(core.inspect(repeated).degenerateFaces).toBe(1);
    expectCoreError(() => core.openSurface(repeated), /faces use the same vertex twice.*face 4/);

    const unused = mesh([...tetPositions, 5, 5, 5], tetTriangles);
    expect(core.inspect(unused).unreferencedVertices).toBe(1);
    expect(core.inspect(unused).bboxDiagonal).toBeCloseTo(Math.sqrt(3));
    expectCoreError(() => core.openSurface(unused), /used by no face.*vertex 4/);

    // A sliver with three collinear corners counts as degenerate but does not stop the surface.
    const sliver = core.inspect(mesh([0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0], [0, 1, 3, 1, 2, 3, 0, 2, 1]));
    expect(sliver.degenerateFaces).toBe(1);
  });

  it('reports a non-manifold edge added to a real mesh, then keeps working', () => {
    const spot = readMesh(sharedMesh('spot.ply'));
    const [a, b] = [spot.triangles[0], spot.triangles[1]];
    const extra = spot.positions.length / 3;
    const broken = mesh([...spot.positions, 0, 0, 5], [...spot.triangles, a, b, extra]);
    expect(core.inspect(broken).nonManifoldEdges).toBe(1);
    expectCoreError(() => core.openSurface(broken), /non-manifold edges/);
    const surface = core.openSurface(spot); // the module is still healthy
    expect(surface.distanceFromVertex(0).every(Number.isFinite)).toBe(true);
    surface.dispose();
  });

  it('checks query arguments', () => {
    const sphere = core.openSurface(icosphere(2));
    const n = sphere.facts.vertices;
    expectCoreError(() => sphere.distanceFromVertex(n), new RegExp(`vertex ${n} is out of range`));
    expectCoreError(() => sphere.distanceFromVertex(-1), /out of range/);
    expectCoreError(() => sphere.distanceFromVertex(1.5), /vertex 1.5 is out of range/);
    expectCoreError(() => sphere.distanceFromPoints([]), /no source points/);
    expectCoreError(() => sphere.distanceFromPoints([{ face: 10_000, barycentric: [1, 0, 0] }]), /names face 10000/);
    expectCoreError(() => sphere.distanceFromPoints([{ face: 0, barycentric: [2, -1, 0] }]), /outside its face/);
    sphere.dispose();
    expectCoreError(() => sphere.distanceFromVertex(0), /disposed/);
  });

  it('opens a surface with boundaries', () => {
    const open = core.openSurface(readMesh(sharedMesh('torus_two_holes_open.ply')));
    expect(open.facts.boundaryLoops).toBe(3);
    const d = open.distanceFromVertex(0);
    expect(d.every((x) => Number.isFinite(x) && x >= 0)).toBe(true);
    expect(Math.max(...d)).toBeGreaterThan(open.facts.bboxDiagonal / 4);
    open.dispose();
  });
});
