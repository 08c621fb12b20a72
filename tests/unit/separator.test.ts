// Stage 1 of CSCD-M (one local separator per source) on real and analytic meshes.
import { beforeAll, describe, expect, it } from 'vitest';
import { defaultOptions, loadCoreNode, type Core, type MeshArrays, type Separator, type Surface } from '../../lib/core/node.ts';
import { extremities, icosphere, pointTriangleDistance2, readMesh, withSlivers } from './support/meshes.ts';
import { sharedMesh } from '../paths.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

const points = (flat: Float64Array) => Array.from({ length: flat.length / 3 }, (_, i) => [flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]]);
const distance3 = (a: number[], b: number[]) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const vertex = (mesh: MeshArrays, v: number) => [0, 1, 2].map((k) => mesh.positions[3 * v + k]);

/** The vertex whose geodesic distance from `from` is closest to `at`. */
function vertexAtDistance(surface: Surface, from: number, at: number): number {
  const d = surface.distanceFromVertex(from);
  let best = 0;
  for (let v = 0; v < d.length; v++) if (Math.abs(d[v] - at) < Math.abs(d[best] - at)) best = v;
  return best;
}

/** The checks every successful separator must pass. */
function expectWellFormed(mesh: MeshArrays, surface: Surface, sep: Separator) {
  expect(sep.status, sep.message).toBe('ok');
  expect(sep.loop.length % 3).toBe(0);
  expect(sep.loop.length / 3).toBeGreaterThanOrEqual(3);
  expect(sep.length).toBeGreaterThan(0);
  expect(sep.length).toBeLessThanOrEqual(sep.approxLength * (1 + 1e-9));
  // The polyline is closed and its length is the loop length.
  const loop = points(sep.loop);
  const polylineLength = loop.reduce((sum, p, i) => sum + distance3(p, loop[(i + 1) % loop.length]), 0);
  expect(polylineLength).toBeLessThanOrEqual(sep.length * 1.02);
  expect(polylineLength).toBeGreaterThan(sep.length * 0.9);
  // Every loop point lies on the surface.
  const tolerance2 = (1e-6 * surface.facts.bboxDiagonal) ** 2;
  for (const p of loop) {
    let best = Infinity;
    for (let f = 0; f < mesh.triangles.length / 3 && best > tolerance2; f++) {
      const [a, b, c] = [0, 1, 2].map((k) => vertex(mesh, mesh.triangles[3 * f + k]));
      best = Math.min(best, pointTriangleDistance2(p, a, b, c));
    }
    expect(best).toBeLessThanOrEqual(tolerance2);
  }
  // The sphere limits the vertices flips may involve: points between two inside vertices may bulge out
  // by a fraction of an edge, no more.
  if (sep.sphere) {
    const slack = 0.5 * surface.facts.meanEdgeLength;
    for (const p of loop) expect(distance3(p, sep.sphere.center)).toBeLessThanOrEqual(sep.sphere.radius + slack);
  }
  expect(sep.areas[0]).toBeLessThanOrEqual(sep.areas[1]);
}

describe('stage 1: one local separator', () => {
  it('uses the documented defaults', () => {
    const surface = core.openSurface(icosphere(2));
    const explicit = surface.separator(0, defaultOptions);
    const implicit = surface.separator(0);
    expect(explicit.cutLocus.vertices).toEqual(implicit.cutLocus.vertices);
    expect(explicit.loop).toEqual(implicit.loop);
    surface.dispose();
  });

  it('finds the cut locus of a sphere point at its antipode', () => {
    const sphere = icosphere(5);
    const surface = core.openSurface(sphere);
    for (const source of [0, 1234, 7777]) {
      const sep = surface.separator(source);
      const antipode = vertex(sphere, source).map((x) => -x);
      expect(sep.cutLocus.vertices.length).toBeGreaterThan(0);
      for (const p of points(sep.cutLocus.points)) expect(distance3(p, antipode)).toBeLessThan(0.1);
    }
    surface.dispose();
  });

  it('gives a meridian of the torus for a source on the outer equator', () => {
    const mesh = readMesh(sharedMesh('torus.ply'));
    const surface = core.openSurface(mesh);
    // The tube radius is half the thinnest extent of the bounding box.
    const { bboxMin, bboxMax } = surface.facts;
    const r = Math.min(...[0, 1, 2].map((k) => bboxMax[k] - bboxMin[k])) / 2;
    const axis = [0, 1, 2].find((k) => bboxMax[k] - bboxMin[k] === 2 * r)!;
    let source = 0;
    let radial = 0;
    for (let v = 0; v < surface.facts.vertices; v++) {
      const p = vertex(mesh, v);
      const fromAxis = Math.hypot(...p.filter((_, k) => k !== axis));
      if (fromAxis > radial) [radial, source] = [fromAxis, v];
    }
    const local = surface.separator(source);
    expectWellFormed(mesh, surface, local);
    expect(Math.abs(local.length - 2 * Math.PI * r) / (2 * Math.PI * r)).toBeLessThan(0.05);
    // Inside the sphere it splits the region in two...
    expect(local.areas[0]).toBeGreaterThan(0.2 * local.areas[1]);
    // ...but a meridian separates nothing on the whole torus: its sides are then measured over the
    // faces within a tube radius of it (along edges), two bands alike and narrower than the 2 pi r x r
    // of a cylinder's (measured: a fifth of it on this torus).
    const global = surface.separator(source, { sphere: false });
    expect(global.status).toBe('ok');
    expect(Math.abs(global.length - 2 * Math.PI * r) / (2 * Math.PI * r)).toBeLessThan(0.05);
    expect(global.areas[0]).toBeGreaterThan(0.7 * global.areas[1]);
    for (const side of global.areas) expect(side / (2 * Math.PI * r * r)).toBeGreaterThan(0.1);
    for (const side of global.areas) expect(side / (2 * Math.PI * r * r)).toBeLessThan(1);
    surface.dispose();
  });

  it('has cycle rank 2g on closed surfaces of genus 1 and 2', () => {
    for (const [name, genus] of [['torus.ply', 1], ['two_torus.ply', 2]] as const) {
      const surface = core.openSurface(readMesh(sharedMesh(name)));
      for (const source of [0, Math.floor(surface.facts.vertices / 3)]) {
        expect(surface.separator(source).cutLocus.cycleRank).toBe(2 * genus);
      }
      surface.dispose();
    }
  });

  it('encircles fingers of the hand near their tips', () => {
    const mesh = readMesh(sharedMesh('hand.ply'));
    const surface = core.openSurface(mesh);
    const diagonal = surface.facts.bboxDiagonal;
    // The six extremities of a hand: five fingertips and the flat cut of the wrist, which encloses no
    // feature (no cut-locus point is reached by a detour there).
    const sources = extremities(surface, 6).map((tip) => ({ tip, source: vertexAtDistance(surface, tip, 0.08 * diagonal) }));
    const fingers = sources.filter(({ source }) => surface.separator(source).status === 'ok');
    expect(fingers.length).toBeGreaterThanOrEqual(5);
    for (const { tip, source } of fingers) {
      const sep = surface.separator(source);
      expectWellFormed(mesh, surface, sep);
      expect(sep.centroidInside).toBe(true);
      expect(sep.length).toBeLessThan(0.2 * diagonal); // a finger's girth, well below its length
      expect(sep.areas[0]).toBeGreaterThan(0);
      // On the whole hand, the loop cuts off a small piece: the fingertip side is A1.
      const whole = surface.separator(source, { sphere: false });
      expect(whole.status).toBe('ok');
      expect(whole.areas[0]).toBeGreaterThan(0);
      expect(whole.areas[0]).toBeLessThan(0.1 * (whole.areas[0] + whole.areas[1]));
      // The loop sits near the tip, not elsewhere on the hand.
      const centroid = [0, 1, 2].map((k) => points(sep.loop).reduce((s, p) => s + p[k], 0) / (sep.loop.length / 3));
      expect(distance3(centroid, vertex(mesh, tip))).toBeLessThan(0.2 * diagonal);
    }
    surface.dispose();
  });

  it('encircles the limbs of the armadillo near their ends', () => {
    const mesh = readMesh(sharedMesh('armadillo.ply'));
    const surface = core.openSurface(mesh);
    const diagonal = surface.facts.bboxDiagonal;
    for (const tip of extremities(surface, 4)) {
      const sep = surface.separator(vertexAtDistance(surface, tip, 0.08 * diagonal));
      expectWellFormed(mesh, surface, sep);
      expect(sep.centroidInside).toBe(true);
      expect(sep.length).toBeLessThan(0.15 * diagonal);
      expect(sep.areas[0]).toBeGreaterThan(0);
    }
    surface.dispose();
  });

  it('gives the same loop length on a badly triangulated copy of the mesh', () => {
    for (const name of ['torus.ply', 'hand.ply']) {
      const clean = readMesh(sharedMesh(name));
      const cleanSurface = core.openSurface(clean);
      const source = name === 'torus.ply' ? 0 : vertexAtDistance(cleanSurface, extremities(cleanSurface, 1)[0], 0.08 * cleanSurface.facts.bboxDiagonal);
      const reference = cleanSurface.separator(source);
      cleanSurface.dispose();
      const sliverMesh = withSlivers(clean, 0.3, 7);
      const slivers = core.openSurface(sliverMesh);
      expect(slivers.facts.faces).toBeGreaterThan(1.5 * clean.triangles.length / 3);
      const sep = slivers.separator(source);
      expect(sep.status, sep.message).toBe('ok');
      expect(Math.abs(sep.length - reference.length) / reference.length).toBeLessThan(0.1);
      slivers.dispose();
    }
  });

  it('shortens loops where the intrinsic triangulation has parallel edges', () => {
    // These elephant.ply sources once failed: their constraint patch has two intrinsic edges joining
    // the same pair of vertices.
    const mesh = readMesh(sharedMesh('elephant.ply'));
    const surface = core.openSurface(mesh);
    for (const source of [69, 15648, 24165]) expectWellFormed(mesh, surface, surface.separator(source));
    surface.dispose();
  });

  it('reports failures as a status and checks its options', () => {
    const surface = core.openSurface(readMesh(sharedMesh('spot.ply')));
    expect(() => surface.separator(0, { target: 'nearest' as 'euclid' })).toThrow(/target must be 'euclid' or 'geodesic'/);
    expect(() => surface.separator(0, { angleThreshold: 4 })).toThrow(/angleThreshold must be between 0 and/);
    // An impossible ridge threshold leaves no cut locus but the call still answers.
    const none = surface.separator(0, { angleThreshold: Math.PI, laplacianThreshold: 1e5 });
    expect(none.status).not.toBe('ok');
    expect(none.message.length).toBeGreaterThan(0);
    expect(none.distance.length).toBe(surface.facts.vertices);
    const geodesic = surface.separator(1020, { target: 'geodesic' });
    expect(geodesic.status).toBe('ok');
    surface.dispose();
  });
});
