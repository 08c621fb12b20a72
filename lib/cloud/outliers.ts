/**
 * Stray points of a scan (outliers): points that lie apart from the sampled surface, which CSCD-PC would
 * otherwise join to it by long edges of its neighbourhood graph and tufted triangulation (shortcuts for
 * the geodesic distances: bob_clean with 100 points strewn over its bounding box got 2.3 times its error).
 *
 * A point is an outlier when its nearest other point is more than OUTLIER_RATIO times as far as the
 * narrowest neighbourhood around it: the distance to the OUTLIER_NEIGHBOURS-th nearest point, the
 * neighbourhood's width, taken at the point's OUTLIER_NEIGHBOURS nearest points, and the smallest of
 * those. Relative, so a cloud's sparse parts are no outliers (the width there is wide too), and a point
 * among others of its kind (a scan line across a twig) has a near neighbour: only points that stand
 * alone go (a pair of strays within 3 widths of each other stays, as the fragments of a twig that a tree
 * scan hit with two or three beams do). Measured (docs/pointcloud.md, "Stray points"): on every shared
 * cloud and the clouds from other meshes, clean, noisy up to 3% of the diagonal, non-uniform and the two
 * tree scans, the ratio stays below 2.4, so no point of theirs goes; of points strewn over the bounding
 * box, those farther from the surface than a few spacings go, all but some lying nearer each other.
 */
import { nearestNeighbours } from './nearest.ts';

/** The neighbourhood whose width is compared (its k). */
export const OUTLIER_NEIGHBOURS = 16;
/** How many times the narrowest nearby width a point's nearest neighbour may be away. */
export const OUTLIER_RATIO = 3;
/** Rounds at most: each one costs a neighbour search over the cloud. */
const MAX_ROUNDS = 8;

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
    const points = new Float64Array(3 * left.length);
    left.forEach((p, j) => points.set(positions.subarray(3 * p, 3 * p + 3), 3 * j));
    const found = standingAlone(points);
    if (found.length === 0) break;
    for (const j of found) outlier[left[j]] = 1;
    left = left.filter((p) => !outlier[p]);
  }
  return outlier;
}

/** One round: the points whose nearest neighbour is more than OUTLIER_RATIO narrowest widths away. */
function standingAlone(positions: Float64Array): number[] {
  const n = positions.length / 3, k = OUTLIER_NEIGHBOURS;
  const { index, distance } = nearestNeighbours(positions, k);
  const found: number[] = [];
  for (let p = 0; p < n; p++) {
    let narrowest = Infinity;
    for (let j = 0; j < k; j++) narrowest = Math.min(narrowest, distance[index[p * k + j] * k + k - 1]);
    if (distance[p * k] > OUTLIER_RATIO * narrowest) found.push(p);
  }
  return found;
}
