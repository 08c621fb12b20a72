#include "pointcloud/target.h"

#include "cscd/descent.h"
#include "cscd/target.h"

namespace cscd {

std::vector<CloudTarget> rankCloudTargets(const CloudNeighbourhood& neighbourhood, const CloudCutLocusSolver& solver,
                                          const CloudCutLocus& cutLocus, const std::vector<double>& distance,
                                          size_t source, TargetMode mode) {
  const NeighbourGraph& graph = neighbourhood.graph();
  std::vector<CloudTarget> targets;
  const CutLocusNeighbours alongCutLocus = cutLocusNeighbours(cutLocus.graph);
  for (size_t target : rankTargets(cutLocus.graph, distance, neighbourhood.positions(), source, mode, kMinDetour)) {
    const std::vector<size_t> ring(graph.neighbour.begin() + long(graph.rowStart[target]),
                                   graph.neighbour.begin() + long(graph.rowStart[target + 1]));
    const std::vector<size_t> starts = incomingNeighbours(ring, distance, alongCutLocus, target);
    if (starts.size() == 2 && solver.angleBetween(cutLocus.gradient, target, starts[0], starts[1]) >= kMinOpposedAngle)
      targets.push_back({target, {starts[0], starts[1]}});
  }
  return targets;
}

} // namespace cscd
