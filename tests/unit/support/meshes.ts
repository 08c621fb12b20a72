// Meshes made in code for tests with known answers, and a reader for the shared data set.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { parseMesh } from '../../../lib/io/index.ts';
import type { MeshArrays, Surface } from '../../../lib/core/index.ts';
import { random } from '../../../lib/core/random.ts';

export function readMesh(file: string): MeshArrays {
  return parseMesh(new Uint8Array(readFileSync(file)), path.basename(file));
}

/** Arrays of a mesh written out in a test. */
export function meshOf(positions: number[], triangles: number[]): MeshArrays {
  return { positions: Float64Array.from(positions), triangles: Uint32Array.from(triangles) };
}

/** A closed, outward-oriented tetrahedron on the origin and the unit axis points. */
export const TETRAHEDRON = { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], triangles: [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3] };

/** Unit icosphere: an icosahedron subdivided `levels` times, vertices projected to the sphere. */
export function icosphere(levels: number): MeshArrays {
  const t = (1 + Math.sqrt(5)) / 2;
  const points: number[][] = [
    [-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
    [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1],
  ].map(normalize);
  let faces = [
    [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2],
    [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5],
    [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
  ];
  for (let level = 0; level < levels; level++) {
    const midpoints = new Map<string, number>();
    const midpoint = (a: number, b: number) => {
      const key = a < b ? `${a},${b}` : `${b},${a}`;
      let index = midpoints.get(key);
      if (index === undefined) {
        index = points.push(normalize(points[a].map((x, k) => x + points[b][k]))) - 1;
        midpoints.set(key, index);
      }
      return index;
    };
    faces = faces.flatMap(([a, b, c]) => {
      const ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      return [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]];
    });
  }
  return { positions: Float64Array.from(points.flat()), triangles: Uint32Array.from(faces.flat()) };
}

/**
 * Torus around the z axis: ring radius R, tube radius r, `nu` rings (even) of `nv` vertices. Odd rings are
 * turned by half a step so that the triangles are nearly equilateral (a one-diagonal quad grid biases
 * gradient-based distances). Vertex (i, j) sits at ring angle 2*pi*i/nu and tube angle
 * 2*pi*(j + (i odd ? 1/2 : 0))/nv, tube angle 0 being the outer equator.
 */
export function torus(R: number, r: number, nu: number, nv: number): MeshArrays {
  if (nu % 2 !== 0) throw new Error('torus: the number of rings must be even');
  const positions = new Float64Array(nu * nv * 3);
  const triangles: number[] = [];
  const id = (i: number, j: number) => (i % nu) * nv + (j % nv);
  for (let i = 0; i < nu; i++) {
    const u = (2 * Math.PI * i) / nu;
    for (let j = 0; j < nv; j++) {
      const v = (2 * Math.PI * (j + (i % 2) / 2)) / nv;
      positions.set([(R + r * Math.cos(v)) * Math.cos(u), (R + r * Math.cos(v)) * Math.sin(u), r * Math.sin(v)], 3 * id(i, j));
      if (i % 2 === 0) triangles.push(id(i, j), id(i + 1, j), id(i, j + 1), id(i, j + 1), id(i + 1, j), id(i + 1, j + 1));
      else triangles.push(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  }
  return { positions, triangles: Uint32Array.from(triangles) };
}

/**
 * Capsule along the x axis: the points within distance r of the segment from (-L/2, 0, 0) to (L/2, 0, 0).
 * `around` vertices per ring; rings spaced about as far apart as the vertices of a ring.
 */
export function capsule(L: number, r: number, around: number): MeshArrays {
  const step = (2 * Math.PI * r) / around;
  const capRings = Math.max(2, Math.round((Math.PI * r) / 2 / step));
  const profile: [number, number][] = []; // (x, ring radius), from the left tip (excluded) to the right one
  for (let i = 1; i <= capRings; i++) {
    const phi = ((Math.PI / 2) * i) / capRings;
    profile.push([-L / 2 - r * Math.cos(phi), r * Math.sin(phi)]);
  }
  const bodyRings = Math.max(1, Math.round(L / step));
  for (let i = 1; i < bodyRings; i++) profile.push([-L / 2 + (L * i) / bodyRings, r]);
  for (let i = capRings; i >= 1; i--) {
    const phi = ((Math.PI / 2) * i) / capRings;
    profile.push([L / 2 + r * Math.cos(phi), r * Math.sin(phi)]);
  }
  const positions: number[] = [-L / 2 - r, 0, 0];
  for (const [x, rho] of profile)
    for (let j = 0; j < around; j++) {
      const angle = (2 * Math.PI * j) / around;
      positions.push(x, rho * Math.cos(angle), rho * Math.sin(angle));
    }
  positions.push(L / 2 + r, 0, 0);
  const last = positions.length / 3 - 1;
  const ring = (i: number, j: number) => 1 + i * around + (j % around);
  const triangles: number[] = [];
  for (let j = 0; j < around; j++) triangles.push(0, ring(0, j + 1), ring(0, j));
  for (let i = 0; i + 1 < profile.length; i++)
    for (let j = 0; j < around; j++)
      triangles.push(ring(i, j), ring(i, j + 1), ring(i + 1, j), ring(i + 1, j), ring(i, j + 1), ring(i + 1, j + 1));
  const end = profile.length - 1;
  for (let j = 0; j < around; j++) triangles.push(last, ring(end, j), ring(end, j + 1));
  return { positions: Float64Array.from(positions), triangles: Uint32Array.from(triangles) };
}

/**
 * A sheet (a surface with boundary, no thickness): the part of the plane where `inside(x, y)` holds,
 * triangulated by a lattice of near-equilateral triangles with edge `h` over [x0, x1] x [y0, y1] (a
 * triangle is kept when its centroid is inside), then placed in space by `place` (default: z = 0).
 */
export function sheet(
  [x0, x1]: [number, number],
  [y0, y1]: [number, number],
  h: number,
  inside: (x: number, y: number) => boolean,
  place: (x: number, y: number) => number[] = (x, y) => [x, y, 0],
): MeshArrays {
  const rowStep = (h * Math.sqrt(3)) / 2;
  const rows = Math.ceil((y1 - y0) / rowStep) + 1;
  const columns = Math.ceil((x1 - x0) / h) + 1;
  const at = (i: number, j: number): [number, number] => [x0 + i * h + (j % 2 ? h / 2 : 0), y0 + j * rowStep];
  const index = new Map<number, number>();
  const positions: number[] = [];
  const triangles: number[] = [];
  const vertex = (i: number, j: number) => {
    const key = j * (columns + 1) + i;
    if (!index.has(key)) {
      index.set(key, positions.length / 3);
      positions.push(...place(...at(i, j)));
    }
    return index.get(key)!;
  };
  for (let j = 0; j + 1 < rows; j++)
    for (let i = 0; i + 1 < columns; i++) {
      // Counter-clockwise seen from +z; the odd rows are shifted right by half an edge.
      const pair: [number, number][][] =
        j % 2 === 0
          ? [[[i, j], [i + 1, j], [i, j + 1]], [[i + 1, j], [i + 1, j + 1], [i, j + 1]]]
          : [[[i, j], [i + 1, j + 1], [i, j + 1]], [[i, j], [i + 1, j], [i + 1, j + 1]]];
      for (const corners of pair) {
        const centre = corners.map(([a, b]) => at(a, b)).reduce(([sx, sy], [x, y]) => [sx + x / 3, sy + y / 3], [0, 0]);
        if (inside(centre[0], centre[1])) triangles.push(...corners.map(([a, b]) => vertex(a, b)));
      }
    }
  return meshOf(positions, triangles);
}

/** The mesh as the text of an OFF file, for CLI tests that need a file. */
export function offText({ positions, triangles }: MeshArrays): string {
  const lines = ['OFF', `${positions.length / 3} ${triangles.length / 3} 0`];
  for (let i = 0; i < positions.length; i += 3) lines.push(Array.from(positions.subarray(i, i + 3)).join(' '));
  for (let i = 0; i < triangles.length; i += 3) lines.push(`3 ${Array.from(triangles.subarray(i, i + 3)).join(' ')}`);
  return `${lines.join('\n')}\n`;
}

function normalize(p: number[]): number[] {
  const n = Math.hypot(p[0], p[1], p[2]);
  return p.map((x) => x / n);
}

/**
 * The same surface, badly triangulated: a share of the faces gets a new vertex just inside one edge
 * and is split into three, one of them a sliver. Old vertex indices are kept.
 */
export function withSlivers(mesh: MeshArrays, share: number, seed: number): MeshArrays {
  const next = random(seed);
  const positions = Array.from(mesh.positions);
  const triangles: number[] = [];
  for (let f = 0; f < mesh.triangles.length / 3; f++) {
    const corners = [0, 1, 2].map((k) => mesh.triangles[3 * f + k]);
    if (next() >= share) {
      triangles.push(...corners);
      continue;
    }
    const e = Math.floor(next() * 3);
    const [a, b, c] = [corners[e], corners[(e + 1) % 3], corners[(e + 2) % 3]];
    const t = 0.2 + 0.6 * next();
    const p = [0, 1, 2].map((k) => {
      const onEdge = positions[3 * a + k] + t * (positions[3 * b + k] - positions[3 * a + k]);
      return onEdge + 0.01 * (positions[3 * c + k] - onEdge);
    });
    const id = positions.length / 3;
    positions.push(...p);
    triangles.push(a, b, id, b, c, id, c, a, id);
  }
  return { positions: Float64Array.from(positions), triangles: Uint32Array.from(triangles) };
}

/** Squared distance from point p to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5). */
export function pointTriangleDistance2(p: number[], a: number[], b: number[], c: number[]): number {
  const sub = (u: number[], v: number[]) => [u[0] - v[0], u[1] - v[1], u[2] - v[2]];
  const dot = (u: number[], v: number[]) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const at = (s: number, t: number) => a.map((x, k) => x + s * (b[k] - x) + t * (c[k] - x));
  const ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const d1 = dot(ab, ap), d2 = dot(ac, ap);
  let q: number[];
  if (d1 <= 0 && d2 <= 0) q = a;
  else {
    const bp = sub(p, b), d3 = dot(ab, bp), d4 = dot(ac, bp);
    const cp = sub(p, c), d5 = dot(ab, cp), d6 = dot(ac, cp);
    const vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (d3 >= 0 && d4 <= d3) q = b;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0) q = at(d1 / (d1 - d3), 0);
    else if (d6 >= 0 && d5 <= d6) q = c;
    else if (vb <= 0 && d2 >= 0 && d6 <= 0) q = at(0, d2 / (d2 - d6));
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
      const w = (d4 - d3) / (d4 - d3 + (d5 - d6));
      q = b.map((x, k) => x + w * (c[k] - x));
    } else {
      const denom = 1 / (va + vb + vc);
      q = at(vb * denom, vc * denom);
    }
  }
  const d = sub(p, q);
  return dot(d, d);
}

/** `count` limb tips by farthest-point sampling of the geodesic distance. */
export function extremities(surface: Surface, count: number): number[] {
  const nearest = new Float64Array(surface.facts.vertices).fill(Infinity);
  const d0 = surface.distanceFromVertex(0);
  let tip = d0.indexOf(Math.max(...d0));
  const tips: number[] = [];
  while (tips.length < count) {
    tips.push(tip);
    const d = surface.distanceFromVertex(tip);
    for (let v = 0; v < d.length; v++) nearest[v] = Math.min(nearest[v], d[v]);
    tip = nearest.indexOf(Math.max(...nearest));
  }
  return tips;
}
