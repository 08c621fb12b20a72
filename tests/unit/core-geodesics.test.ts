// Heat-method distances from the WASM core against known answers: great circles on a sphere, outer
// equator and meridian arcs on a torus, and exact polyhedral geodesics (MMP) on real meshes.
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import { icosphere, readMesh, torus } from './support/meshes.ts';
import { sharedMesh } from '../paths.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

function point(positions: ArrayLike<number>, v: number): [number, number, number] {
  return [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
}

/**
 * Mean of |d - reference| / reference over the vertices whose reference distance is finite and exceeds
 * `minDistance`, at least `minShare` of all vertices.
 */
function meanRelativeError(d: Float64Array, reference: ArrayLike<number>, minDistance: number, minShare = 0.5): number {
  let sum = 0;
  let count = 0;
  for (let v = 0; v < d.length; v++) {
    if (!(reference[v] > minDistance && Number.isFinite(reference[v]))) continue;
    sum += Math.abs(d[v] - reference[v]) / reference[v];
    count++;
  }
  expect(count).toBeGreaterThan(d.length * minShare);
  return sum / count;
}

describe('heat-method geodesic distance', () => {
  it('matches great-circle distances on a finely meshed unit sphere', () => {
    const sphere = icosphere(5); // 10242 vertices, mean edge length about 0.03
    const surface = core.openSurface(sphere);
    const source = 17;
    const d = surface.distanceFromVertex(source);
    const s = point(sphere.positions, source);
    const greatCircle = Array.from({ length: d.length }, (_, v) => {
      const p = point(sphere.positions, v);
      return Math.acos(Math.min(1, Math.max(-1, p[0] * s[0] + p[1] * s[1] + p[2] * s[2])));
    });
    expect(d[source]).toBeCloseTo(0, 6);
    expect(meanRelativeError(d, greatCircle, 0.1)).toBeLessThan(0.02);
    // The antipode is at distance pi.
    const antipode = greatCircle.indexOf(Math.max(...greatCircle));
    expect(Math.abs(d[antipode] - Math.PI) / Math.PI).toBeLessThan(0.02);
    surface.dispose();
  });

  it('takes the nearest of several surface points as the source', () => {
    const sphere = icosphere(4);
    const surface = core.openSurface(sphere);
    // Two points inside faces on opposite sides of the sphere: every vertex is within pi/2 of one.
    const points = [
      { face: 0, barycentric: [0.2, 0.3, 0.5] as [number, number, number] },
      { face: findOppositeFace(sphere.positions, sphere.triangles, 0), barycentric: [1 / 3, 1 / 3, 1 / 3] as [number, number, number] },
    ];
    const d = surface.distanceFromPoints(points);
    const sources = points.map((p) => barycentricPoint(sphere.positions, sphere.triangles, p.face, p.barycentric));
    let worst = 0;
    for (let v = 0; v < d.length; v++) {
      const q = point(sphere.positions, v);
      const exact = Math.min(...sources.map((s) => Math.acos(Math.min(1, dot(normalize(s), q)))));
      if (exact > 0.2) worst = Math.max(worst, Math.abs(d[v] - exact) / exact);
    }
    expect(worst).toBeLessThan(0.08);
    expect(Math.max(...d)).toBeLessThan(Math.PI / 2 * 1.05);
    surface.dispose();
  });

  it('follows the outer equator and a meridian of a torus', () => {
    const R = 1, r = 0.4, nu = 240, nv = 60; // near-equilateral triangles at the outer equator
    const mesh = torus(R, r, nu, nv);
    const surface = core.openSurface(mesh);
    const d = surface.distanceFromVertex(0); // ring angle 0, tube angle 0: on the outer equator
    // Arcs short enough to be minimising: along the outer equator (radius R + r) and the meridian (radius r).
    for (const i of [8, 16, 24, 32]) {
      const arc = ((2 * Math.PI * i) / nu) * (R + r);
      expect(Math.abs(d[i * nv] - arc) / arc).toBeLessThan(0.03);
    }
    for (const j of [6, 12, 18, 24]) {
      const arc = ((2 * Math.PI * j) / nv) * r;
      expect(Math.abs(d[j] - arc) / arc).toBeLessThan(0.03);
    }
    surface.dispose();
  });

  for (const name of ['torus.ply', 'spot.ply', 'elephant_small.ply']) {
    it(`agrees with exact polyhedral geodesics on ${name}`, () => {
      const mesh = readMesh(sharedMesh(name));
      const surface = core.openSurface(mesh);
      for (const source of [0, Math.floor(surface.facts.vertices / 2)]) {
        const heat = surface.distanceFromVertex(source);
        const exact = surface.exactDistanceFromVertex(source);
        expect(heat.length).toBe(surface.facts.vertices);
        expect(meanRelativeError(heat, exact, 5 * surface.facts.meanEdgeLength)).toBeLessThan(0.03);
      }
      surface.dispose();
    });
  }

  it('solves each connected component on its own', () => {
    const mesh = readMesh(sharedMesh('rings.ply')); // three separate tori
    const surface = core.openSurface(mesh);
    const d = surface.distanceFromVertex(0);
    const reached = d.filter(Number.isFinite).length;
    expect(reached).toBeGreaterThan(0);
    expect(reached).toBeLessThan(d.length); // the other rings are unreachable: +Infinity
    const exact = surface.exactDistanceFromVertex(0);
    for (let v = 0; v < d.length; v++) expect(Number.isFinite(d[v])).toBe(Number.isFinite(exact[v]));
    expect(meanRelativeError(d, exact, 5 * surface.facts.meanEdgeLength, 0.25)).toBeLessThan(0.03);
    surface.dispose();
  });
});

function dot(a: number[], b: number[]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

function normalize(p: number[]) {
  const n = Math.hypot(p[0], p[1], p[2]);
  return p.map((x) => x / n);
}

function barycentricPoint(positions: Float64Array | Float32Array, triangles: Uint32Array, face: number, b: number[]) {
  const corners = [0, 1, 2].map((k) => point(positions, triangles[3 * face + k]));
  return [0, 1, 2].map((axis) => b[0] * corners[0][axis] + b[1] * corners[1][axis] + b[2] * corners[2][axis]);
}

function findOppositeFace(positions: Float64Array | Float32Array, triangles: Uint32Array, face: number): number {
  const c = normalize(barycentricPoint(positions, triangles, face, [1 / 3, 1 / 3, 1 / 3]));
  let best = 0;
  let bestDot = Infinity;
  for (let f = 0; f < triangles.length / 3; f++) {
    const q = normalize(barycentricPoint(positions, triangles, f, [1 / 3, 1 / 3, 1 / 3]));
    if (dot(c, q) < bestDot) {
      bestDot = dot(c, q);
      best = f;
    }
  }
  return best;
}
