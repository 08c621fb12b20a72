#include "pointcloud/trace.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <unordered_map>

namespace cscd {
size_t PathsToSource::next(size_t point) {
  if (nextPoint.empty()) {
    const size_t n = graph.vertexCount();
    std::vector<double> length(n, INFINITY);
    nextPoint.assign(n, kNoParent);
    using Entry = std::pair<double, size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> frontier;
    frontier.push({length[source_] = 0, source_});
    while (!frontier.empty()) {
      const auto [d, p] = frontier.top();
      frontier.pop();
      if (d > length[p]) continue;
      for (size_t k = graph.rowStart[p]; k < graph.rowStart[p + 1]; k++) {
        const size_t q = graph.neighbour[k];
        const double through = d + norm(positions[p] - positions[q]);
        if (through < length[q]) {
          length[q] = through;
          nextPoint[q] = p;
          frontier.push({through, q});
        }
      }
    }
  }
  return nextPoint[point];
}

TracedLoop traceCloudLoop(const NeighbourGraph& graph, const std::vector<double>& distance, size_t target,
                          std::array<size_t, 2> starts, PathsToSource& toSource) {
  const size_t source = toSource.source();
  auto forEachNeighbour = [&](size_t p, auto&& visit) {
    for (size_t k = graph.rowStart[p]; k < graph.rowStart[p + 1]; k++) visit(graph.neighbour[k]);
  };
  // The heat distance comes from the tufted triangulation, over which the graph (without its bridges) is
  // sparser: on a noisy cloud a descent along the graph often stops at a local minimum (17 of 40 sources
  // of deer_noise1.0 found no loop so). From there the path follows the graph's shortest path towards the
  // source until the distance is below where it stopped, and descends again; a point it meets again cuts
  // the path back to it, so the path never crosses itself.
  auto descendToSource = [&](std::vector<size_t>& path) {
    while (!descend(forEachNeighbour, distance, source, path)) {
      const double stuck = distance[path.back()];
      std::unordered_map<size_t, size_t> at;
      for (size_t i = 0; i < path.size(); i++) at[path[i]] = i;
      do {
        const size_t next = toSource.next(path.back());
        if (next == kNoParent) return false;
        const auto seen = at.find(next);
        if (seen != at.end()) {
          for (size_t i = seen->second + 1; i < path.size(); i++) at.erase(path[i]);
          path.resize(seen->second + 1);
        } else {
          at[next] = path.size();
          path.push_back(next);
        }
      } while (path.back() != source && !(distance[path.back()] < stuck));
    }
    return true;
  };
  TracedLoop traced;
  traced.firstPath = {target, starts[0]};
  traced.secondPath = {target, starts[1]};
  if (!descendToSource(traced.firstPath) || !descendToSource(traced.secondPath)) {
    traced.failure = "the source is not reached along the neighbourhood graph";
    return traced;
  }
  joinDescents(traced);
  if (traced.loop.size() < 3) traced.failure = "the traced loop is degenerate";
  return traced;
}

} // namespace cscd
