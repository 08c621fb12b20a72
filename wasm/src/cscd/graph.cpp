#include "cscd/graph.h"

#include "cscd/measures.h"
#include "cscd/union_find.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

using geometrycentral::Vector3;

namespace cscd {

namespace {

// A junction triangle's three edges (its nodes are sorted, so each edge is too).
std::array<std::array<size_t, 2>, 3> sides(const std::array<size_t, 3>& t) { return {{{t[0], t[1]}, {t[1], t[2]}, {t[0], t[2]}}}; }

// Whether separator m lies between separators a and b as consecutive slices of one tube: its plane
// between their loop centroids, and both within its radius of its axis. Two branches that leave a tube
// side by side (fingers) lie beside each other's axes, and a branch leaving between two slices lies on
// the same side of both; neither is taken for slices.
bool between(const SeparatorFrame& m, const SeparatorFrame& a, const SeparatorFrame& b) {
  auto along = [&](const SeparatorFrame& f) { return dot(f.centre - m.centre, m.normal); };
  auto off = [&](const SeparatorFrame& f) { return norm(f.centre - m.centre - along(f) * m.normal); };
  return along(a) * along(b) < 0 && off(a) <= m.radius && off(b) <= m.radius;
}

// A group of junction triangles is one branching where its junctions lie within a few separator radii
// of their mean, or around a body whose middle lies deep inside (a ball with arms).
// On a noisy cloud the packed loops go round the noise, their regions tile the surface, and the
// triangles where three tiles meet chain over the whole shape: one group, whose star's spokes ran from
// one hub across the shape to every tile. Such a group's junctions spread over many separator radii,
// and their mean lies nowhere deep: near the surface or outside. Measured (seed 1, the 91 groups of four
// regions or more of 37 clouds and 29 meshes; docs/skeleton.md, "Tilings"; spread in radii / in
// depths): branchings 0.1-2.9 radii, but star8's eight arms around a ball 4.1-4.2 radii / 1.6 depths;
// tilings 8.8 / 16 (armadillo_noise1.0, 70 regions), 15 / 92 (deer_noise1.0, 78), 4.9 / 76 (the noisy
// hanger's strips, 74), and 4.3 / 28 around a thin-walled cup's hollow (5 regions). A tiling that also
// holds one large loop (round the body of a blob whose noisy surface the tiles cover) spreads over few
// of its largest radius but many of its median one: branchings 0.1-10 median radii (the noisy wolf's
// 9.3 at 10.6 depths), tilings with such a loop 22-25 (cheburashka at 0.75% noise, 35 and 56 regions);
// docs/skeleton.md, "Tilings round one large loop".
// Tiles that cover a whole noisy blob have their mean deep inside, as a ball's with arms; they are told
// apart by their number: 15-51 members against at most 7 in the one branching over 15 median radii (the
// noisy wolf's chest); docs/skeleton.md, "Tilings of a whole blob".
constexpr double kMaxSpreadInRadii = 4, kMaxSpreadInMedianRadii = 15, kMaxSpreadInDepths = 10;
constexpr size_t kMinBlobTiles = 12;

// surface: the shape's elements; the depth of a point is its distance to the nearest. noisy: the
// separators may go round the shape's noise.
bool tiling(const std::vector<Vector3>& places, const std::set<size_t>& members, const std::vector<SeparatorFrame>& separators,
            const std::vector<Vector3>& surface, bool noisy) {
  std::vector<double> radii;
  for (size_t v : members)
    if (v < separators.size()) radii.push_back(separators[v].radius);
  if (radii.empty()) return false;
  std::sort(radii.begin(), radii.end());
  const double largest = radii.back(), median = radii[radii.size() / 2];
  Vector3 mean{0, 0, 0};
  for (const Vector3& p : places) mean += p;
  mean /= double(places.size());
  double spread = 0;
  for (const Vector3& p : places) spread = std::max(spread, norm(p - mean));
  const bool overMedians = median > 0 && spread > kMaxSpreadInMedianRadii * median;
  if (!(largest > 0 && (spread > kMaxSpreadInRadii * largest || overMedians))) return false;
  if (noisy && overMedians && radii.size() >= kMinBlobTiles) return true;
  double depth = INFINITY;
  for (const Vector3& p : surface) depth = std::min(depth, norm(p - mean));
  return spread > kMaxSpreadInDepths * depth;
}

// Edge sets as rows of bits over GF(2), reduced against a basis: whether a cycle is a sum of others.
class CycleSpace {
public:
  using Row = std::vector<uint64_t>;
  explicit CycleSpace(size_t edges) : words((edges + 63) / 64) {}
  Row row() const { return Row(words, 0); }
  static void set(Row& r, size_t bit) { r[bit / 64] ^= uint64_t(1) << (bit % 64); }
  // Adds r to the span; false when it was in it already.
  bool add(Row r) {
    for (size_t w = words; w-- > 0;)
      while (r[w]) {
        const size_t top = 64 * w + 63 - size_t(__builtin_clzll(r[w]));
        auto it = basis.find(top);
        if (it == basis.end()) {
          basis.emplace(top, std::move(r));
          return true;
        }
        for (size_t i = 0; i <= w; i++) r[i] ^= it->second[i];
      }
    return false;
  }

private:
  size_t words;
  std::map<size_t, Row> basis; // by highest bit
};

// How a group's members are joined instead of by its triangles: Kruskal's tree of the shortest of its
// edges (between the nodes' positions), which keeps them connected with no cycle among them and each
// joined to its nearest neighbours on the surface, and the edges that close the group's holes. Each edge
// left out of the tree closes a cycle of it; the triangles fill most (the cycle is a sum of their
// boundaries); the others go round a hole of the group, either round a part of the shape (tiles round a
// leg: the cycle's middle is inside) or round a hole of the shape (regions round a handle: outside). A
// star or a tree alone loses the second kind, and with it a cycle of the shape (a noisy strip bent into a
// ring, docs/skeleton.md "Holes of a group").
struct GroupJoin {
  std::vector<std::array<size_t, 2>> tree, holes;
};
GroupJoin joinGroup(const SkeletonGraph& graph, const std::set<std::array<size_t, 2>>& edges,
                    const std::vector<std::array<size_t, 3>>& triangles, const std::function<bool(const Vector3&)>& inside) {
  std::map<std::array<size_t, 2>, size_t> index;
  for (const auto& e : edges) index.emplace(e, index.size());
  CycleSpace filled(edges.size());
  for (const auto& t : triangles) {
    CycleSpace::Row boundary = filled.row();
    for (const auto& e : sides(t)) CycleSpace::set(boundary, index.at(e));
    filled.add(std::move(boundary));
  }

  std::vector<std::pair<double, std::array<size_t, 2>>> byLength;
  for (const auto& e : edges) byLength.push_back({norm(graph.nodes[e[0]] - graph.nodes[e[1]]), e});
  std::sort(byLength.begin(), byLength.end());
  GroupJoin join;
  UnionFind tree(graph.nodes.size());
  std::map<size_t, std::vector<size_t>> treeNeighbours;
  std::vector<std::pair<double, std::array<size_t, 2>>> closing;
  for (const auto& [length, e] : byLength) {
    if (tree.find(uint32_t(e[0])) == tree.find(uint32_t(e[1]))) {
      closing.push_back({length, e});
      continue;
    }
    tree.unite(uint32_t(e[0]), uint32_t(e[1]));
    join.tree.push_back(e);
    treeNeighbours[e[0]].push_back(e[1]);
    treeNeighbours[e[1]].push_back(e[0]);
  }

  // Each closing edge's cycle (the tree's path between its ends, and the edge), shortest first: a
  // short cycle round a gap in the tiles, whose middle is inside, is then known before a long one round
  // a handle, which may go round that gap as well and would otherwise count as a second handle.
  struct Cycle {
    double length = 0;
    std::array<size_t, 2> edge;
    CycleSpace::Row edges;
    std::vector<Vector3> loop;
  };
  std::vector<Cycle> cycles;
  for (const auto& [length, e] : closing) {
    std::map<size_t, size_t> from{{e[0], e[0]}};
    std::vector<size_t> queue{e[0]};
    for (size_t i = 0; i < queue.size() && !from.count(e[1]); i++)
      for (size_t w : treeNeighbours[queue[i]])
        if (from.emplace(w, queue[i]).second) queue.push_back(w);
    Cycle cycle{length, e, filled.row(), {graph.nodes[e[1]]}};
    CycleSpace::set(cycle.edges, index.at(e));
    for (size_t v = e[1]; v != e[0]; v = from[v]) {
      CycleSpace::set(cycle.edges, index.at({std::min(v, from[v]), std::max(v, from[v])}));
      cycle.length += norm(graph.nodes[v] - graph.nodes[from[v]]);
      cycle.loop.push_back(graph.nodes[from[v]]);
    }
    cycles.push_back(std::move(cycle));
  }
  std::stable_sort(cycles.begin(), cycles.end(), [](const Cycle& a, const Cycle& b) { return a.length < b.length; });
  // Cycles round one hole of the shape (a wide band tiled in two rings round it) have their middles on
  // its axis, nearer each other than their radii; round two holes, at least a hole's width apart.
  std::vector<std::pair<Vector3, double>> keptHoles; // their cycles' middles and radii
  for (Cycle& cycle : cycles) {
    if (!filled.add(std::move(cycle.edges))) continue;
    const Vector3 middle = loopCentroid(cycle.loop, true);
    const double radius = cycle.length / (2 * M_PI);
    if (inside(middle) || std::any_of(keptHoles.begin(), keptHoles.end(), [&](const auto& hole) {
          return norm(hole.first - middle) < std::min(hole.second, radius);
        }))
      continue;
    keptHoles.push_back({middle, radius});
    join.holes.push_back(cycle.edge);
  }
  return join;
}

} // namespace

size_t SkeletonGraph::components() const {
  UnionFind sets(nodes.size());
  for (const auto& e : edges) sets.unite(uint32_t(e[0]), uint32_t(e[1]));
  size_t count = 0;
  for (size_t i = 0; i < nodes.size(); i++)
    if (sets.find(uint32_t(i)) == i) count++;
  return count;
}

void cliquesToStars(SkeletonGraph& graph, const std::map<std::array<size_t, 3>, Vector3>& junctions,
                    const std::vector<SeparatorFrame>& separators, const std::vector<Vector3>& surface,
                    const std::function<bool(const Vector3&)>& inside, bool noisy) {
  std::set<std::array<size_t, 2>> edgeSet;
  for (auto e : graph.edges) edgeSet.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  auto present = [&](const std::array<size_t, 3>& t) {
    const auto edges = sides(t);
    return std::all_of(edges.begin(), edges.end(), [&](const auto& e) { return edgeSet.count(e) > 0; });
  };

  // Slices first: three consecutive slices of one tube meet where their separators are not parallel
  // (tilted loops, the inside of a bend), and a star there turns the middle one into a spur (the leaves
  // along a torus, docs/skeleton.md "Slices of one tube"): the edge between the outer two is dropped, and
  // no star made. Not where another junction triangle has that edge: the two would then leave a cycle
  // that their star removes.
  std::map<std::array<size_t, 2>, std::vector<std::array<size_t, 3>>> junctionsOfEdge;
  for (const auto& [t, place] : junctions)
    for (const auto& e : sides(t)) junctionsOfEdge[e].push_back(t);
  auto hasFrame = [&](size_t v) { return v < separators.size() && norm2(separators[v].normal) > 0; };
  // Passes until none drops an edge: a triangle that a drop takes away no longer holds back the slices
  // that share their outer edge with it.
  for (bool dropped = true; dropped;) {
    dropped = false;
    for (const auto& junction : junctions) {
      const std::array<size_t, 3>& t = junction.first;
      if (!present(t) || !hasFrame(t[0]) || !hasFrame(t[1]) || !hasFrame(t[2])) continue;
      for (int k = 0; k < 3; k++) {
        const size_t a = t[(k + 1) % 3], b = t[(k + 2) % 3];
        if (!between(separators[t[k]], separators[a], separators[b])) continue;
        const std::array<size_t, 2> outer{std::min(a, b), std::max(a, b)};
        const auto& sharing = junctionsOfEdge[outer];
        if (std::none_of(sharing.begin(), sharing.end(), [&](const auto& other) { return other != t && present(other); })) {
          edgeSet.erase(outer);
          dropped = true;
        }
        break;
      }
    }
  }

  // The junction triangles present in the graph, grouped when they share an edge.
  std::vector<std::array<size_t, 3>> triangles;
  for (const auto& [t, place] : junctions)
    if (present(t)) triangles.push_back(t);
  UnionFind groups(triangles.size());
  std::map<std::array<size_t, 2>, size_t> firstTriangleOfEdge;
  for (size_t i = 0; i < triangles.size(); i++) {
    const auto& t = triangles[i];
    for (const auto& e : sides(t)) {
      auto [it, inserted] = firstTriangleOfEdge.emplace(e, i);
      if (!inserted) groups.unite(uint32_t(i), uint32_t(it->second));
    }
  }

  std::map<size_t, std::set<size_t>> members;
  std::map<size_t, std::set<std::array<size_t, 2>>> groupEdges;
  std::map<size_t, std::vector<std::array<size_t, 3>>> groupTriangles;
  std::map<size_t, std::vector<Vector3>> places;
  for (size_t i = 0; i < triangles.size(); i++) {
    const auto& t = triangles[i];
    size_t g = groups.find(uint32_t(i));
    members[g].insert(t.begin(), t.end());
    for (const auto& e : sides(t)) groupEdges[g].insert(e);
    groupTriangles[g].push_back(t);
    places[g].push_back(junctions.at(t));
  }
  for (const auto& [g, nodes] : members) {
    for (const auto& e : groupEdges[g]) edgeSet.erase(e);
    // A tiling, or regions round a hole of the shape (no one branching either): its tree and its holes.
    const GroupJoin join = joinGroup(graph, groupEdges[g], groupTriangles[g], inside);
    if (!join.holes.empty() || tiling(places[g], nodes, separators, surface, noisy)) {
      edgeSet.insert(join.tree.begin(), join.tree.end());
      edgeSet.insert(join.holes.begin(), join.holes.end());
      continue;
    }
    Vector3 center{0, 0, 0};
    double weight = 0;
    for (size_t v : nodes) {
      center += graph.weights[v] * graph.nodes[v];
      weight += graph.weights[v];
    }
    const size_t hub = graph.nodes.size();
    graph.nodes.push_back(weight > 0 ? center / weight : graph.nodes[*nodes.begin()]);
    graph.weights.push_back(0); // a branch node owns no surface of its own
    for (size_t v : nodes) edgeSet.insert({v, hub});
  }
  graph.edges.assign(edgeSet.begin(), edgeSet.end());
}

} // namespace cscd
