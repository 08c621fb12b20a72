#pragma once

#include "cscd/descent.h"
#include "cscd/ridge_tree.h"
#include "geometrycentral/utilities/vector3.h"

#include <array>
#include <vector>

namespace cscd {

// The approximate loop on a cloud (cscd/descent.h): from the target, the two steepest descents of the
// distance along the neighbourhood graph, from its two opposed incoming neighbours (pointcloud/target.h)
// to the source, cut where they meet and joined into a closed loop of point indices; a descent that
// stops at a local minimum goes on along the graph's shortest path towards the source.
// Each point's next point on the graph's shortest path to one source (Dijkstra, Euclidean lengths; kNoParent
// where the source is not reached), found when a descent first needs it and kept for the source's further
// loops (a noisy cloud's source traces up to kMaxTargets).
class PathsToSource {
public:
  PathsToSource(const NeighbourGraph& graph, const std::vector<geometrycentral::Vector3>& positions, size_t source)
      : graph(graph), positions(positions), source_(source) {}
  size_t source() const { return source_; }
  size_t next(size_t point);

private:
  const NeighbourGraph& graph;
  const std::vector<geometrycentral::Vector3>& positions;
  size_t source_;
  std::vector<size_t> nextPoint; // empty until first asked
};

TracedLoop traceCloudLoop(const NeighbourGraph& graph, const std::vector<double>& distance, size_t target,
                          std::array<size_t, 2> starts, PathsToSource& toSource);

} // namespace cscd
