// Point clouds made in code: PLY files in every encoding, and point sets on known shapes; and cloud files read.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { random } from '../../../lib/core/random.ts';
import { parseShape, type ParsedCloud } from '../../../lib/io/index.ts';

/** A point-cloud file read and parsed; throws when it holds a mesh. */
export function readCloudFile(file: string): ParsedCloud {
  const shape = parseShape(new Uint8Array(readFileSync(file)), path.basename(file));
  if (shape.kind !== 'cloud') throw new Error(`${file} holds a mesh`);
  return shape;
}

export type PlyEncoding = 'ascii' | 'binary_little_endian' | 'binary_big_endian';

/** A PLY point cloud: x y z (then nx ny nz when given) of one scalar type, no face element. */
export function cloudPly(
  points: number[][], normals: number[][] | null, encoding: PlyEncoding, type: 'float' | 'double', comment = 'made by tests/unit/support/clouds.ts',
): Uint8Array {
  const names = normals ? ['x', 'y', 'z', 'nx', 'ny', 'nz'] : ['x', 'y', 'z'];
  const header = `ply\nformat ${encoding} 1.0\ncomment ${comment}\nelement vertex ${points.length}\n`
    + `${names.map((name) => `property ${type} ${name}\n`).join('')}end_header\n`;
  const rows = points.map((p, i) => (normals ? [...p, ...normals[i]] : p));
  if (encoding === 'ascii') return new TextEncoder().encode(header + rows.map((row) => row.join(' ')).join('\n') + '\n');
  const size = type === 'float' ? 4 : 8;
  const bytes = new Uint8Array(header.length + size * names.length * points.length);
  bytes.set(new TextEncoder().encode(header));
  const view = new DataView(bytes.buffer);
  const littleEndian = encoding === 'binary_little_endian';
  let o = header.length;
  for (const value of rows.flat()) {
    if (type === 'float') view.setFloat32(o, value, littleEndian);
    else view.setFloat64(o, value, littleEndian);
    o += size;
  }
  return bytes;
}

/** `n` points spread at random (from the seed) over the unit sphere, with their outward normals. */
export function spherePoints(n: number, seed: number): { positions: Float64Array; normals: Float32Array } {
  const next = random(seed);
  const positions = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    const z = 2 * next() - 1, angle = 2 * Math.PI * next(), r = Math.sqrt(1 - z * z);
    positions.set([r * Math.cos(angle), r * Math.sin(angle), z], 3 * i);
  }
  return { positions, normals: Float32Array.from(positions) };
}

/**
 * `n` points spread at random (from the seed) over the torus about the z axis with core radius `R` and tube
 * radius `r` (uniform in area: rejection by the area element), with their outward normals.
 */
export function torusPoints(n: number, R: number, r: number, seed: number): { positions: Float64Array; normals: Float32Array } {
  const next = random(seed);
  const positions = new Float64Array(3 * n), normals = new Float32Array(3 * n);
  for (let i = 0; i < n; ) {
    const around = 2 * Math.PI * next(), across = 2 * Math.PI * next();
    if (next() * (R + r) > R + r * Math.cos(across)) continue;
    const normal = [Math.cos(around) * Math.cos(across), Math.sin(around) * Math.cos(across), Math.sin(across)];
    positions.set([R * Math.cos(around) + r * normal[0], R * Math.sin(around) + r * normal[1], r * normal[2]], 3 * i);
    normals.set(normal, 3 * i++);
  }
  return { positions, normals };
}

/** Distance from each point to its nearest other point (brute force: small clouds only). */
export function nearestDistances(positions: Float64Array): number[] {
  const n = positions.length / 3;
  return Array.from({ length: n }, (_, i) => {
    let best = Infinity;
    for (let j = 0; j < n; j++) {
      if (j !== i) best = Math.min(best, Math.hypot(positions[3 * i] - positions[3 * j], positions[3 * i + 1] - positions[3 * j + 1], positions[3 * i + 2] - positions[3 * j + 2]));
    }
    return best;
  });
}

/**
 * `n` points spread at random (from the seed) over the surface of revolution about the z axis of radius
 * `radius(z)` for z in [zMin, zMax] (uniform in area: rejection by the area element), without normals.
 */
export function revolutionPoints(n: number, radius: (z: number) => number, zMin: number, zMax: number, seed: number): Float64Array {
  const next = random(seed);
  const slope = (z: number) => (radius(z + 1e-6) - radius(z - 1e-6)) / 2e-6;
  const element = (z: number) => radius(z) * Math.hypot(1, slope(z));
  let largest = 0;
  for (let k = 0; k <= 1000; k++) largest = Math.max(largest, element(zMin + ((zMax - zMin) * k) / 1000));
  const positions = new Float64Array(3 * n);
  for (let i = 0; i < n; ) {
    const z = zMin + (zMax - zMin) * next(), angle = 2 * Math.PI * next();
    if (next() * largest > element(z)) continue;
    positions.set([radius(z) * Math.cos(angle), radius(z) * Math.sin(angle), z], 3 * i++);
  }
  return positions;
}

/** Points as XYZ text, one `x y z` row each. */
export function xyzText(positions: Float64Array): string {
  const rows: string[] = [];
  for (let p = 0; p < positions.length / 3; p++) rows.push(Array.from(positions.subarray(3 * p, 3 * p + 3)).join(' '));
  return rows.join('\n');
}

/**
 * A tube of radius 1 along z scanned in `rings` rings `gap` apart, `around` points evenly round each (each
 * ring turned a little from the last, as a turntable's scan is): with rings several times farther apart
 * than the points round them, each point's nearest neighbours all lie in its own ring.
 */
export function ringScannedTube(rings: number, around: number, gap: number): Float64Array {
  const positions = new Float64Array(3 * rings * around);
  for (let ring = 0; ring < rings; ring++)
    for (let i = 0; i < around; i++) {
      const angle = (2 * Math.PI * (i + 0.37 * ring)) / around;
      positions.set([Math.cos(angle), Math.sin(angle), ring * gap], 3 * (ring * around + i));
    }
  return positions;
}

/** The index of the point of `points` nearest to each point of `queries` (brute force: small sets only). */
export function nearestPoints(queries: ArrayLike<number>, points: ArrayLike<number>): Int32Array {
  const result = new Int32Array(queries.length / 3);
  for (let q = 0; q < result.length; q++) {
    let best = Infinity;
    for (let p = 0; p < points.length / 3; p++) {
      const d = (points[3 * p] - queries[3 * q]) ** 2 + (points[3 * p + 1] - queries[3 * q + 1]) ** 2 + (points[3 * p + 2] - queries[3 * q + 2]) ** 2;
      if (d < best) [best, result[q]] = [d, p];
    }
  }
  return result;
}
