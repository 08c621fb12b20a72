// The bench's pure computations (bench/README.md says what each figure means): tip gap and own leaves
// against a ground-truth skeleton, radii from a method's vertex map, and the figures that sum a run up.
// Plain arrays in, numbers out: no files, no core.

/** A skeleton as the bench holds it: xyz per node, node index pairs. */
export interface Graph {
  nodes: ArrayLike<number>;
  edges: ArrayLike<number>;
}

/** A vertex map that cannot give radii (wrong length, a node index out of range): its message is one line for the table. */
export class VertexMapError extends Error {
  override name = 'VertexMapError';
}

export function median(values: number[]): number | null {
  if (!values.length) return null;
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
}

/** exp(mean(log x)): the mean of ratios that treats x and 1/x alike; null for none. */
export function geometricMean(values: number[]): number | null {
  if (!values.length) return null;
  return Math.exp(values.reduce((sum, x) => sum + Math.log(x), 0) / values.length);
}

/** Distinct neighbours per node (self-loops and repeated edges left out). */
function neighbours(nodeCount: number, edges: ArrayLike<number>): number[][] {
  const sets = Array.from({ length: nodeCount }, () => new Set<number>());
  for (let e = 0; e + 1 < edges.length; e += 2) {
    const [a, b] = [edges[e], edges[e + 1]];
    if (a === b) continue;
    sets[a].add(b);
    sets[b].add(a);
  }
  return sets.map((s) => [...s]);
}

/** The degree-1 nodes of a graph given as node and edge lists, except those in `except`. */
export function leafIndices(nodeCount: number, edges: ArrayLike<number>, except: number[] = []): number[] {
  return neighbours(nodeCount, edges).flatMap((n, i) => (n.length === 1 && !except.includes(i) ? [i] : []));
}

function pointOf(xyz: ArrayLike<number>, i: number): [number, number, number] {
  return [xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]];
}

function distance(p: ArrayLike<number>, q: ArrayLike<number>): number {
  return Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}

function segmentDistance(p: ArrayLike<number>, a: ArrayLike<number>, b: ArrayLike<number>): number {
  const d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const length2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const t = length2 > 0 ? Math.min(1, Math.max(0, ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]) / length2)) : 0;
  return distance(p, [a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]]);
}

/** Distance from p to the skeleton's polyline: its edges as segments, a node on no edge as a point (Infinity for an empty skeleton). */
export function distanceToSkeleton(p: ArrayLike<number>, skeleton: Graph): number {
  const nodeCount = skeleton.nodes.length / 3;
  const onEdge = new Uint8Array(nodeCount);
  let best = Infinity;
  for (let e = 0; e + 1 < skeleton.edges.length; e += 2) {
    const [a, b] = [skeleton.edges[e], skeleton.edges[e + 1]];
    onEdge[a] = onEdge[b] = 1;
    best = Math.min(best, segmentDistance(p, pointOf(skeleton.nodes, a), pointOf(skeleton.nodes, b)));
  }
  for (let i = 0; i < nodeCount; i++) if (!onEdge[i]) best = Math.min(best, distance(p, pointOf(skeleton.nodes, i)));
  return best;
}

/**
 * How far a reference skeleton given as points (WoodSKE's trees: dense points along the branches, no
 * edges) lies from a skeleton: the mean of each point's distance to it, in % of `diagonal`.
 */
export function meanDistanceToSkeleton(points: ArrayLike<number>, skeleton: Graph, diagonal: number): number {
  let sum = 0;
  const count = Math.floor(points.length / 3);
  for (let i = 0; i < count; i++) sum += distanceToSkeleton([points[3 * i], points[3 * i + 1], points[3 * i + 2]], skeleton);
  return (100 * sum) / count / diagonal;
}

export interface TipGap {
  /** Per tip: distance to the skeleton over the mesh's bounding-box diagonal. */
  gaps: number[];
  mean: number;
  max: number;
  /** Tips that got a skeleton leaf of their own within `leafReach` (see ownLeaves). */
  ownLeaves: number;
}

/**
 * How many tips get a leaf of their own within `reach`: (tip, leaf) pairs closer than `reach` are taken
 * by increasing distance, each tip and each leaf at most once, so two tips cannot share one leaf.
 */
export function ownLeaves(tips: ArrayLike<number>[], leaves: ArrayLike<number>[], reach: number): number {
  const pairs = tips.flatMap((tip, t) => leaves.flatMap((leaf, l) => {
    const d = distance(tip, leaf);
    return d <= reach ? [{ t, l, d }] : [];
  })).sort((x, y) => x.d - y.d);
  const [tipTaken, leafTaken] = [new Set<number>(), new Set<number>()];
  for (const { t, l } of pairs) {
    if (tipTaken.has(t) || leafTaken.has(l)) continue;
    tipTaken.add(t);
    leafTaken.add(l);
  }
  return tipTaken.size;
}

/** Skeleton leaves count as a tip's own when within this fraction of the diagonal. */
export const LEAF_REACH = 0.01;

/** The tip gap of a skeleton against ground-truth tips (null when there are no tips). */
export function tipGap(tips: ArrayLike<number>[], skeleton: Graph, diagonal: number): TipGap | null {
  if (!tips.length) return null;
  const gaps = tips.map((tip) => distanceToSkeleton(tip, skeleton) / diagonal);
  const leaves = leafIndices(skeleton.nodes.length / 3, skeleton.edges).map((i) => pointOf(skeleton.nodes, i));
  return {
    gaps,
    mean: gaps.reduce((a, b) => a + b, 0) / gaps.length,
    max: Math.max(...gaps),
    ownLeaves: ownLeaves(tips, leaves, LEAF_REACH * diagonal),
  };
}

export interface VertexMapRadii {
  radii: Float64Array;
  /** Nodes that own no vertex and took their neighbours' mean radius. */
  fromNeighbours: number;
  /** Nodes of components that own no vertex at all, which took the fallback radius. */
  fromFallback: number;
}

/**
 * Radii by a method's vertex map (LS's rule): a node's radius is the median distance from it to the
 * mesh vertices mapped to it (-1: unmapped). A node that owns none takes the mean radius of its
 * neighbours that have one, repeated until every node reached from an owning node is set; the nodes of
 * a component that owns no vertex at all take `fallback` (the first rule's radius; without it they
 * make the map unusable).
 */
export function vertexMapRadii(
  positions: ArrayLike<number>, skeleton: Graph, vertexToNode: ArrayLike<number>, fallback: ArrayLike<number> | null,
): VertexMapRadii {
  const vertexCount = positions.length / 3;
  const nodeCount = skeleton.nodes.length / 3;
  if (vertexToNode.length !== vertexCount) throw new VertexMapError(`map has ${vertexToNode.length} entries for ${vertexCount} vertices`);
  const owned: number[][] = Array.from({ length: nodeCount }, () => []);
  for (let v = 0; v < vertexCount; v++) {
    const node = vertexToNode[v];
    if (node === -1) continue;
    if (!(Number.isInteger(node) && node >= 0 && node < nodeCount)) throw new VertexMapError(`map sends vertex ${v} to node ${node} of ${nodeCount}`);
    owned[node].push(distance(pointOf(positions, v), pointOf(skeleton.nodes, node)));
  }
  const radii = new Float64Array(nodeCount).fill(NaN);
  owned.forEach((distances, i) => { if (distances.length) radii[i] = median(distances) as number; });

  const adjacent = neighbours(nodeCount, skeleton.edges);
  let fromNeighbours = 0;
  // One ring at a time, each from the radii set before it, so the result does not depend on node order.
  for (;;) {
    const ring = Array.from(radii).flatMap((r, i) => {
      if (!Number.isNaN(r)) return [];
      const set = adjacent[i].filter((n) => !Number.isNaN(radii[n]));
      return set.length ? [{ i, r: set.reduce((sum, n) => sum + radii[n], 0) / set.length }] : [];
    });
    if (!ring.length) break;
    for (const { i, r } of ring) radii[i] = r;
    fromNeighbours += ring.length;
  }
  const unset = Array.from(radii).flatMap((r, i) => (Number.isNaN(r) ? [i] : []));
  if (unset.length && !fallback) throw new VertexMapError(`${unset.length} nodes in components that own no vertex, and no other radius for them`);
  for (const i of unset) radii[i] = (fallback as ArrayLike<number>)[i];
  const fromFallback = unset.length;
  return { radii, fromNeighbours, fromFallback };
}

/**
 * A map written by a tool that numbers the mesh's vertices its own way, given with the positions of
 * the vertices it indexes, carried over to the mesh's own vertices by exact position (compared at
 * float precision, so that the same text read as float or double matches). Mesh vertices with no
 * counterpart get -1; vertices at the same position share one node, as the tool merged them.
 */
export function mapByPosition(positions: ArrayLike<number>, toolPositions: ArrayLike<number>, toolMap: ArrayLike<number>): Int32Array {
  if (toolPositions.length !== 3 * toolMap.length) throw new VertexMapError(`map has ${toolMap.length} entries for ${toolPositions.length / 3} positions`);
  const key = (xyz: ArrayLike<number>, i: number) => `${Math.fround(xyz[3 * i])} ${Math.fround(xyz[3 * i + 1])} ${Math.fround(xyz[3 * i + 2])}`;
  const nodeAt = new Map<string, number>();
  for (let i = 0; i < toolMap.length; i++) nodeAt.set(key(toolPositions, i), toolMap[i]);
  return Int32Array.from({ length: positions.length / 3 }, (_, v) => nodeAt.get(key(positions, v)) ?? -1);
}

export interface Comparison {
  /** Meshes where both methods were scored. */
  meshes: number;
  /** Of those, meshes where the first method's error is below the second's. */
  below: number;
  /** Geometric mean over those meshes of the first method's error over the second's (null for none). */
  geomean: number | null;
}

/** Pairs of errors (first method, second method) on the same meshes. */
export function compareErrors(pairs: [number, number][]): Comparison {
  return {
    meshes: pairs.length,
    below: pairs.filter(([a, b]) => a < b).length,
    geomean: geometricMean(pairs.map(([a, b]) => a / b)),
  };
}
