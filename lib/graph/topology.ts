/**
 * The topology of a graph given as node index pairs (a skeleton's edges): the connected component of
 * every node and the cycle rank E - V + components, its number of independent cycles (every edge
 * counts, self-loops and repeated edges too, as in a skeleton's stats.cycles).
 */
import { UnionFind } from './union-find.ts';

export interface GraphTopology {
  /** Per node, its component's smallest node. */
  componentOf: Int32Array;
  components: number;
  cycleRank: number;
}

export function graphTopology(nodeCount: number, edges: ArrayLike<number>): GraphTopology {
  const sets = new UnionFind(nodeCount);
  for (let i = 0; i + 1 < edges.length; i += 2) sets.union(edges[i], edges[i + 1]);
  const componentOf = new Int32Array(nodeCount);
  let components = 0;
  for (let v = 0; v < nodeCount; v++) {
    componentOf[v] = sets.find(v);
    if (componentOf[v] === v) components++;
  }
  return { componentOf, components, cycleRank: (edges.length >> 1) - nodeCount + components };
}
