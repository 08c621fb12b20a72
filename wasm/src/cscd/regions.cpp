#include "cscd/regions.h"

#include "cscd/union_find.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <numeric>
#include <set>

using namespace geometrycentral;

namespace cscd {

Regions growRegions(const ElementGraph& graph, std::vector<double> distance, std::vector<uint32_t> seeds,
                    size_t separators) {
  const size_t n = graph.positions.size();
  Regions regions;
  regions.distance = std::move(distance);
  regions.label = std::move(seeds);
  const std::vector<double>& d = regions.distance;
  std::vector<uint32_t>& label = regions.label;

  // Watershed in order of increasing distance; an element with no labelled neighbour yet waits.
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return d[a] < d[b]; });
  auto labelFromNeighbours = [&](size_t v) {
    uint32_t best = kNoRegion;
    double bestDistance = INFINITY;
    for (uint32_t i : graph.neighbours[v])
      if (label[i] != kNoRegion && (best == kNoRegion || d[i] < bestDistance)) {
        best = label[i];
        bestDistance = d[i];
      }
    return best;
  };
  std::vector<size_t> waiting;
  auto floodWaiting = [&]() {
    for (bool changed = true; changed;) {
      changed = false;
      for (size_t v : waiting)
        if (label[v] == kNoRegion && (label[v] = labelFromNeighbours(v)) != kNoRegion) changed = true;
    }
  };
  for (size_t v : order) {
    if (label[v] != kNoRegion || !std::isfinite(d[v])) continue;
    label[v] = labelFromNeighbours(v);
    if (label[v] == kNoRegion) waiting.push_back(v);
  }
  floodWaiting();

  // Seeds of close separators can interleave and cut off islands of a label: each label keeps its
  // largest piece; the elements of other pieces join the regions around them.
  UnionFind pieces(n);
  for (const auto& [a, b] : graph.edges)
    if (label[a] == label[b]) pieces.unite(a, b);
  std::vector<size_t> pieceSize(n, 0);
  for (size_t v = 0; v < n; v++) pieceSize[pieces.find(uint32_t(v))]++;
  std::vector<size_t> largestPiece(separators, SIZE_MAX);
  for (size_t v = 0; v < n; v++) {
    if (label[v] == kNoRegion) continue;
    size_t piece = pieces.find(uint32_t(v)), best = largestPiece[label[v]];
    if (best == SIZE_MAX || pieceSize[piece] > pieceSize[best] || (pieceSize[piece] == pieceSize[best] && piece < best))
      largestPiece[label[v]] = piece;
  }
  waiting.clear();
  for (size_t v : order)
    if (label[v] != kNoRegion && pieces.find(uint32_t(v)) != largestPiece[label[v]]) {
      label[v] = kNoRegion;
      waiting.push_back(v);
    }
  floodWaiting();

  // Components that no separator reached: one region each, but for adopted elements (after the others,
  // as their adoptive elements may be in such a component).
  regions.count = separators;
  std::vector<char> isAdopted(n, 0);
  if (graph.adoptive)
    for (size_t v = 0; v < n; v++) isAdopted[v] = label[v] == kNoRegion && (*graph.adoptive)[v] != kNoRegion;
  std::vector<uint32_t> componentRegion;
  for (size_t v = 0; v < n; v++) {
    if (label[v] != kNoRegion || isAdopted[v]) continue;
    size_t c = size_t(graph.component[v]);
    if (componentRegion.size() <= c) componentRegion.resize(c + 1, kNoRegion);
    if (componentRegion[c] == kNoRegion) componentRegion[c] = uint32_t(regions.count++);
    label[v] = componentRegion[c];
  }
  for (size_t v = 0; v < n; v++)
    if (isAdopted[v]) label[v] = label[(*graph.adoptive)[v]];
  auto anyAdopted = [&](const std::array<uint32_t, 3>& t) { return isAdopted[t[0]] || isAdopted[t[1]] || isAdopted[t[2]]; };

  regions.centroid.assign(regions.count, Vector3{0, 0, 0});
  regions.area.assign(regions.count, 0);
  for (size_t v = 0; v < n; v++) {
    regions.centroid[label[v]] += graph.areas[v] * graph.positions[v];
    regions.area[label[v]] += graph.areas[v];
  }
  for (size_t r = 0; r < regions.count; r++)
    if (regions.area[r] > 0) regions.centroid[r] /= regions.area[r];

  // The elements of each side of each contact, where a contact needs more than one.
  std::map<std::array<size_t, 2>, std::array<std::set<uint32_t>, 2>> sides;
  for (const auto& t : graph.triangles) {
    if (anyAdopted(t)) continue;
    std::array<size_t, 3> l{label[t[0]], label[t[1]], label[t[2]]};
    if (graph.minContact > 1)
      for (uint32_t a : t)
        for (uint32_t b : t)
          if (label[a] < label[b]) {
            auto& side = sides[{label[a], label[b]}];
            side[0].insert(a);
            side[1].insert(b);
          }
    std::sort(l.begin(), l.end());
    if (l[0] != l[1]) regions.adjacent.insert({l[0], l[1]});
    if (l[1] != l[2]) regions.adjacent.insert({l[1], l[2]});
    if (l[0] != l[2]) regions.adjacent.insert({l[0], l[2]});
  }
  std::map<std::array<size_t, 3>, size_t> junctionTriangles;
  for (const auto& t : graph.junctionTriangles ? *graph.junctionTriangles : graph.triangles) {
    if (anyAdopted(t)) continue;
    std::array<size_t, 3> l{label[t[0]], label[t[1]], label[t[2]]};
    std::sort(l.begin(), l.end());
    if (l[0] == l[1] || l[1] == l[2]) continue;
    regions.junctions.emplace(l, geometrycentral::Vector3{0, 0, 0}).first->second +=
        (graph.positions[t[0]] + graph.positions[t[1]] + graph.positions[t[2]]) / 3.;
    junctionTriangles[l]++;
  }
  for (auto& [l, place] : regions.junctions) place /= double(junctionTriangles[l]);
  // A contact too small to be a border counts where the two regions meet a third: beside a junction a
  // region can touch another in a few elements only.
  if (graph.minContact > 1) {
    std::set<std::array<size_t, 2>> atJunction;
    for (const auto& [l, place] : regions.junctions) atJunction.insert({{l[0], l[1]}, {l[1], l[2]}, {l[0], l[2]}});
    for (auto it = regions.adjacent.begin(); it != regions.adjacent.end();) {
      const auto& side = sides.at(*it);
      const bool border = std::min(side[0].size(), side[1].size()) >= graph.minContact;
      it = border || atJunction.count(*it) ? std::next(it) : regions.adjacent.erase(it);
    }
  }
  return regions;
}

} // namespace cscd
