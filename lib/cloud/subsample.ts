/**
 * Subsampling of point clouds too large to compute on, Poisson-disk style: the points kept are spread
 * evenly whatever the density of the input (the dense overlaps of a scan thin out, sparse parts stay).
 *
 * The points are visited in an order shuffled from the seed, and one is kept unless a point kept
 * before lies within the radius r: that is mesh repair's weld run on the shuffled points, whose kept
 * points are exactly these. So any two points kept are more than r apart, and every point dropped has
 * one kept within r. The radius is searched for (a few runs of O(n) each) until the count lands
 * between (1 - COUNT_SLACK) x the target and the target. Pure TypeScript; the same cloud, target and
 * seed give the same points on every machine.
 */
import { random } from '../core/random.ts';
import { boundingBoxDiagonal, weld } from '../io/repair.ts';
import type { CloudArrays } from '../io/types.ts';

/** How far below the target the count may land: the search then stops. */
const COUNT_SLACK = 0.05;
/** Searches for the radius stop after this many runs, with the closest count at most the target. */
const MAX_RUNS = 16;

/** One run of the selection: its radius and which shuffled points it kept (`to[j] === j`). */
interface Run {
  radius: number;
  to: Int32Array;
  kept: number;
}

/** A subsample and the points it left out, each with the kept point that stands for it. */
export interface Subsample<C extends CloudArrays> {
  cloud: C;
  /** Input indices of the points left out, in a shuffled order (its first few are spread like all of them). */
  leftOut: Int32Array;
  /** For each point left out, the index in `cloud` of a kept point within the subsample's radius of it. */
  standIn: Int32Array;
  /** For each input point, its index in `cloud`, or its stand-in's when it was left out. */
  pointOf: Int32Array;
}

/**
 * At most `targetCount` points of a cloud with finite coordinates (those of checkCloud), in their
 * input order, with their normals; the cloud itself when it has no more points than that.
 */
export function subsampleCloud<C extends CloudArrays>(cloud: C, targetCount: number, seed: number): C {
  return subsample(cloud, targetCount, seed).cloud;
}

/** subsampleCloud, with the points left out and their stand-ins (the page draws them all). */
export function subsample<C extends CloudArrays>(cloud: C, targetCount: number, seed: number): Subsample<C> {
  const n = cloud.positions.length / 3;
  if (n <= targetCount) return { cloud, leftOut: new Int32Array(0), standIn: new Int32Array(0), pointOf: Int32Array.from({ length: n }, (_, i) => i) };
  const order = shuffled(n, seed);
  const positions = new Float64Array(3 * n);
  order.forEach((i, j) => positions.set(cloud.positions.subarray(3 * i, 3 * i + 3), 3 * j));
  const select = (radius: number): Run => {
    const { to, count } = weld(positions, radius);
    return { radius, to, kept: n - count };
  };

  const aim = (1 - COUNT_SLACK / 2) * targetCount;
  // Samples of a surface: about area / r^2 of them, the area being of the order of diagonal^2.
  let radius = boundingBoxDiagonal(cloud.positions) / Math.sqrt(targetCount);
  let below: Run | null = null;
  let above: Run | null = null;
  for (let run = 0; run < MAX_RUNS; run++) {
    const result = select(radius);
    if (result.kept <= targetCount) {
      if (!below || result.kept > below.kept) below = result;
      if (result.kept >= (1 - COUNT_SLACK) * targetCount) break;
    } else if (!above || result.kept < above.kept) {
      above = result;
    }
    radius = below && above ? between(above, below, aim) : radius * Math.sqrt(result.kept / aim);
  }
  // Only when every run kept too many (none does at a radius as large as the cloud).
  below ??= select(boundingBoxDiagonal(cloud.positions));

  // The kept points in input order and each one's place among them; those left out in the shuffled
  // order, so that any first few of them are spread like all of them.
  const isKept = new Uint8Array(n);
  order.forEach((i, j) => (isKept[i] = below.to[j] === j ? 1 : 0));
  const kept = new Int32Array(below.kept), placeOf = new Int32Array(n);
  for (let i = 0, k = 0; i < n; i++) {
    if (!isKept[i]) continue;
    placeOf[i] = k;
    kept[k++] = i;
  }
  const leftOut = new Int32Array(n - below.kept), standIn = new Int32Array(n - below.kept);
  for (let j = 0, l = 0; j < n; j++) {
    if (isKept[order[j]]) continue;
    leftOut[l] = order[j];
    standIn[l++] = placeOf[order[below.to[j]]]; // weld joined it to a kept point within the radius
  }
  leftOut.forEach((point, j) => (placeOf[point] = standIn[j]));
  return {
    cloud: { ...cloud, positions: gather(cloud.positions, kept, Float64Array), normals: cloud.normals && gather(cloud.normals, kept, Float32Array) },
    leftOut,
    standIn,
    pointOf: placeOf,
  };
}

/** 0 .. n-1 in the order of a Fisher-Yates shuffle drawn from the seed. */
function shuffled(n: number, seed: number): Int32Array {
  const next = random(seed);
  const order = new Int32Array(n);
  for (let i = 0; i < n; i++) order[i] = i;
  for (let i = n - 1; i > 0; i--) {
    const j = Math.floor(next() * (i + 1));
    const t = order[i];
    order[i] = order[j];
    order[j] = t;
  }
  return order;
}

/** The radius where the count would be `aim`, interpolated on log scales between two runs on either side. */
function between(above: Run, below: Run, aim: number): number {
  const t = Math.log(above.kept / aim) / Math.log(above.kept / below.kept);
  return above.radius * Math.pow(below.radius / above.radius, t);
}

function gather<T extends Float64Array | Float32Array>(values: T, points: Int32Array, Type: new (n: number) => T): T {
  const out = new Type(3 * points.length);
  points.forEach((i, p) => out.set(values.subarray(3 * i, 3 * i + 3), 3 * p));
  return out;
}
