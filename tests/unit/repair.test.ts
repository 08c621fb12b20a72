// Repair on load (lib/io/repair.ts): each repair on a mesh built to need it, checked by the core's own
// facts afterwards; meshes that need nothing come back untouched.
import { readdirSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core, type MeshArrays } from '../../lib/core/node.ts';
import { MeshFormatError } from '../../lib/io/index.ts';
import { repairMesh } from '../../lib/io/repair.ts';
import { random } from '../../lib/core/random.ts';
import { sharedData, sharedMesh } from '../paths.ts';
import { TETRAHEDRON, capsule, icosphere, meshOf as mesh, readMesh, torus } from './support/meshes.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

const { positions: TET_POSITIONS, triangles: TET_TRIANGLES } = TETRAHEDRON;

/** The core sees a mesh it can open: manifold, oriented, nothing degenerate or unused. */
function expectClean(m: MeshArrays) {
  const facts = core.inspect(m);
  expect(facts).toMatchObject({ manifold: true, consistentlyOriented: true, degenerateFaces: 0, unreferencedVertices: 0 });
  core.openSurface(m).dispose();
  return facts;
}

/** CPU time since `start`: unlike wall time, it does not grow when other processes share the cores. */
function cpuMs(start: NodeJS.CpuUsage): number {
  const { user, system } = process.cpuUsage(start);
  return (user + system) / 1000;
}

/** Each face as the sorted corner positions: what splits and flips must not change. */
function faceCorners(m: MeshArrays): string[] {
  return Array.from({ length: m.triangles.length / 3 }, (_, f) =>
    [0, 1, 2].map((k) => Array.from(m.positions.subarray(3 * m.triangles[3 * f + k], 3 * m.triangles[3 * f + k] + 3)).join(' ')).sort().join(' | '));
}

function flipped(m: MeshArrays, faces: number[]): MeshArrays {
  const triangles = m.triangles.slice();
  for (const f of faces) [triangles[3 * f + 1], triangles[3 * f + 2]] = [triangles[3 * f + 2], triangles[3 * f + 1]];
  return { positions: m.positions, triangles };
}

function scaled(m: MeshArrays, s: number): MeshArrays {
  return { positions: m.positions.map((x) => s * x), triangles: m.triangles };
}

/** Two meshes as one: the second's vertices after the first's. */
function joined(a: MeshArrays, b: MeshArrays): MeshArrays {
  const offset = a.positions.length / 3;
  return mesh([...a.positions, ...b.positions], [...a.triangles, ...b.triangles.map((v) => v + offset)]);
}

describe('meshes that need no repair', () => {
  it('come back as the same object with no repairs', () => {
    for (const m of [icosphere(3), torus(3, 1, 24, 12), capsule(2, 0.5, 16), mesh(TET_POSITIONS, TET_TRIANGLES)]) {
      const result = repairMesh(m);
      expect(result.mesh).toBe(m);
      expect(result.repairs).toEqual([]);
      expect(Array.from(result.vertexMap)).toEqual(Array.from({ length: m.positions.length / 3 }, (_, i) => i));
    }
  });

  it('every shared mesh', () => {
    const names = readdirSync(`${sharedData}/meshes`).filter((name) => name.endsWith('.ply'));
    expect(names.length).toBeGreaterThanOrEqual(26);
    for (const name of names) {
      const m = readMesh(sharedMesh(name));
      expect(repairMesh(m).repairs, name).toEqual([]);
    }
  });

  it('a hollow ball: the cavity faces inward and stays so', () => {
    const outer = icosphere(2);
    const cavity = flipped(scaled(outer, 0.5), Array.from({ length: outer.triangles.length / 3 }, (_, f) => f));
    expect(repairMesh(joined(outer, cavity)).repairs).toEqual([]);
  });

  it('a million faces in well under a few seconds', () => {
    const big = torus(3, 1, 1000, 500);
    expect(big.triangles.length).toBe(3_000_000);
    const start = process.cpuUsage();
    expect(repairMesh(big).repairs).toEqual([]);
    expect(cpuMs(start)).toBeLessThan(5000);
  });
});

describe('repairs', () => {
  it('welds a triangle soup back into the mesh, within a scale-relative tolerance', () => {
    const spot = readMesh(sharedMesh('spot.ply'));
    const facts = core.inspect(spot);
    const soup = (jitter: number) => {
      const positions: number[] = [];
      spot.triangles.forEach((v, i) => positions.push(...[0, 1, 2].map((k) => spot.positions[3 * v + k] + (i % 3 === 1 ? jitter : 0))));
      return mesh(positions, Array.from(spot.triangles, (_, i) => i));
    };
    const corners = spot.triangles.length;
    const exact = soup(0);
    const welded = repairMesh(exact);
    expect(welded.repairs).toEqual([`welded ${corners - facts.vertices} duplicate vertices (closer than 1e-6 of the bounding-box diagonal)`]);
    expect(expectClean(welded.mesh)).toMatchObject({ vertices: facts.vertices, faces: facts.faces, genus: 0 });
    // Every corner maps to a vertex at its own position.
    welded.vertexMap.forEach((to, corner) => {
      for (let k = 0; k < 3; k++) expect(welded.mesh.positions[3 * to + k]).toBe(exact.positions[3 * corner + k]);
    });

    // Near (1e-8 of the diagonal) still welds; far (1e-4) does not.
    expect(repairMesh(soup(1e-8 * facts.bboxDiagonal)).repairs[0]).toMatch(`welded ${corners - facts.vertices} duplicate`);
    const apart = repairMesh(soup(1e-4 * facts.bboxDiagonal));
    expect(apart.repairs[0]).toMatch(/^welded \d+ duplicate/);
    expect(core.inspect(apart.mesh).vertices).toBeGreaterThan(facts.vertices);
  });

  it('flips faces that disagree with their neighbours', () => {
    const sphere = icosphere(2);
    const result = repairMesh(flipped(sphere, [3, 17, 100]));
    expect(result.repairs).toEqual(['flipped 3 faces to agree with their neighbours']);
    expect(result.mesh.triangles).toEqual(sphere.triangles);
    expect(result.mesh.positions).toEqual(sphere.positions);
  });

  it('turns a closed component that faces inward outward, and a cavity that faces outward inward', () => {
    const sphere = icosphere(2);
    const all = Array.from({ length: sphere.triangles.length / 3 }, (_, f) => f);
    const inward = repairMesh(flipped(sphere, all));
    expect(inward.repairs).toEqual([`reversed 1 closed component that faced inward (${all.length} faces)`]);
    expect(inward.mesh.triangles).toEqual(sphere.triangles);

    const hollow = repairMesh(joined(sphere, scaled(sphere, 0.5)));
    expect(hollow.repairs).toEqual([`reversed 1 closed component that faced inward (${all.length} faces)`]);
    expect(expectClean(hollow.mesh).components).toBe(2);
    expect(hollow.mesh.triangles.subarray(0, 3 * all.length)).toEqual(sphere.triangles);
  });

  it('finds the one inside-out part among 8000 closed parts quickly', () => {
    // A 20 x 20 x 20 grid of separate tetrahedra (spacing 2), the one at index 4321 reversed.
    const positions: number[] = [], triangles: number[] = [];
    for (let i = 0; i < 8000; i++) {
      const offset = [i % 20, Math.floor(i / 20) % 20, Math.floor(i / 400)].map((x) => 2 * x);
      positions.push(...TET_POSITIONS.map((x, k) => x + offset[k % 3]));
      const faces = TET_TRIANGLES.map((v) => v + 4 * i);
      triangles.push(...(i === 4321 ? flipped(mesh(TET_POSITIONS, faces), [0, 1, 2, 3]).triangles : faces));
    }
    const start = process.cpuUsage();
    const result = repairMesh(mesh(positions, triangles));
    expect(cpuMs(start)).toBeLessThan(3000);
    expect(result.repairs).toEqual(['reversed 1 closed component that faced inward (4 faces)']);
    expect(Array.from(result.mesh.triangles.subarray(12 * 4321, 12 * 4322))).toEqual(TET_TRIANGLES.map((v) => v + 4 * 4321));
  });

  it('splits a bow-tie vertex', () => {
    // Two tetrahedra touching at vertex 0.
    const other = TET_POSITIONS.map((x, i) => (i < 3 ? x : -x));
    const bowTie = mesh([...TET_POSITIONS, ...other.slice(3)], [...TET_TRIANGLES, ...TET_TRIANGLES.map((v) => (v === 0 ? 0 : v + 3)).map((v, i, t) => (i % 3 === 1 ? t[i + 1] : i % 3 === 2 ? t[i - 1] : v))]);
    expect(core.inspect(bowTie).nonManifoldVertices).toBe(1);
    const result = repairMesh(bowTie);
    expect(result.repairs).toEqual(['split 1 non-manifold vertex (faces meeting only at a point) into 2']);
    expect(expectClean(result.mesh)).toMatchObject({ vertices: 8, components: 2, genus: 0 });
    expect(Array.from(result.mesh.positions.subarray(21, 24))).toEqual([0, 0, 0]); // the copy, after the others
  });

  it('detaches the third face of a fin edge', () => {
    const fin = mesh([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1], [0, 1, 2, 1, 0, 3, 0, 1, 4]);
    const result = repairMesh(fin);
    expect(result.repairs).toEqual(['split 1 non-manifold edge (more than two faces on an edge) into 2 edges with 2 copied vertices']);
    // Faces 0 and 1 (a consistent pair) stay joined along 0-1; face 2 gets copies 5 and 6 of 0 and 1.
    expect(Array.from(result.mesh.triangles)).toEqual([0, 1, 2, 1, 0, 3, 5, 6, 4]);
    expect(expectClean(result.mesh)).toMatchObject({ vertices: 7, components: 2, boundaryLoops: 2 });
  });

  it('separates two closed surfaces sharing an edge', () => {
    // A second tetrahedron on edge 0-1 of the first: four faces on that edge.
    const second = mesh([...TET_POSITIONS, 0, -1, 0, 0, 0, -1], [...TET_TRIANGLES, 0, 4, 1, 0, 1, 5, 0, 5, 4, 1, 4, 5]);
    expect(core.inspect(second).nonManifoldEdges).toBe(1);
    const result = repairMesh(second);
    expect(result.repairs).toEqual(['split 1 non-manifold edge (more than two faces on an edge) into 2 edges with 2 copied vertices']);
    expect(expectClean(result.mesh)).toMatchObject({ vertices: 8, components: 2, boundaryLoops: 0, genus: 0 });

    // Faces in another order: the first consistent pair is one face of each, so joining it would keep
    // the four together around vertices 0 and 1; the edge is then cut apart completely.
    const order = [0, 5, 1, 4, 2, 3, 6, 7];
    const interleaved = mesh(Array.from(second.positions), order.flatMap((f) => Array.from(second.triangles.subarray(3 * f, 3 * f + 3))));
    const apart = repairMesh(interleaved);
    expect(apart.repairs).toEqual(['split 1 non-manifold edge (more than two faces on an edge) into 2 edges with 2 copied vertices']);
    expect(expectClean(apart.mesh)).toMatchObject({ vertices: 8, components: 2, boundaryLoops: 0, genus: 0 });

    // A third tetrahedron touching vertex 0 and listed first keeps vertex 0, so the first pass moves
    // the pair onto a copy and the second pass copies that copy: every copy sits where its vertex was.
    const touching = TET_TRIANGLES.map((v) => (v === 0 ? 0 : v + 5)).map((v, i, t) => (i % 3 === 1 ? t[i + 1] : i % 3 === 2 ? t[i - 1] : v));
    const moved = (p: number[]) => p.map((x, i) => x + [1, 2, 3][i % 3]);
    const three = mesh(moved([...interleaved.positions, ...TET_POSITIONS.slice(3).map((x) => -2 * x)]), [...touching, ...interleaved.triangles]);
    const result3 = repairMesh(three);
    // Vertex 0 is an end of the cut edge, so its third copy is counted with the edge.
    expect(result3.repairs).toEqual(['split 1 non-manifold edge (more than two faces on an edge) into 2 edges with 3 copied vertices']);
    expect(expectClean(result3.mesh)).toMatchObject({ vertices: 12, components: 3, boundaryLoops: 0, genus: 0 });
    expect(faceCorners(result3.mesh)).toEqual(faceCorners(three));
  });

  it('flips a zero-area cap with its neighbour, keeping a closed surface closed', () => {
    // The octahedron with vertex 6 in the middle of edge 0-2: one side has the edge split at 6, the
    // other still has edge 0-2, and the cap (2, 0, 6) closes the T-junction with no area.
    const positions = [1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0.5, 0.5, 0];
    const triangles = [0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 6, 5, 6, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5, 2, 0, 6];
    expect(core.inspect(mesh(positions, triangles)).degenerateFaces).toBe(1);
    const result = repairMesh(mesh(positions, triangles));
    expect(result.repairs).toEqual(['flipped 1 zero-area face with its neighbour into proper triangles (the same surface)']);
    // Face 0 (0, 2, 4) across edge 0-2 and the cap become (6, 2, 4) and (0, 6, 4).
    expect(Array.from(result.mesh.triangles.subarray(0, 3))).toEqual([0, 6, 4]);
    expect(Array.from(result.mesh.triangles.subarray(27))).toEqual([6, 2, 4]);
    expect(expectClean(result.mesh)).toMatchObject({ faces: 10, boundaryLoops: 0, genus: 0 });
  });

  it('removes degenerate and duplicate faces and unreferenced vertices, and maps the vertices', () => {
    // The tetrahedron, a stray vertex first, a face repeating a vertex, a zero-area sliver on a
    // collinear extra vertex, and face 1 again in the other orientation.
    const positions = [9, 9, 9, ...TET_POSITIONS, 2, 0, 0];
    const triangles = [...TET_TRIANGLES.map((v) => v + 1), 1, 1, 2, 1, 2, 5, 1, 4, 2];
    const result = repairMesh(mesh(positions, triangles));
    expect(result.repairs).toEqual([
      'removed 2 degenerate faces (zero area or a repeated vertex)',
      'removed 1 duplicate face (the same three vertices as an earlier face)',
      'removed 2 unreferenced vertices (used by no face)',
    ]);
    expect(Array.from(result.mesh.triangles)).toEqual(TET_TRIANGLES);
    expect(Array.from(result.mesh.positions)).toEqual(TET_POSITIONS);
    expect(Array.from(result.vertexMap)).toEqual([-1, 0, 1, 2, 3, -1]);
    expectClean(result.mesh);
  });

  it('refuses a mesh whose faces are all degenerate', () => {
    const collinear = mesh([0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0], [0, 1, 2, 1, 2, 3]);
    expect(() => repairMesh(collinear)).toThrow(MeshFormatError);
    expect(() => repairMesh(collinear)).toThrow('all 2 faces are degenerate (zero area or a repeated vertex): there is no surface left');
  });

  it('turns random triangle soups into manifold meshes or refuses them', () => {
    // Few vertices on a coarse grid: duplicates, collinear points, fins and bow-ties are common.
    const next = random(7);
    let oriented = 0;
    const trials = 500;
    for (let trial = 0; trial < trials; trial++) {
      const nV = 3 + Math.floor(next() * 10), nF = 1 + Math.floor(next() * 25);
      const soup = mesh(Array.from({ length: 3 * nV }, () => Math.floor(next() * 3)), Array.from({ length: 3 * nF }, () => Math.floor(next() * nV)));
      let result;
      try {
        result = repairMesh(soup);
      } catch (error) {
        expect(error).toBeInstanceOf(MeshFormatError);
        continue;
      }
      const facts = core.inspect(result.mesh);
      expect(facts, JSON.stringify(Array.from(soup.triangles))).toMatchObject({ manifold: true, degenerateFaces: 0, unreferencedVertices: 0 });
      // Faces only go away, split or flip; their corners stay where they were (cap flips, the one
      // repair that makes new faces, are tested on their own).
      const before = new Set(faceCorners(soup));
      if (!result.repairs.some((r) => r.includes('zero-area'))) expect(faceCorners(result.mesh).every((corners) => before.has(corners))).toBe(true);
      // Some soups make one-sided surfaces (Moebius-like), which no flip can orient; most are two-sided.
      if (facts.consistentlyOriented) oriented++;
    }
    expect(oriented).toBeGreaterThan(0.8 * trials);
  });

  it('leaves what it cannot mend to the core: a Moebius strip, non-finite coordinates', () => {
    // A strip of 5 quads around a circle, closed with a half twist.
    const n = 5;
    const positions: number[] = [];
    for (let i = 0; i < n; i++) {
      const t = (2 * Math.PI * i) / n;
      const w = 0.3 * Math.cos(t / 2), h = 0.3 * Math.sin(t / 2);
      positions.push((1 + w) * Math.cos(t), (1 + w) * Math.sin(t), h, (1 - w) * Math.cos(t), (1 - w) * Math.sin(t), -h);
    }
    const triangles: number[] = [];
    for (let i = 0; i < n; i++) {
      const [a, b] = [2 * i, 2 * i + 1];
      const [c, d] = i + 1 < n ? [2 * i + 2, 2 * i + 3] : [1, 0]; // the twist swaps the sides
      triangles.push(a, b, c, c, b, d);
    }
    const moebius = mesh(positions, triangles);
    expect(core.inspect(moebius).consistentlyOriented).toBe(false);
    expect(repairMesh(moebius).repairs).toEqual([]);

    const withNaN = mesh([...TET_POSITIONS.slice(0, 11), NaN], TET_TRIANGLES);
    expect(repairMesh(withNaN).mesh).toBe(withNaN);
    // An unused vertex may be anything: it is dropped.
    const unusedNaN = repairMesh(mesh([...TET_POSITIONS, NaN, 0, 0], TET_TRIANGLES));
    expect(unusedNaN.repairs).toEqual(['removed 1 unreferenced vertex (used by no face)']);
  });
});
