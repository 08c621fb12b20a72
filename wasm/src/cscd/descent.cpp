#include "cscd/descent.h"

#include <algorithm>
#include <unordered_set>

namespace cscd {
namespace {

// The neighbour of `ring` (a cyclic run from `begin`, `count` long) with the smallest distance.
size_t lowestOnArc(const std::vector<size_t>& ring, size_t begin, size_t count, const std::vector<double>& distance) {
  size_t best = ring[begin % ring.size()];
  for (size_t k = 1; k < count; k++) {
    size_t v = ring[(begin + k) % ring.size()];
    if (distance[v] < distance[best]) best = v;
  }
  return best;
}

} // namespace

CutLocusNeighbours cutLocusNeighbours(const CutLocus& cutLocus) {
  CutLocusNeighbours along;
  for (const auto& e : cutLocus.edges) {
    const size_t a = cutLocus.vertices[e[0]], b = cutLocus.vertices[e[1]];
    along[a].push_back(b);
    along[b].push_back(a);
  }
  return along;
}

std::vector<size_t> incomingNeighbours(const std::vector<size_t>& ring, const std::vector<double>& distance,
                                       const CutLocusNeighbours& alongCutLocus, size_t target) {
  const size_t n = ring.size();
  if (n < 2) return {};

  const auto listed = alongCutLocus.find(target);
  auto onCutLocus = [&](size_t v) {
    return listed != alongCutLocus.end() && std::find(listed->second.begin(), listed->second.end(), v) != listed->second.end();
  };
  std::vector<size_t> cuts;
  for (size_t k = 0; k < n; k++)
    if (onCutLocus(ring[k])) cuts.push_back(k);
  if (cuts.size() < 2) {
    // Leave out the cut-locus neighbour (or, with none, the highest neighbour) and halve the rest.
    auto higher = [&](size_t a, size_t b) { return distance[a] < distance[b]; };
    size_t first = cuts.empty() ? size_t(std::max_element(ring.begin(), ring.end(), higher) - ring.begin()) : cuts[0];
    if (n < 3) return {};
    size_t half = (n - 1) / 2;
    return {lowestOnArc(ring, first + 1, half, distance), lowestOnArc(ring, first + half + 1, n - 1 - half, distance)};
  }

  std::vector<size_t> arcLowest; // one per non-empty arc between consecutive cuts
  for (size_t i = 0; i < cuts.size(); i++) {
    size_t from = cuts[i], to = cuts[(i + 1) % cuts.size()];
    size_t count = (to + n - from - 1) % n;
    if (count > 0) arcLowest.push_back(lowestOnArc(ring, from + 1, count, distance));
  }
  if (arcLowest.size() < 2) return {};
  std::partial_sort(arcLowest.begin(), arcLowest.begin() + 2, arcLowest.end(),
                    [&](size_t a, size_t b) { return distance[a] < distance[b]; });
  return {arcLowest[0], arcLowest[1]};
}

void joinDescents(TracedLoop& traced) {
  std::unordered_set<size_t> onFirst(traced.firstPath.begin() + 1, traced.firstPath.end());
  size_t meet = 1;
  while (!onFirst.count(traced.secondPath[meet])) meet++;
  const size_t meeting = traced.secondPath[meet];
  traced.secondPath.resize(meet + 1);
  traced.firstPath.resize(size_t(std::find(traced.firstPath.begin(), traced.firstPath.end(), meeting) -
                                 traced.firstPath.begin()) +
                          1);
  traced.loop = traced.firstPath;
  // A loop leaves out the target at the end (it closes there); a path ends at its second end.
  const size_t last = traced.closed ? 1 : 0;
  for (size_t k = traced.secondPath.size() - 1; k-- > last;) traced.loop.push_back(traced.secondPath[k]);
}

} // namespace cscd
