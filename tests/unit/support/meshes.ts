// Meshes made in code for tests with known answers, and a reader for the shared data set.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { parseMesh } from '../../../lib/io/index.ts';
import type { MeshArrays } from '../../../lib/core/index.ts';

export function readMesh(file: string): MeshArrays {
  return parseMesh(new Uint8Array(readFileSync(file)), path.basename(file));
}

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

function normalize(p: number[]): number[] {
  const n = Math.hypot(p[0], p[1], p[2]);
  return p.map((x) => x / n);
}
