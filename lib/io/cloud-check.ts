/**
 * Point-cloud checks on load, the counterpart of mesh repair (repair.ts): what can be mended is mended
 * and said, one sentence each; what cannot is refused with a MeshFormatError. Pure TypeScript on typed
 * arrays, shared by the CLI and the page's worker.
 *
 * In order:
 * 1. remove points with a non-finite coordinate (NaN or infinity). A mesh refuses them only on a face,
 *    where no surface can do without them, and removes unused ones as unreferenced vertices; no point
 *    of a cloud holds anything else up, so they are all like the latter. All of them non-finite is refused;
 * 2. normals: a non-finite or zero normal makes the whole cloud go without normals (a cloud has
 *    normals for every point or for none); normals further than UNIT_TOLERANCE from unit length are
 *    scaled to it;
 * 3. merge duplicate points, closer than DUPLICATE_TOLERANCE x the bounding-box diagonal: each joins
 *    the first earlier point in reach, whose position is kept; their normals are summed and scaled to unit length;
 * 4. remove outliers, points that stand alone away from the others (lib/cloud/outliers.ts), unless
 *    the settings say not to (a mesh's vertices);
 * 5. refuse a cloud of k points or fewer, k being the neighbour count: every point needs k others;
 * 6. refuse a cloud with no thickness (all points on a line or a plane), from the covariance's
 *    eigenvalues: the spread across the line or plane below FLAT_TOLERANCE of the spread along it.
 *
 * A cloud that needs none of this comes back as the very same object. Otherwise the points left keep
 * their order (the first of duplicates stands for them) and `pointMap` says where each input point went.
 */
import { findOutliers, OUTLIER_NEIGHBOURS, OUTLIER_RATIO } from '../cloud/outliers.ts';
import { boundingBoxDiagonal, count, weld } from './repair.ts';
import { MeshFormatError, type CloudArrays } from './types.ts';

/** Merging reach, relative to the bounding-box diagonal: only points equal up to rounding of their coordinates. */
export const DUPLICATE_TOLERANCE = 1e-9;
/**
 * Flatness, as the ratio of standard deviations across and along: float32 rounding of a flat cloud
 * placed up to 100 times its size from the origin stays 10 times below it; a sheet of paper is 3 times above it.
 */
export const FLAT_TOLERANCE = 1e-4;
/** Normals written as float32 or with 4 decimals are unit vectors to within this. */
const UNIT_TOLERANCE = 1e-3;

export interface CloudCheckResult<C extends CloudArrays> {
  /** The input object when nothing was done, else a copy with the cleaned arrays. */
  cloud: C;
  /** One sentence per change made, with counts; empty when the cloud was returned as it came. */
  repairs: string[];
  /** Index of every input point in the cleaned cloud, -1 for removed ones. */
  pointMap: Int32Array;
}

/** What the checks may do besides what they always do. */
export interface CloudCheckSettings {
  /** Remove outliers (lib/cloud/outliers.ts): on for scans; off for a mesh's vertices, which lie on its surface by construction. */
  outliers: boolean;
}

export function checkCloud<C extends CloudArrays>(cloud: C, neighbours: number, settings: CloudCheckSettings = { outliers: true }): CloudCheckResult<C> {
  const input = cloud.positions.length / 3;
  const repairs: string[] = [];
  const finite = finitePoints(cloud.positions);
  if (finite.count === 0) {
    throw new MeshFormatError(`all ${count(input, 'point has', 'points have')} a non-finite coordinate (NaN or infinity)`);
  }
  if (finite.count < input) repairs.push(`removed ${count(input - finite.count, 'point', 'points')} with a non-finite coordinate (NaN or infinity)`);

  let normals = cloud.normals;
  const badNormals = normals ? unusableNormals(normals, finite.used) : 0;
  if (badNormals > 0) {
    normals = null;
    repairs.push(`dropped the normals: ${count(badNormals, 'point has', 'points have')} a non-finite or zero normal`);
  }

  const welded = weld(cloud.positions, DUPLICATE_TOLERANCE * boundingBoxDiagonal(cloud.positions, finite.used), finite.used);
  if (welded.count > 0) {
    repairs.push(`merged ${count(welded.count, 'duplicate point', 'duplicate points')} (closer than ${DUPLICATE_TOLERANCE.toExponential()} of the bounding-box diagonal)${normals ? ', averaging their normals' : ''}`);
  }

  // Each point kept is the first of its duplicates (weld keeps the lowest index), unless it stands alone.
  const firsts: number[] = [];
  for (let i = 0; i < input; i++) if (finite.used[i] && welded.to[i] === i) firsts.push(i);
  const stray = settings.outliers
    ? findOutliers(firsts.length === input ? cloud.positions : gatherPoints(cloud.positions, firsts))
    : new Uint8Array(firsts.length);
  const strayCount = stray.reduce((sum, s) => sum + s, 0);
  if (strayCount > 0) {
    repairs.push(
      `removed ${count(strayCount, 'stray point', 'stray points')} (alone or in twos and threes, more than ${OUTLIER_RATIO} times as far from the other points as those are from their ${OUTLIER_NEIGHBOURS}th nearest)`,
    );
  }
  const pointMap = new Int32Array(input).fill(-1);
  const keptPoints: number[] = [];
  firsts.forEach((i, j) => {
    if (!stray[j]) pointMap[i] = keptPoints.push(i) - 1;
  });
  for (let i = 0; i < input; i++) if (finite.used[i]) pointMap[i] = pointMap[welded.to[i]];
  const kept = keptPoints.length;
  const positions = kept === input ? cloud.positions : gatherPoints(cloud.positions, keptPoints);
  if (normals) {
    const merged = mergeNormals(normals, pointMap, keptPoints);
    normals = merged.normals;
    if (merged.scaled > 0) repairs.push(`scaled ${count(merged.scaled, 'normal', 'normals')} to unit length`);
  }

  if (kept <= neighbours) {
    const left = kept === input ? '' : ` (of ${input} in the file)`;
    throw new MeshFormatError(
      `the cloud has ${count(kept, 'point', 'points')}${left}, too few for the neighbour count k = ${neighbours}: every point needs k others`,
    );
  }
  checkThickness(positions);

  if (repairs.length === 0) return { cloud, repairs, pointMap };
  return { cloud: { ...cloud, positions, normals }, repairs, pointMap };
}

/** The positions of the given points, in that order. */
function gatherPoints(positions: Float64Array, points: number[]): Float64Array {
  const out = new Float64Array(3 * points.length);
  points.forEach((i, p) => out.set(positions.subarray(3 * i, 3 * i + 3), 3 * p));
  return out;
}

/** Which points have three finite coordinates, and how many. */
function finitePoints(positions: Float64Array): { used: Uint8Array; count: number } {
  const used = new Uint8Array(positions.length / 3);
  let finite = 0;
  for (let i = 0; i < used.length; i++) {
    if (Number.isFinite(positions[3 * i]) && Number.isFinite(positions[3 * i + 1]) && Number.isFinite(positions[3 * i + 2])) {
      used[i] = 1;
      finite++;
    }
  }
  return { used, count: finite };
}

/** How many of the finite points have a normal that gives no direction. */
function unusableNormals(normals: Float32Array, used: Uint8Array): number {
  let bad = 0;
  for (let i = 0; i < used.length; i++) {
    const length = Math.hypot(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
    if (used[i] && !(length > 0 && Number.isFinite(length))) bad++;
  }
  return bad;
}

/**
 * The normal of each point kept: the sum of its duplicates' normals scaled to unit length, or its own,
 * scaled when further from unit length than UNIT_TOLERANCE (`scaled` counts those).
 */
function mergeNormals(normals: Float32Array, pointMap: Int32Array, keptPoints: number[]): { normals: Float32Array; scaled: number } {
  const kept = keptPoints.length;
  const sums = new Float64Array(3 * kept);
  const members = new Int32Array(kept);
  for (let i = 0; i < pointMap.length; i++) {
    const to = pointMap[i];
    if (to < 0) continue;
    members[to]++;
    for (let k = 0; k < 3; k++) sums[3 * to + k] += normals[3 * i + k];
  }
  const out = new Float32Array(3 * kept);
  let scaled = 0;
  for (let p = 0; p < kept; p++) {
    const length = Math.hypot(sums[3 * p], sums[3 * p + 1], sums[3 * p + 2]);
    const single = members[p] === 1;
    if (single && Math.abs(length - 1) <= UNIT_TOLERANCE) {
      out.set(sums.subarray(3 * p, 3 * p + 3), 3 * p);
      continue;
    }
    if (single) scaled++;
    // Opposite normals of duplicates cancel out: the first one's direction stands.
    const sum = length > 0 ? sums.subarray(3 * p, 3 * p + 3) : normals.subarray(3 * keptPoints[p], 3 * keptPoints[p] + 3);
    const norm = Math.hypot(sum[0], sum[1], sum[2]);
    for (let k = 0; k < 3; k++) out[3 * p + k] = sum[k] / norm;
  }
  return { normals: out, scaled };
}

/** Refuses points that lie on a line or a plane (eigenvalues of their covariance). */
function checkThickness(positions: Float64Array): void {
  const n = positions.length / 3;
  const [along, second, across] = covarianceEigenvalues(positions);
  const points = count(n, 'point', 'points');
  const why = `a point cloud needs thickness in all three dimensions to have a curve skeleton`;
  if (Math.sqrt(Math.max(0, second) / along) < FLAT_TOLERANCE) {
    throw new MeshFormatError(`all ${points} lie on one line (their spread across it is below ${FLAT_TOLERANCE.toExponential()} of their spread along it): ${why}`);
  }
  if (Math.sqrt(Math.max(0, across) / along) < FLAT_TOLERANCE) {
    throw new MeshFormatError(`all ${points} lie on one plane (their spread across it is below ${FLAT_TOLERANCE.toExponential()} of their spread along it): ${why}`);
  }
}

/** Eigenvalues of the points' covariance matrix, largest first (the closed form for symmetric 3x3 matrices). */
function covarianceEigenvalues(positions: Float64Array): [number, number, number] {
  const n = positions.length / 3;
  const mean = [0, 0, 0];
  for (let i = 0; i < n; i++) for (let k = 0; k < 3; k++) mean[k] += positions[3 * i + k] / n;
  // About the mean, so that a cloud far from the origin loses no precision.
  let xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
  for (let i = 0; i < n; i++) {
    const x = positions[3 * i] - mean[0], y = positions[3 * i + 1] - mean[1], z = positions[3 * i + 2] - mean[2];
    xx += x * x; yy += y * y; zz += z * z; xy += x * y; xz += x * z; yz += y * z;
  }
  const offDiagonal = xy * xy + xz * xz + yz * yz;
  if (offDiagonal === 0) {
    const diagonal = [xx / n, yy / n, zz / n].sort((a, b) => b - a);
    return [diagonal[0], diagonal[1], diagonal[2]];
  }
  // Smith (1961): the eigenvalues are q + 2p cos(phi + 2 pi j / 3) for the shifted, scaled matrix B.
  const q = (xx + yy + zz) / 3;
  const p = Math.sqrt(((xx - q) ** 2 + (yy - q) ** 2 + (zz - q) ** 2 + 2 * offDiagonal) / 6);
  const bxx = (xx - q) / p, byy = (yy - q) / p, bzz = (zz - q) / p, bxy = xy / p, bxz = xz / p, byz = yz / p;
  const halfDeterminant = (bxx * (byy * bzz - byz * byz) - bxy * (bxy * bzz - byz * bxz) + bxz * (bxy * byz - byy * bxz)) / 2;
  const phi = Math.acos(Math.min(1, Math.max(-1, halfDeterminant))) / 3;
  const largest = q + 2 * p * Math.cos(phi);
  const smallest = q + 2 * p * Math.cos(phi + (2 * Math.PI) / 3);
  return [largest / n, (3 * q - largest - smallest) / n, smallest / n];
}
