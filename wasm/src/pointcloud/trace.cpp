#include "pointcloud/trace.h"

namespace cscd {

TracedLoop traceCloudLoop(const NeighbourGraph& graph, const std::vector<double>& distance, size_t target,
                          std::array<size_t, 2> starts, size_t source) {
  auto forEachNeighbour = [&](size_t p, auto&& visit) {
    for (size_t k = graph.rowStart[p]; k < graph.rowStart[p + 1]; k++) visit(graph.neighbour[k]);
  };
  TracedLoop traced;
  traced.firstPath = {target, starts[0]};
  traced.secondPath = {target, starts[1]};
  if (!descend(forEachNeighbour, distance, source, traced.firstPath) ||
      !descend(forEachNeighbour, distance, source, traced.secondPath)) {
    traced.failure = "steepest descent stopped at a local minimum of the distance";
    return traced;
  }
  joinDescents(traced);
  if (traced.loop.size() < 3) traced.failure = "the traced loop is degenerate";
  return traced;
}

} // namespace cscd
