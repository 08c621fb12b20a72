// The bench's pure figures (bench/metrics.ts) on inputs small enough to work out by hand.
import { describe, expect, it } from 'vitest';
import {
  compareErrors, distanceToSkeleton, geometricMean, leafIndices, mapByPosition, meanDistanceToSkeleton, ownLeaves, tipGap, VertexMapError,
  vertexMapRadii,
} from '../../bench/metrics.ts';

// A 3-segment polyline along x from 0 to 3, then a lone node at (10, 0, 0): nodes 0-1-2-3 and 4.
const polyline = {
  nodes: [0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 10, 0, 0],
  edges: [0, 1, 1, 2, 2, 3],
};

describe('distance to a skeleton', () => {
  it('measures to the segments, not only to the nodes', () => {
    expect(distanceToSkeleton([1.5, 2, 0], polyline)).toBeCloseTo(2, 12);
    expect(distanceToSkeleton([-3, 4, 0], polyline)).toBeCloseTo(5, 12); // past the end: to node 0
  });
  it('counts a node on no edge as a point', () => {
    expect(distanceToSkeleton([10, 0, 1], polyline)).toBeCloseTo(1, 12);
  });
  it('is infinite for an empty skeleton', () => {
    expect(distanceToSkeleton([0, 0, 0], { nodes: [], edges: [] })).toBe(Infinity);
  });
  it('of reference points, is their mean distance in % of the diagonal', () => {
    // 2 above the segments, 1 beside the lone node, 0 on the polyline: mean 1, a diagonal of 20 -> 5%.
    expect(meanDistanceToSkeleton([1.5, 2, 0, 10, 0, 1, 2.5, 0, 0], polyline, 20)).toBeCloseTo(5, 12);
  });
});

describe('leaves', () => {
  it('are the nodes of degree 1, self-loops and repeated edges left out', () => {
    expect(leafIndices(5, polyline.edges)).toEqual([0, 3]);
    expect(leafIndices(4, [0, 1, 1, 2, 2, 3, 3, 3, 0, 1])).toEqual([0, 3]);
    expect(leafIndices(4, polyline.edges, [0])).toEqual([3]);
  });
  it('serve one tip each, the closest pair first', () => {
    // Two tips near leaf 3, one a bit closer: only that one gets it; the tip near leaf 0 gets leaf 0.
    const leaves = [[0, 0, 0], [3, 0, 0]];
    expect(ownLeaves([[3.05, 0, 0], [3.02, 0, 0], [0, 0.01, 0]], leaves, 0.1)).toBe(2);
    expect(ownLeaves([[3.5, 0, 0]], leaves, 0.1)).toBe(0);
  });
  it('are matched by increasing distance over all pairs, not tip by tip', () => {
    // Tip 0's nearest leaf is 1 (0.45), but tip 1 is nearer to it (0.3) and can have no other: taken
    // pair by pair, tip 0 falls back to leaf 0 (0.55) and both tips have a leaf.
    expect(ownLeaves([[0.55, 0, 0], [1.3, 0, 0]], [[0, 0, 0], [1, 0, 0]], 0.6)).toBe(2);
  });
});

describe('tip gap', () => {
  it('is the distance over the diagonal, mean and max, with own leaves within 1% of the diagonal', () => {
    // Diagonal 100: within reach (1) of leaf 3, within reach of the polyline's middle but no leaf there, far from all.
    const gap = tipGap([[3.5, 0, 0], [1.5, 0.5, 0], [3, 20, 0]], polyline, 100);
    expect(gap?.gaps.map((g) => Number(g.toFixed(12)))).toEqual([0.005, 0.005, 0.2]);
    expect(gap?.mean).toBeCloseTo(0.07, 12);
    expect(gap?.max).toBeCloseTo(0.2, 12);
    expect(gap?.ownLeaves).toBe(1);
  });
  it('is null without tips', () => {
    expect(tipGap([], polyline, 1)).toBeNull();
  });
});

describe('vertex-map radii', () => {
  // Vertices around node 0 at distances 1, 2, 4; around node 2 at 3; node 1 owns none (a branch node);
  // node 3 owns none and has only node 2 as neighbour; node 4 is alone and owns none.
  const positions = [0, 1, 0, 0, 0, 2, 0, -4, 0, 2, 3, 0];
  const fallback = [9, 9, 9, 9, 7];
  it('takes the median distance to the owned vertices, and the neighbours\' mean for nodes that own none', () => {
    const { radii, fromNeighbours, fromFallback } = vertexMapRadii(positions, polyline, [0, 0, 0, 2], fallback);
    expect(Array.from(radii)).toEqual([2, 2.5, 3, 3, 7]);
    expect([fromNeighbours, fromFallback]).toEqual([2, 1]);
  });
  it('fills rings outward: a node two edges from any owner takes its neighbour\'s filled radius', () => {
    const { radii } = vertexMapRadii(positions, polyline, [0, 0, 0, -1], fallback);
    expect(Array.from(radii)).toEqual([2, 2, 2, 2, 7]);
  });
  it('rejects a map of the wrong length or with a node out of range', () => {
    expect(() => vertexMapRadii(positions, polyline, [0, 0, 0], fallback)).toThrow(new VertexMapError('map has 3 entries for 4 vertices'));
    expect(() => vertexMapRadii(positions, polyline, [0, 0, 0, 5], fallback)).toThrow(VertexMapError);
  });
  it('needs the fallback only for components that own no vertex', () => {
    const connected = { nodes: polyline.nodes.slice(0, 12), edges: polyline.edges };
    expect(Array.from(vertexMapRadii(positions, connected, [0, 0, 0, 2], null).radii)).toEqual([2, 2.5, 3, 3]);
    expect(() => vertexMapRadii(positions, polyline, [0, 0, 0, 2], null)).toThrow(new VertexMapError('1 nodes in components that own no vertex, and no other radius for them'));
  });
  it('carries a map in another vertex order over by position', () => {
    // The tool has the mesh's vertices 2, 0, 1 (vertex 3 missing) and merged nothing.
    const tool = [0, -4, 0, 0, 1, 0, 0, 0, 2];
    expect(Array.from(mapByPosition(positions, tool, [5, 6, 7]))).toEqual([6, 7, 5, -1]);
  });
});

describe('summary figures', () => {
  it('geometric mean', () => {
    expect(geometricMean([0.5, 2])).toBeCloseTo(1, 12);
    expect(geometricMean([2, 8])).toBeCloseTo(4, 12);
    expect(geometricMean([])).toBeNull();
  });
  it('counts meshes where the first error is below the second and their geometric mean ratio', () => {
    const c = compareErrors([[1, 2], [3, 3], [4, 1]]);
    expect([c.meshes, c.below]).toEqual([3, 1]);
    expect(c.geomean).toBeCloseTo(Math.cbrt(0.5 * 1 * 4), 12);
  });
});
