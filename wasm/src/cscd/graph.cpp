#include "cscd/graph.h"

#include "cscd/union_find.h"

#include <algorithm>
#include <map>

using geometrycentral::Vector3;

namespace cscd {

namespace {

// Whether separator m lies between separators a and b as consecutive slices of one tube: its plane
// between their loop centroids, and both within its radius of its axis. Two branches that leave a tube
// side by side (fingers) lie beside each other's axes, and a branch leaving between two slices lies on
// the same side of both; neither is taken for slices.
bool between(const SeparatorFrame& m, const SeparatorFrame& a, const SeparatorFrame& b) {
  auto along = [&](const SeparatorFrame& f) { return dot(f.centre - m.centre, m.normal); };
  auto off = [&](const SeparatorFrame& f) { return norm(f.centre - m.centre - along(f) * m.normal); };
  return along(a) * along(b) < 0 && off(a) <= m.radius && off(b) <= m.radius;
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

void cliquesToStars(SkeletonGraph& graph, const std::set<std::array<size_t, 3>>& junctions,
                    const std::vector<SeparatorFrame>& separators) {
  std::set<std::array<size_t, 2>> edgeSet;
  for (auto e : graph.edges) edgeSet.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  auto present = [&](const std::array<size_t, 3>& t) {
    return edgeSet.count({t[0], t[1]}) && edgeSet.count({t[1], t[2]}) && edgeSet.count({t[0], t[2]});
  };

  // Slices first: three consecutive slices of one tube meet where their separators are not parallel
  // (tilted loops, the inside of a bend), and a star there turns the middle one into a spur (the leaves
  // along a torus, docs/skeleton.md "Slices of one tube"): the edge between the outer two is dropped, and
  // no star made. Not where another junction triangle has that edge: the two would then leave a cycle
  // that their star removes.
  std::map<std::array<size_t, 2>, std::vector<std::array<size_t, 3>>> junctionsOfEdge;
  for (const auto& t : junctions)
    for (std::array<size_t, 2> e : {std::array<size_t, 2>{t[0], t[1]}, {t[1], t[2]}, {t[0], t[2]}}) junctionsOfEdge[e].push_back(t);
  auto hasFrame = [&](size_t v) { return v < separators.size() && norm2(separators[v].normal) > 0; };
  // Passes until none drops an edge: a triangle that a drop takes away no longer holds back the slices
  // that share their outer edge with it.
  for (bool dropped = true; dropped;) {
    dropped = false;
    for (const auto& t : junctions) {
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
  for (const auto& t : junctions)
    if (present(t)) triangles.push_back(t);
  UnionFind groups(triangles.size());
  std::map<std::array<size_t, 2>, size_t> firstTriangleOfEdge;
  for (size_t i = 0; i < triangles.size(); i++) {
    const auto& t = triangles[i];
    for (std::array<size_t, 2> e : {std::array<size_t, 2>{t[0], t[1]}, {t[1], t[2]}, {t[0], t[2]}}) {
      auto [it, inserted] = firstTriangleOfEdge.emplace(e, i);
      if (!inserted) groups.unite(uint32_t(i), uint32_t(it->second));
    }
  }

  std::map<size_t, std::set<size_t>> members;
  std::map<size_t, std::set<std::array<size_t, 2>>> groupEdges;
  for (size_t i = 0; i < triangles.size(); i++) {
    const auto& t = triangles[i];
    size_t g = groups.find(uint32_t(i));
    members[g].insert(t.begin(), t.end());
    groupEdges[g].insert({{t[0], t[1]}, {t[1], t[2]}, {t[0], t[2]}});
  }
  for (const auto& [g, nodes] : members) {
    for (const auto& e : groupEdges[g]) edgeSet.erase(e);
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
