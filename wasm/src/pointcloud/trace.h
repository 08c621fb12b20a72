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
TracedLoop traceCloudLoop(const NeighbourGraph& graph, const std::vector<geometrycentral::Vector3>& positions,
                          const std::vector<double>& distance, size_t target, std::array<size_t, 2> starts,
                          size_t source);

} // namespace cscd
