/**
 * Stray points of a scan (outliers): points that lie apart from the sampled surface, which CSCD-PC would
 * otherwise join to it by long edges of its neighbourhood graph and tufted triangulation (shortcuts for
 * the geodesic distances: 100 points strewn over the bounding box cost bob_clean 1.3-2 times its error,
 * deer_noise1.0 2-7 times and three stray cycles; docs/pointcloud.md, "Stray points").
 *
 * A point is an outlier when its nearest other point is more than OUTLIER_RATIO times as far as the
 * narrowest neighbourhood around it: the distance to the OUTLIER_NEIGHBOURS-th nearest point, the
 * neighbourhood's width, taken at the point's OUTLIER_NEIGHBOURS nearest points, and the smallest of
 * those. Relative, so a cloud's sparse parts are no outliers (the width there is wide too). So are two
 * or three points that stand apart together, each within that reach of another of them but more than a
 * width from it: strays that happen to lie near each other. Closer, they are a fragment sampled as
 * densely as the surface (a twig a tree scan hit with two or three beams) and stay. Measured
 * (docs/pointcloud.md, "Stray points"): on every shared cloud and the clouds from other meshes, clean,
 * noisy up to 3% of the diagonal, non-uniform and the two tree scans, no point goes (the ratio stays below
 * 2.4, the tree scans' fragments are 0.14-0.71 widths across); of points strewn over the bounding box,
 * those farther from the surface than a few spacings go.
 */
import { UnionFind } from '../graph/union-find.ts';
import { nearestNeighbours } from './nearest.ts';

/** The neighbourhood whose width is compared (its k). */
export const OUTLIER_NEIGHBOURS = 16;
/** How many times the narrowest nearby width a point's nearest neighbour may be away. */
export const OUTLIER_RATIO = 3;
/** Rounds at most: each one costs a neighbour search over the cloud. */
const MAX_ROUNDS = 8;
/** The largest group of points that stand alone together and are removed, if they lie apart. */
const MAX_GROUP = 3;

/**
 * Which points of a cloud are outliers (1). Rounds of the rule above on the points left, until one finds
 * none (at most MAX_ROUNDS): a stray whose nearest point, or one whose narrow neighbourhood, was another
 * stray may stand alone once that one is gone. None when the cloud has too few points for the rule.
 */
export function findOutliers(positions: Float64Array): Uint8Array {
  const n = positions.length / 3;
  const outlier = new Uint8Array(n);
  let left = Int32Array.from({ length: n }, (_, i) => i);
  for (let round = 0; round < MAX_ROUNDS && left.length > OUTLIER_NEIGHBOURS; round++) {
    let points = positions;
    if (left.length < n) {
      points = new Float64Array(3 * left.length);
      left.forEach((p, j) => points.set(positions.subarray(3 * p, 3 * p + 3), 3 * j));
    }
    const found = standingAlone(points);
    if (found.length === 0) break;
    for (const j of found) outlier[left[j]] = 1;
    left = left.filter((p) => !outlier[p]);
  }
  return outlier;
}

/**
 * One round: the points that stand alone, and the groups of up to MAX_GROUP that stand alone together.
 * A point stands alone when its nearest is more than OUTLIER_RATIO times the narrowest width around it
 * away. The others are joined to those of their nearest within that reach (points standing alone left
 * out); a group of at most MAX_GROUP joined only among themselves goes when each of its points is more
 * than a width from its nearest: closer, it is a fragment sampled as densely as the surface.
 */
function standingAlone(positions: Float64Array): number[] {
  const n = positions.length / 3, k = OUTLIER_NEIGHBOURS;
  const { index, distance } = nearestNeighbours(positions, k);
  const narrowest = new Float64Array(n).fill(Infinity);
  for (let p = 0; p < n; p++) {
    for (let j = 0; j < k; j++) narrowest[p] = Math.min(narrowest[p], distance[index[p * k + j] * k + k - 1]);
  }
  const alone = new Uint8Array(n);
  for (let p = 0; p < n; p++) alone[p] = distance[p * k] > OUTLIER_RATIO * narrowest[p] ? 1 : 0;
  const groups = new UnionFind(n);
  for (let p = 0; p < n; p++) {
    if (alone[p]) continue;
    const reach = OUTLIER_RATIO * narrowest[p];
    for (let j = 0; j < k && distance[p * k + j] <= reach; j++) {
      const q = index[p * k + j];
      if (!alone[q]) groups.union(p, q);
    }
  }
  // Each group's first MAX_GROUP + 1 points: enough to tell a small group from the rest.
  const members = new Map<number, number[]>();
  const found: number[] = [];
  for (let p = 0; p < n; p++) {
    if (alone[p]) {
      found.push(p);
      continue;
    }
    const root = groups.find(p), list = members.get(root);
    if (!list) members.set(root, [p]);
    else if (list.length <= MAX_GROUP) list.push(p);
  }
  for (const group of members.values()) {
    if (group.length > 1 && group.length <= MAX_GROUP && group.every((p) => distance[p * k] > narrowest[p])) found.push(...group);
  }
  return found;
}
