/**
 * Union-find (disjoint sets) over 0 .. size - 1 with path halving. A set's representative is its
 * smallest member, whatever the order of the unions. Shared by mesh repair (the fans of corners around
 * a vertex), graph topology (./topology.ts) and scripts/results.ts (the pieces of a region).
 */
export class UnionFind {
  private readonly parent: Int32Array;

  constructor(size: number) {
    this.parent = new Int32Array(size);
    for (let i = 0; i < size; i++) this.parent[i] = i;
  }

  /** The smallest member of x's set. */
  find(x: number): number {
    const { parent } = this;
    while (parent[x] !== x) x = parent[x] = parent[parent[x]];
    return x;
  }

  union(a: number, b: number): void {
    const ra = this.find(a), rb = this.find(b);
    if (ra !== rb) this.parent[Math.max(ra, rb)] = Math.min(ra, rb);
  }
}
