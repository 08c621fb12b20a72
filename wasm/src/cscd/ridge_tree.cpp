#include "cscd/ridge_tree.h"

#include "cscd/union_find.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <utility>

namespace cscd {

size_t CutLocus::components() const {
  UnionFind sets(vertices.size());
  for (const auto& e : edges) sets.unite(e[0], e[1]);
  size_t count = 0;
  for (size_t i = 0; i < vertices.size(); i++)
    if (sets.find(i) == i) count++;
  return count;
}

size_t treeParent(const NeighbourGraph& graph, const std::vector<size_t>& parentEdge, size_t v) {
  if (parentEdge[v] == kNoParent) return kNoParent;
  const auto& ends = graph.edgeVertices[parentEdge[v]];
  return ends[0] == v ? ends[1] : ends[0];
}

double smallestCosine(const std::vector<std::array<double, 2>>& ring) {
  double smallest = 1;
  for (size_t i = 0; i < ring.size(); i++)
    for (size_t j = i + 1; j < ring.size(); j++) smallest = std::min(smallest, ring[i][0] * ring[j][0] + ring[i][1] * ring[j][1]);
  return smallest;
}

double ringAngle(double smallestCosine, const CutLocusOptions& options) {
  if (!options.everyAngle && !(smallestCosine <= std::cos(options.angleThreshold) + 1e-9))
    return std::numeric_limits<double>::quiet_NaN();
  return std::acos(std::max(-1.0, smallestCosine));
}

std::vector<char> passingVertices(const std::vector<double>& angleDeviation, const std::vector<double>& laplacian,
                                  const std::vector<char>& excluded, const CutLocusOptions& options) {
  std::vector<char> passing(laplacian.size(), 0);
  for (size_t v = 0; v < passing.size(); v++)
    passing[v] = !excluded[v] && laplacian[v] <= -options.laplacianThreshold && angleDeviation[v] >= options.angleThreshold;
  return passing;
}

// Spanning tree of the source's component rooted at the farthest vertex, grown Prim-style from the most
// ridge-like frontier vertex first (lowest Laplacian), each vertex hanging from its most ridge-like
// neighbour already in the tree. Vertices passing the thresholds go ahead of all others, so the tree
// first spans every passing vertex connected to the root through passing vertices: that subtree is the
// restriction in growing mode (a breadth-first search from the root through passing vertices), and
// within it the tree runs along the ridge crests. Only passing vertices and their paths to the root are
// ever read, so the tree stops growing once it holds every passing vertex (on the horse mesh, after
// 12-92% of the vertices, median 79%, over 24 sources); the others keep no parent.
std::vector<size_t> ridgeTree(const NeighbourGraph& graph, const std::vector<double>& laplacian,
                              const std::vector<char>& passing, const std::vector<double>& distance, size_t root) {
  const size_t n = graph.vertexCount();
  std::vector<size_t> parent(n, kNoParent);
  std::vector<char> inTree(n, 0), queued(n, 0);
  size_t passingLeft = std::count(passing.begin(), passing.end(), 1);
  using Entry = std::pair<std::pair<bool, double>, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> frontier;
  auto push = [&](size_t v) {
    queued[v] = 1;
    frontier.push({{!passing[v], std::isnan(laplacian[v]) ? INFINITY : laplacian[v]}, v});
  };
  push(root);
  while (!frontier.empty()) {
    size_t v = frontier.top().second;
    frontier.pop();
    inTree[v] = 1;
    passingLeft -= passing[v];
    std::pair<bool, double> best{true, INFINITY};
    for (size_t k = graph.rowStart[v]; k < graph.rowStart[v + 1]; k++) {
      size_t w = graph.neighbour[k];
      std::pair<bool, double> key{!passing[w], laplacian[w]};
      if (inTree[w] && w != v && (parent[v] == kNoParent || key < best)) {
        best = key;
        parent[v] = graph.edge[k];
      }
      if (!queued[w] && std::isfinite(distance[w])) push(w);
    }
    if (passingLeft == 0) break;
  }
  parent[root] = kNoParent;
  return parent;
}

// Growing: the root and every vertex whose whole tree path to the root passes. Pruning: every passing
// vertex and its whole tree path to the root.
std::vector<char> restrictTree(const NeighbourGraph& graph, const std::vector<size_t>& parent,
                               const std::vector<char>& passing, size_t root, CutLocusRestriction mode) {
  const size_t n = graph.vertexCount();
  std::vector<char> kept(n, 0), known(n, 0);
  if (mode == CutLocusRestriction::Pruning) {
    kept[root] = 1;
    for (size_t v = 0; v < n; v++)
      if (passing[v] && parent[v] != kNoParent)
        for (size_t w = v; !kept[w]; w = treeParent(graph, parent, w)) kept[w] = 1;
    return kept;
  }
  kept[root] = known[root] = 1;
  std::vector<size_t> path;
  for (size_t v = 0; v < n; v++) {
    path.clear();
    size_t w = v;
    for (; w != kNoParent && !known[w]; w = treeParent(graph, parent, w)) path.push_back(w);
    bool keep = w != kNoParent && kept[w];
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
      keep = keep && passing[*it];
      kept[*it] = keep;
      known[*it] = 1;
    }
  }
  return kept;
}

void assembleCutLocus(const NeighbourGraph& graph, const std::vector<size_t>& parent, std::vector<char> kept,
                      const std::vector<std::array<size_t, 2>>& extraEdges, int pruneDepth, CutLocus& result) {
  const size_t n = graph.vertexCount();
  std::vector<std::vector<size_t>> adjacent(n);
  auto link = [&](size_t a, size_t b) {
    adjacent[a].push_back(b);
    adjacent[b].push_back(a);
  };
  for (size_t v = 0; v < n; v++)
    if (kept[v] && parent[v] != kNoParent) link(v, treeParent(graph, parent, v));
  for (const auto& e : extraEdges) link(e[0], e[1]);

  // Remove leaf branches (leaf .. first junction) shorter than pruneDepth edges, in one pass. The root,
  // as the farthest point, always stays; a graph that is a single path is kept whole.
  std::vector<size_t> degree(n);
  for (size_t v = 0; v < n; v++) degree[v] = adjacent[v].size();
  std::vector<size_t> branch;
  for (size_t leaf = 0; leaf < n; leaf++) {
    if (!kept[leaf] || degree[leaf] != 1 || leaf == result.root) continue;
    branch.assign(1, leaf);
    size_t previous = leaf, v = adjacent[leaf][0];
    while (degree[v] == 2 && v != result.root) {
      branch.push_back(v);
      size_t next = adjacent[v][0] == previous ? adjacent[v][1] : adjacent[v][0];
      previous = v;
      v = next;
    }
    bool endsAtJunction = degree[v] >= 3 || v == result.root;
    if (endsAtJunction && branch.size() < static_cast<size_t>(std::max(pruneDepth, 0)))
      for (size_t b : branch) kept[b] = 0;
  }

  std::vector<size_t> node(n, kNoParent);
  for (size_t v = 0; v < n; v++)
    if (kept[v]) {
      node[v] = result.vertices.size();
      result.vertices.push_back(v);
    }
  for (size_t v = 0; v < n; v++)
    for (size_t w : adjacent[v])
      if (v < w && kept[v] && kept[w]) result.edges.push_back({node[v], node[w]});
}

} // namespace cscd
