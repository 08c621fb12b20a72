#include "cscd/graph.h"

#include "cscd/union_find.h"

#include <algorithm>
#include <map>

using geometrycentral::Vector3;

namespace cscd {

size_t SkeletonGraph::components() const {
  UnionFind sets(nodes.size());
  for (const auto& e : edges) sets.unite(uint32_t(e[0]), uint32_t(e[1]));
  size_t count = 0;
  for (size_t i = 0; i < nodes.size(); i++)
    if (sets.find(uint32_t(i)) == i) count++;
  return count;
}

void cliquesToStars(SkeletonGraph& graph, const std::set<std::array<size_t, 3>>& junctions) {
  std::set<std::array<size_t, 2>> edgeSet;
  for (auto e : graph.edges) edgeSet.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});

  // The junction triangles present in the graph, grouped when they share an edge.
  std::vector<std::array<size_t, 3>> triangles;
  for (const auto& t : junctions)
    if (edgeSet.count({t[0], t[1]}) && edgeSet.count({t[1], t[2]}) && edgeSet.count({t[0], t[2]})) triangles.push_back(t);
  if (triangles.empty()) return;
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
