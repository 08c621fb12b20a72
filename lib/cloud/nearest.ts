/**
 * The k nearest other points of every point of a cloud, on a k-d tree (balanced, implicit: the median
 * of each range splits it across the widest axis of the range's box). Pure TypeScript on typed arrays:
 * the core has its own search (geometry-central's), but the point-cloud checks run before it is loaded.
 */

/** Points per leaf: below this a range is scanned point by point. */
const LEAF = 8;

export interface Neighbours {
  /** k per point: its nearest other points, nearest first. */
  index: Int32Array;
  /** k per point: their distances. */
  distance: Float64Array;
}

/** Each point's `k` nearest other points (k < the point count). Equal distances: the lower index first. */
export function nearestNeighbours(positions: Float64Array, k: number): Neighbours {
  const n = positions.length / 3;
  if (!(k >= 1 && k < n)) throw new RangeError(`nearestNeighbours: k = ${k} for ${n} points`);
  const order = new Int32Array(n);
  for (let i = 0; i < n; i++) order[i] = i;
  const axisAt = new Int8Array(n); // the split axis of the range whose median sits at this place
  const box = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  for (let i = 0; i < 3 * n; i++) {
    box[i % 3] = Math.min(box[i % 3], positions[i]);
    box[3 + (i % 3)] = Math.max(box[3 + (i % 3)], positions[i]);
  }
  build(positions, order, axisAt, 0, n, box);

  const index = new Int32Array(n * k), distance = new Float64Array(n * k);
  const heap = new Heap(k);
  // Ranges still to search, with the squared distance from the point to their side of the split: the
  // tree is about log2(n / LEAF) deep, and each level leaves one range waiting.
  const rangeLo = new Int32Array(64), rangeHi = new Int32Array(64), rangeGap = new Float64Array(64);
  // The points in the tree's order: leaves are contiguous, and consecutive queries are close in space.
  const xyz = new Float64Array(3 * n);
  for (let j = 0; j < n; j++) xyz.set(positions.subarray(3 * order[j], 3 * order[j] + 3), 3 * j);
  for (let t = 0; t < n; t++) {
    const p = order[t], px = xyz[3 * t], py = xyz[3 * t + 1], pz = xyz[3 * t + 2];
    heap.size = 0;
    rangeLo[0] = 0, rangeHi[0] = n, rangeGap[0] = 0;
    let top = 1;
    while (top > 0) {
      top--;
      const lo = rangeLo[top], hi = rangeHi[top];
      if (heap.size === k && rangeGap[top] > heap.worst()) continue;
      if (hi - lo <= LEAF) {
        for (let j = lo; j < hi; j++) {
          if (j === t) continue;
          const dx = xyz[3 * j] - px, dy = xyz[3 * j + 1] - py, dz = xyz[3 * j + 2] - pz;
          heap.offer(order[j], dx * dx + dy * dy + dz * dz);
        }
        continue;
      }
      const mid = (lo + hi) >> 1, axis = axisAt[mid];
      const dx = xyz[3 * mid] - px, dy = xyz[3 * mid + 1] - py, dz = xyz[3 * mid + 2] - pz;
      if (mid !== t) heap.offer(order[mid], dx * dx + dy * dy + dz * dz);
      const gap = axis === 0 ? dx : axis === 1 ? dy : dz; // > 0: the point is on the low side of the median
      // The far half waits below the near one, which is searched first.
      rangeLo[top] = gap > 0 ? mid + 1 : lo, rangeHi[top] = gap > 0 ? hi : mid, rangeGap[top++] = gap * gap;
      rangeLo[top] = gap > 0 ? lo : mid + 1, rangeHi[top] = gap > 0 ? mid : hi, rangeGap[top++] = 0;
    }
    heap.drain(index, distance, p * k);
  }
  return { index, distance };
}

/** The k best candidates so far in a max-heap of squared distances, the worst at the top. */
class Heap {
  size = 0;
  private readonly d2: Float64Array;
  private readonly at: Int32Array;

  constructor(private readonly k: number) {
    this.d2 = new Float64Array(k);
    this.at = new Int32Array(k);
  }

  worst(): number {
    return this.d2[0];
  }

  offer(i: number, d2: number): void {
    const { k } = this;
    if (this.size === k) {
      if (!worse(this.d2[0], this.at[0], d2, i)) return;
      this.siftDown(0, d2, i, k);
      return;
    }
    let place = this.size++;
    while (place > 0) {
      const up = (place - 1) >> 1;
      if (!worse(d2, i, this.d2[up], this.at[up])) break;
      this.d2[place] = this.d2[up], this.at[place] = this.at[up], place = up;
    }
    this.d2[place] = d2, this.at[place] = i;
  }

  /** Writes the candidates nearest first (distances, not squared) from `offset`, emptying the heap. */
  drain(index: Int32Array, distance: Float64Array, offset: number): void {
    for (let last = this.size - 1; last >= 0; last--) {
      index[offset + last] = this.at[0];
      distance[offset + last] = Math.sqrt(this.d2[0]);
      this.siftDown(0, this.d2[last], this.at[last], last);
    }
    this.size = 0;
  }

  /** Puts (d2, i) at `place` of a heap of `size`, moving it down past better children. */
  private siftDown(place: number, d2: number, i: number, size: number): void {
    for (;;) {
      const left = 2 * place + 1, right = left + 1;
      if (left >= size) break;
      const child = right < size && worse(this.d2[right], this.at[right], this.d2[left], this.at[left]) ? right : left;
      if (!worse(this.d2[child], this.at[child], d2, i)) break;
      this.d2[place] = this.d2[child], this.at[place] = this.at[child], place = child;
    }
    this.d2[place] = d2, this.at[place] = i;
  }
}

/** Ranked by distance, then index: a total order, so the neighbours do not depend on the search's path. */
function worse(d2: number, i: number, e2: number, j: number): boolean {
  return d2 > e2 || (d2 === e2 && i > j);
}

/**
 * Arranges order[lo, hi) as a k-d tree: the median along the widest axis of the range's box at the
 * middle, each half likewise with the box cut there (the box, not the points' own extent: no pass over
 * the points per range).
 */
function build(positions: Float64Array, order: Int32Array, axisAt: Int8Array, lo: number, hi: number, box: number[]): void {
  if (hi - lo <= LEAF) return;
  const extent = [box[3] - box[0], box[4] - box[1], box[5] - box[2]];
  const axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0 : extent[1] >= extent[2] ? 1 : 2;
  const mid = (lo + hi) >> 1;
  select(positions, order, axis, lo, hi - 1, mid);
  axisAt[mid] = axis;
  const split = positions[3 * order[mid] + axis];
  const low = box.slice(), high = box.slice();
  low[3 + axis] = split, high[axis] = split;
  build(positions, order, axisAt, lo, mid, low);
  build(positions, order, axisAt, mid + 1, hi, high);
}

/** Quickselect: order[target] becomes the point a sort of order[lo..hi] by the axis would put there. */
function select(positions: Float64Array, order: Int32Array, axis: number, lo: number, hi: number, target: number): void {
  const key = (j: number) => positions[3 * order[j] + axis];
  while (hi > lo) {
    const pivot = key((lo + hi) >> 1);
    let i = lo, j = hi;
    while (i <= j) {
      while (key(i) < pivot) i++;
      while (key(j) > pivot) j--;
      if (i <= j) {
        const t = order[i];
        order[i] = order[j], order[j] = t;
        i++, j--;
      }
    }
    if (target <= j) hi = j;
    else if (target >= i) lo = i;
    else return;
  }
}
